#include "experiment/report_inputs.h"

#include <nlohmann/json.hpp>

#include "common/error.h"
#include "common/file_io.h"
#include "common/json_fields.h"

namespace echoplan::experiment {

namespace fs = std::filesystem;
namespace jf = json_fields;

namespace {

nlohmann::json to_json(const TemplateMatrix& t) {
  const std::vector<double> values(t.mean.values.begin(), t.mean.values.end());
  return {{"object", t.object},
          {"action", t.action},
          {"hop_seconds", t.hop_seconds},
          {"recordings", t.recordings},
          {"frames", t.mean.rows},
          {"bands", t.mean.cols},
          {"mean", values}};
}

TemplateMatrix template_from_json(const nlohmann::json& j, const std::string& path,
                                  const jf::JsonSource& source) {
  TemplateMatrix t;
  t.object = jf::string(jf::member(j, "object", path, source), jf::child(path, "object"), source);
  t.action = jf::string(jf::member(j, "action", path, source), jf::child(path, "action"), source);
  t.hop_seconds = jf::number(jf::member(j, "hop_seconds", path, source),
                             jf::child(path, "hop_seconds"), source);
  t.recordings = jf::integer(jf::member(j, "recordings", path, source), 1, 1 << 30,
                             jf::child(path, "recordings"), source);
  const int frames = jf::integer(jf::member(j, "frames", path, source), 0, 1 << 20,
                                 jf::child(path, "frames"), source);
  const int bands = jf::integer(jf::member(j, "bands", path, source), 0, 1 << 12,
                                jf::child(path, "bands"), source);
  const std::vector<double> mean =
      jf::numbers(jf::member(j, "mean", path, source), static_cast<long long>(frames) * bands,
                  jf::child(path, "mean"), source);
  t.mean.resize(frames, bands);
  for (std::size_t v = 0; v < mean.size(); ++v) t.mean.values[v] = static_cast<float>(mean[v]);
  return t;
}

}  // namespace

void write_report_inputs(const fs::path& directory, const ReportInputs& inputs) {
  nlohmann::json j = {{"heard", nlohmann::json::array()}, {"templates", nlohmann::json::array()}};
  for (const HeardCounts& h : inputs.heard) j["heard"].push_back(to_json(h));
  for (const TemplateMatrix& t : inputs.templates) j["templates"].push_back(to_json(t));
  write_file_atomically(directory / kReportInputs, j.dump() + "\n");
}

ReportInputs read_report_inputs(const fs::path& directory) {
  const fs::path file = directory / kReportInputs;
  ReportInputs inputs;
  if (!fs::exists(file)) return inputs;
  const std::string source = file.string();
  const nlohmann::json j =
      nlohmann::json::parse(read_text_file(source, "report inputs"), nullptr, false);
  if (j.is_discarded()) throw InputError(source, 0, "is not JSON");
  const nlohmann::json& heard = jf::array(jf::member(j, "heard", "", source), "heard", source);
  for (std::size_t i = 0; i < heard.size(); ++i)
    inputs.heard.push_back(heard_counts_from_json(heard[i], jf::element("heard", i), source));
  const nlohmann::json& templates =
      jf::array(jf::member(j, "templates", "", source), "templates", source);
  for (std::size_t i = 0; i < templates.size(); ++i)
    inputs.templates.push_back(
        template_from_json(templates[i], jf::element("templates", i), source));
  return inputs;
}

}  // namespace echoplan::experiment
