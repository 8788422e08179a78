// libFuzzer target: arbitrary bytes as an observation model file (JSON). Bad input must end in
// echoplan::InputError; a model that loads must classify a short clip without any other failure.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "perception/clip_analysis.h"
#include "perception/observation_model_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace echoplan::perception;
  try {
    const ObservationModel model = parse_observation_model(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    echoplan::audio::AudioClip clip;
    clip.sample_rate = 8000;
    for (int i = 0; i < 1600; ++i)
      clip.samples.push_back(static_cast<float>(0.3 * std::sin(0.37 * i) * std::exp(-i / 400.0)));
    ClipAnalyzer analyzer(model.analysis());
    ClipAnalysis analysis;
    analyzer.analyse(clip, "clip", analysis);
    for (const auto& action : model.actions()) (void)model.classify(analysis, action);
  } catch (const echoplan::InputError&) {
    // A malformed model: the documented outcome.
  }
  return 0;
}
