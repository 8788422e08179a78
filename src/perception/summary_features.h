// A fixed-length, level-normalised description of one clip's sound event: what `summary-lda`
// classifies.
//
// Everything is measured from the onset (ClipAnalysis::onset_frame) and relative to the loudest
// frame of the event, so a clip recorded after 0.35 s of silence, or a strike at another force,
// gives the same numbers up to the noise floor. Log-mel values are floored 12 nats (52 dB) below
// that peak, so the digital silence and the room floor weigh no more than a quiet tail does.
//
// Layout (kSummarySize = 123 values, natural-log units unless said):
//   [0, 104)    mean log-mel spectrum (26 psf bands) relative to the peak frame level, in 4
//   segments after the
//               onset: frames 0-3 (attack), 3-15, 15-50, 50-150 (to 1.5 s; slides last that long)
//   [104, 116)  standard deviation of MFCC c1..c12 over frames 0-150 (how steady the timbre is)
//   [116, 119)  ln(1 + frames) until the level falls 10, 20 and 30 dB below its peak (decay)
//   [119, 121)  mean ln flatness of the floored mel spectrum over frames 0-15 and 15-150
//               (tonal ring vs noise)
//   [121, 123)  ln(1 + mean spectral centroid in Hz) over frames 0-15 and 15-150 (a brightness
//               cue: psf's unwindowed 512-sample frames leak a tone into every bin, so a 500 Hz
//               tone reads about 3 kHz)
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "perception/clip_analysis.h"

namespace echoplan::perception {

inline constexpr std::size_t kSummarySize = 123;
// The psf preset's mel bands, which the summary (and pcen_summary.h) describes.
inline constexpr std::size_t kSummaryBands = 26;
// The four spans of frames after the onset whose mean spectrum the summary keeps: [from, to).
inline constexpr std::array<std::pair<std::size_t, std::size_t>, 4> kSummarySegments{
    {{0, 3}, {3, 15}, {15, 50}, {50, 150}}};

// The summary of `clip` (features from the psf preset: 26 log-mel bands, 13 MFCCs).
std::array<double, kSummarySize> summary_features(const ClipAnalysis& clip);

// A short name per entry ("shape0_band3", "mfcc_std5", "decay20", ...), for reports and tests.
std::vector<std::string> summary_feature_names();

// PREFIX{segment}_band{band} for every segment of kSummarySegments and band of kSummaryBands, in
// that order: the names of a per-segment band spectrum (the summary's and pcen_summary.h's).
std::vector<std::string> segment_band_names(std::string_view prefix);

}  // namespace echoplan::perception
