// Analysis windows for framing a signal before the FFT.
//
// Periodic windows (length N, period N) are what spectral analysis uses (librosa, scipy
// `fftbins=True`); symmetric ones (period N - 1) are the filter-design form (numpy.hanning,
// numpy.hamming).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace echoplan::audio {

enum class WindowKind {
  rectangular,        // all ones (python_speech_features' default)
  hann_periodic,      // 0.5 - 0.5 cos(2 pi n / N)       (librosa's default)
  hann_symmetric,     // 0.5 - 0.5 cos(2 pi n / (N - 1))  (numpy.hanning)
  hamming_periodic,   // 0.54 - 0.46 cos(2 pi n / N)
  hamming_symmetric,  // 0.54 - 0.46 cos(2 pi n / (N - 1)) (numpy.hamming)
};

// The `length` window samples, computed in double and rounded to float. length >= 1; a symmetric
// window of length 1 is {1}.
std::vector<float> make_window(WindowKind kind, int length);

// Names used in files and on the command line: "rect", "hann", "hann_symmetric", "hamming",
// "hamming_symmetric". window_from_name throws InputError listing the valid names.
std::string_view window_name(WindowKind kind);
WindowKind window_from_name(std::string_view name);

}  // namespace echoplan::audio
