// make_feature_set: writes a synthetic feature set (perception/synthetic_feature_set.h) for the
// benchmarks, or for trying echoplan without a robot:
//
//   build/bench/make_feature_set -o /tmp/fs --objects 100 --group-size 5 --sessions 5
//       --actions press,grasp,lift --action-scales 0.3,0.6,1 --modality audio:8:1.5
//       --modality haptic:4:0.5 --group-separation 1 --session-sd 0.3 --repeats 1 --seed 1
//
// then `echoplan train --data /tmp/fs --groups /tmp/fs/groups.csv` or a campaign's dataset world.
// Bad input exits 2 with one line on stderr.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>
#include <vector>

#include "common/error.h"
#include "perception/synthetic_feature_set.h"

namespace {

using echoplan::InputError;
using echoplan::perception::SyntheticModality;

// "NAME:FEATURES:SEPARATION", e.g. "audio:8:1.5".
SyntheticModality parse_modality(const std::string& text) {
  const auto first = text.find(':');
  const auto second = first == std::string::npos ? first : text.find(':', first + 1);
  if (second == std::string::npos)
    throw InputError(fmt::format("--modality {}: expected NAME:FEATURES:SEPARATION", text));
  SyntheticModality m;
  m.name = text.substr(0, first);
  try {
    m.features = std::stoi(text.substr(first + 1, second - first - 1));
    m.separation = std::stod(text.substr(second + 1));
  } catch (const std::exception&) {
    throw InputError(fmt::format("--modality {}: FEATURES and SEPARATION must be numbers", text));
  }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  echoplan::perception::SyntheticSpec spec;
  spec.modalities.clear();
  std::string out;
  std::vector<std::string> modalities;
  CLI::App app{"Writes a synthetic feature set: DIR/<action>/<modality>.csv (and DIR/groups.csv)"};
  app.add_option("-o,--out", out, "the folder to write")->required();
  app.add_option("--objects", spec.objects, "objects")->capture_default_str();
  app.add_option("--group-size", spec.group_size, "objects per group, 0: no groups")
      ->capture_default_str();
  app.add_option("--sessions", spec.sessions, "sessions per object")->capture_default_str();
  app.add_option("--repeats", spec.repeats, "performances of each action per session")
      ->capture_default_str();
  app.add_option("--actions", spec.actions, "the behaviours")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--action-scales", spec.action_scales,
                 "per action, multiplies every modality's separation (default 1 each)")
      ->delimiter(',');
  app.add_option("--modality", modalities,
                 "NAME:FEATURES:SEPARATION, repeatable (default audio:5:3)");
  app.add_option("--group-separation", spec.group_separation, "spread of group means, in noise SDs")
      ->capture_default_str();
  app.add_option("--session-sd", spec.session_sd,
                 "SD of each session's offset, shared by its repeats")
      ->capture_default_str();
  app.add_option("--lookalike-share", spec.lookalike_share,
                 "chance that an object looks like another group in every behaviour")
      ->capture_default_str();
  app.add_option("--lookalike-pull", spec.lookalike_pull,
                 "how far such an object sits towards the group it looks like, 0 to 1")
      ->capture_default_str();
  app.add_option("--seed", spec.seed, "every number comes from it")->capture_default_str();
  try {
    app.parse(argc, argv);
    for (const std::string& m : modalities) spec.modalities.push_back(parse_modality(m));
    if (spec.modalities.empty()) spec.modalities.push_back({"audio", 5, 3.0});
    echoplan::perception::write_synthetic_feature_set(out, spec);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const InputError& e) {
    std::cerr << "make_feature_set: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
