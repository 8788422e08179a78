// index.html: the whole campaign on one self-contained page (figures inlined as PNG data, no
// scripts, no links out), readable from a file without a server.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "experiment/campaign_figures.h"
#include "experiment/campaign_report.h"

namespace echoplan::experiment {

// The page's HTML. `figures` name PNG files in directory/figures, which are read and inlined.
std::string html_report(const std::filesystem::path& directory, const CampaignResults& results,
                        const std::vector<Figure>& figures);

// RFC 4648 base64 of `bytes`.
std::string base64(const std::string& bytes);

}  // namespace echoplan::experiment
