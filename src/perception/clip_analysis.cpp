#include "perception/clip_analysis.h"

#include <fmt/format.h>

#include <algorithm>

#include "audio/io.h"
#include "audio/levels.h"
#include "common/error.h"

namespace echoplan::perception {
namespace {

const AnalysisSettings& checked(const AnalysisSettings& s) {
  if (s.sample_rate < 1000 || s.sample_rate > 384000)
    throw InputError(
        fmt::format("analysis sample_rate = {} Hz is outside 1000..384000", s.sample_rate));
  if (!(s.silence_rms >= 0.0 && s.silence_rms < 1.0))
    throw InputError(
        fmt::format("analysis silence_rms = {} is outside 0..1 (full-scale RMS)", s.silence_rms));
  return s;
}

}  // namespace

std::size_t first_sound_frame(const audio::FeatureMatrix& rms, double silence_rms) {
  for (std::size_t t = 0; t < rms.rows; ++t)
    if (static_cast<double>(rms.at(t, 0)) > silence_rms) return t;
  return rms.rows == 0 ? 0 : rms.rows - 1;
}

std::size_t onset_frame(const audio::FeatureMatrix& flux, std::size_t from,
                        const audio::OnsetConfig& onset) {
  if (flux.rows == 0) throw InputError("cannot find an onset: the clip has no frames");
  from = std::min(from, flux.rows - 1);
  // Peak picking only after the leading silence: the recorder's opening zeros carry no event.
  audio::FeatureMatrix tail;
  tail.resize(flux.rows - from, 1);
  std::copy(flux.values.begin() + static_cast<std::ptrdiff_t>(from), flux.values.end(),
            tail.values.begin());
  return from + audio::alignment_frame(tail, audio::OnsetChoice::strongest, onset);
}

ClipAnalyzer::ClipAnalyzer(const AnalysisSettings& settings)
    : settings_(checked(settings)),
      extractor_(audio::preset_by_name(settings.preset, settings.sample_rate)) {}

void ClipAnalyzer::analyse(const audio::AudioClip& clip, const std::string& name,
                           ClipAnalysis& out) {
  if (clip.frames() == 0) throw InputError(name, 0, "the clip has no audio frames");
  audio::AudioClip mono = audio::convert_clip(
      clip,
      {.channel_policy = audio::ChannelPolicy::mean, .target_sample_rate = settings_.sample_rate},
      name);
  analyse_mono(std::move(mono.samples), name, out);
}

void ClipAnalyzer::analyse_mono(std::vector<float> mono, const std::string& name,
                                ClipAnalysis& out) {
  if (mono.empty()) throw InputError(name, 0, "the clip has no audio frames");
  out.sample_rate = settings_.sample_rate;
  audio::AudioClip clip{settings_.sample_rate, 1, std::move(mono)};
  out.ebr_db = audio::measured_ebr_db(clip);
  out.mono = std::move(clip.samples);
  try {
    extractor_.compute(out.mono, out.features);
  } catch (const InputError& e) {
    throw InputError(name, 0, e.problem());
  }
  out.first_sound_frame = first_sound_frame(out.features.rms, settings_.silence_rms);
  out.onset_frame = onset_frame(out.features.flux, out.first_sound_frame, settings_.onset);
  out.hop_seconds =
      static_cast<double>(extractor_.config().stft.framing.hop) / settings_.sample_rate;
}

}  // namespace echoplan::perception
