// The names of frame-wise features, as on the command line, and picking one out of a Features.
#include <fmt/format.h>

#include "audio/features.h"
#include "audio/name_table.h"
#include "common/error.h"

namespace echoplan::audio {

namespace {
constexpr detail::NameTable<FeatureKind, 9> kFeatureNames{{
    {FeatureKind::log_mel, "logmel"},
    {FeatureKind::mfcc, "mfcc"},
    {FeatureKind::centroid, "centroid"},
    {FeatureKind::bandwidth, "bandwidth"},
    {FeatureKind::rolloff, "rolloff"},
    {FeatureKind::flatness, "flatness"},
    {FeatureKind::flux, "flux"},
    {FeatureKind::rms, "rms"},
    {FeatureKind::zcr, "zcr"},
}};
}  // namespace

std::string_view feature_name(FeatureKind kind) { return detail::name_of(kFeatureNames, kind); }

FeatureKind feature_from_name(std::string_view name) {
  if (const auto kind = detail::value_named(kFeatureNames, name)) return *kind;
  throw InputError(
      fmt::format("unknown feature '{}' (expected logmel, mfcc, centroid, bandwidth, rolloff, "
                  "flatness, flux, rms or zcr)",
                  name));
}

const FeatureMatrix& select_feature(const Features& f, FeatureKind kind) {
  switch (kind) {
    case FeatureKind::log_mel:
      return f.log_mel;
    case FeatureKind::mfcc:
      return f.mfcc;
    case FeatureKind::centroid:
      return f.centroid;
    case FeatureKind::bandwidth:
      return f.bandwidth;
    case FeatureKind::rolloff:
      return f.rolloff;
    case FeatureKind::flatness:
      return f.flatness;
    case FeatureKind::flux:
      return f.flux;
    case FeatureKind::rms:
      return f.rms;
    case FeatureKind::zcr:
      return f.zcr;
  }
  return f.log_mel;
}

}  // namespace echoplan::audio
