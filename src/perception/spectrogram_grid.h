// The 10 x 10 spectrogram grid: CY101's audio layout, a clip as 100 numbers, each the mean log
// power of one block of its spectrogram, computed as the code Sinapov et al. published with an
// earlier study on the same robot computes it (the run that made the CY101 files is not published;
// its values, 10 to 27, are the size this gives).
//
// From the clip's mono samples at the analysis rate fs, scaled to 16-bit integers (x 32768, as the
// original reads a WAV's samples): frames of round(0.025625 fs) samples every round(0.01 fs) (410
// and 160 at 16 kHz), start-aligned, the last zero-padded; a symmetric Hamming window
// (0.54 - 0.46 cos(2 pi n / (N - 1))); the power |X_k|^2 of a real FFT of the smallest power of two
// that holds a frame (512); its lower half, bins 0 .. fft / 4 (129); max(ln power, 0). Then the
// frames are cut into 10 time bins of floor(frames / 10) frames and the bins into 10 frequency bins
// of floor(129 / 10) = 12 (what is left over at the end of either is dropped), each block's mean
// one feature, laid out time bin by time bin (entry 10 t + f), as the dataset stores them.
//
// At fs = 16 kHz (`train --sample-rate 16000`) this is the original's computation on a mono clip;
// at another rate the same durations and share of the spectrum. Not reproduced: the original read
// a stereo file's interleaved samples as one 16 kHz stream, whatever the file's rate.
#pragma once

#include <string>
#include <vector>

#include "perception/clip_analysis.h"

namespace echoplan::perception {

inline constexpr int kGridTimeBins = 10;
inline constexpr int kGridFrequencyBins = 10;

// The grid of `clip` (its mono samples at its sample rate). InputError for a clip with fewer
// frames than time bins.
std::vector<double> spectrogram_grid(const ClipAnalysis& clip);
// t1_f1, t1_f2, ..., t10_f10.
std::vector<std::string> spectrogram_grid_names();

}  // namespace echoplan::perception
