#include "audio/window.h"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "audio/name_table.h"
#include "common/error.h"

namespace echoplan::audio {
namespace {

constexpr detail::NameTable<WindowKind, 5> kNames{{
    {WindowKind::rectangular, "rect"},
    {WindowKind::hann_periodic, "hann"},
    {WindowKind::hann_symmetric, "hann_symmetric"},
    {WindowKind::hamming_periodic, "hamming"},
    {WindowKind::hamming_symmetric, "hamming_symmetric"},
}};

}  // namespace

std::vector<float> make_window(WindowKind kind, int length) {
  if (length < 1) throw InputError(fmt::format("window length {} must be at least 1", length));
  std::vector<float> window(static_cast<std::size_t>(length), 1.0f);
  if (kind == WindowKind::rectangular) return window;
  const bool symmetric =
      kind == WindowKind::hann_symmetric || kind == WindowKind::hamming_symmetric;
  const bool hann = kind == WindowKind::hann_periodic || kind == WindowKind::hann_symmetric;
  const double period = symmetric ? length - 1 : length;
  if (period <= 0) return window;
  // Generalised cosine window a - (1 - a) cos(2 pi n / period).
  const double a = hann ? 0.5 : 0.54;
  for (int n = 0; n < length; ++n)
    window[static_cast<std::size_t>(n)] =
        static_cast<float>(a - (1.0 - a) * std::cos(2.0 * std::numbers::pi * n / period));
  return window;
}

std::string_view window_name(WindowKind kind) { return detail::name_of(kNames, kind); }

WindowKind window_from_name(std::string_view name) {
  if (const auto kind = detail::value_named(kNames, name)) return *kind;
  throw InputError(fmt::format(
      "unknown window '{}' (expected rect, hann, hann_symmetric, hamming, hamming_symmetric)",
      name));
}

}  // namespace echoplan::audio
