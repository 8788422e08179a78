// Compares the psf and librosa presets with the reference vectors in tests/data/reference/audio/
// (computed in float64 by python_speech_features 0.6.1 and librosa 0.11): every expected file of
// every input.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "../common/source_dir.h"
#include "audio/features.h"
#include "audio/io.h"

namespace echoplan::audio {
namespace {

namespace fs = std::filesystem;
const fs::path kReference =
    fs::path(echoplan::testing::source_dir()) / "tests/data/reference/audio";

struct Table {
  std::size_t rows = 0, cols = 0;
  std::vector<double> v;
  double at(std::size_t r, std::size_t c) const { return v[r * cols + c]; }
};

Table read_csv(const fs::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << path;
  Table t;
  std::string line;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::string cell;
    std::size_t cols = 0;
    while (std::getline(ss, cell, ',')) {
      t.v.push_back(std::stod(cell));
      ++cols;
    }
    if (t.rows == 0) t.cols = cols;
    EXPECT_EQ(cols, t.cols) << path << " row " << t.rows;
    ++t.rows;
  }
  return t;
}

std::vector<std::string> input_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kReference / "inputs"))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

class Reference : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    clip_ = read_audio((kReference / "inputs" / GetParam()).string(),
                       {.channel_policy = ChannelPolicy::mean});
    expected_ = kReference / "expected" / fs::path(GetParam()).stem();
  }
  Table expected(const std::string& name) const { return read_csv(expected_ / (name + ".csv")); }
  Features features(const FeatureConfig& config) const {
    FeatureExtractor extractor(config);
    Features f;
    extractor.compute(clip_.samples, f);
    return f;
  }
  AudioClip clip_;
  fs::path expected_;
};

void expect_shape(const FeatureMatrix& m, const Table& t, const std::string& what) {
  ASSERT_EQ(m.rows, t.rows) << what;
  ASSERT_EQ(m.cols, t.cols) << what;
}

// Tolerances. The references are float64; our FFT (Debian's KISS FFT) is float32 and our outputs
// are float32. Two error sources, each with its own bound:
//  - float32 output rounding: half an ulp, 6e-8 relative; we allow 4 ulps (kOutputRelative) of
//  |value|;
//  - float32 FFT rounding: each bin's error is ~1e-7 * sqrt(log2 N) of the frame's *loudest*
//  content,
//    not of the bin itself, so a band E_m far below the loudest band E_max of its frame has a
//    relative error up to kFftRelative * E_max / E_m. In log units that is |d ln E_m| <=
//    kFftRelative * E_max / E_m. Measured worst case over all inputs is 5e-8; kFftRelative = 1e-6
//    leaves a 20x margin.
constexpr double kOutputRelative = 2.4e-7;
constexpr double kFftRelative = 1e-6;

// Allowed error (in the table's own log unit) of each band of frame `r` of a log-energy table.
std::vector<double> allowed_log_errors(const Table& t, std::size_t r, bool decibel) {
  const double to_nat = decibel ? std::log(10.0) / 10.0 : 1.0;
  auto energy = [&](std::size_t c) { return std::exp(t.at(r, c) * to_nat); };
  double loudest = 0.0;
  for (std::size_t c = 0; c < t.cols; ++c) loudest = std::max(loudest, energy(c));
  std::vector<double> allowed(t.cols);
  for (std::size_t c = 0; c < t.cols; ++c)
    allowed[c] =
        kOutputRelative * std::abs(t.at(r, c)) + kFftRelative * loudest / energy(c) / to_nat;
  return allowed;
}

void expect_log_energies(const FeatureMatrix& m, const Table& t, bool decibel,
                         const std::string& what) {
  expect_shape(m, t, what);
  for (std::size_t r = 0; r < t.rows; ++r) {
    const auto allowed = allowed_log_errors(t, r, decibel);
    for (std::size_t c = 0; c < t.cols; ++c)
      ASSERT_NEAR(m.at(r, c), t.at(r, c), allowed[c]) << what << " frame " << r << " band " << c;
  }
}

// Cepstra are lifted orthonormal DCTs of the log energies: |d c_i| <= lift_i * ||d log E||_2
// (Cauchy- Schwarz with a unit-norm DCT row), with ||d log E|| bounded by the per-band allowances
// above.
void expect_cepstra(const FeatureMatrix& m, const Table& cepstra, const Table& log_energies,
                    bool decibel, int lifter, bool energy_in_c0, const std::string& what) {
  expect_shape(m, cepstra, what);
  ASSERT_EQ(cepstra.rows, log_energies.rows);
  for (std::size_t r = 0; r < cepstra.rows; ++r) {
    double norm = 0.0;
    for (double a : allowed_log_errors(log_energies, r, decibel)) norm += a * a;
    norm = std::sqrt(norm);
    for (std::size_t i = 0; i < cepstra.cols; ++i) {
      const double lift =
          lifter > 0
              ? 1.0 + lifter / 2.0 * std::sin(std::numbers::pi * static_cast<double>(i) / lifter)
              : 1.0;
      // c0 = ln(total energy) when energy_in_c0: float32 FFT relative error of a sum of all bins.
      const double bound = (i == 0 && energy_in_c0) ? kFftRelative : lift * norm;
      ASSERT_NEAR(m.at(r, i), cepstra.at(r, i),
                  kOutputRelative * std::abs(cepstra.at(r, i)) + bound)
          << what << " frame " << r << " coefficient " << i;
    }
  }
}

TEST_P(Reference, PsfLogfbank) {
  expect_log_energies(features(psf_preset(clip_.sample_rate)).log_mel, expected("psf_logfbank"),
                      false, "psf_logfbank");
}

TEST_P(Reference, PsfMfcc) {
  expect_cepstra(features(psf_preset(clip_.sample_rate)).mfcc, expected("psf_mfcc"),
                 expected("psf_logfbank"), false, 22, true, "psf_mfcc");
}

TEST_P(Reference, LibrosaMelspecDb) {
  expect_log_energies(features(librosa_preset(clip_.sample_rate)).log_mel,
                      expected("librosa_melspec_db"), true, "librosa_melspec_db");
}

TEST_P(Reference, LibrosaMfcc) {
  expect_cepstra(features(librosa_preset(clip_.sample_rate)).mfcc, expected("librosa_mfcc"),
                 expected("librosa_melspec_db"), true, 0, false, "librosa_mfcc");
}

TEST_P(Reference, LibrosaCentroid) {
  // A magnitude-weighted mean of bin frequencies: float32 magnitudes are off by ~6e-8 * sqrt(N) ~
  // 3e-6 of the frame's loudest bins, so the mean moves by at most that fraction of the frequency
  // span sr / 2.
  const Table t = expected("librosa_centroid");
  const FeatureMatrix m = features(librosa_preset(clip_.sample_rate)).centroid;
  expect_shape(m, t, "centroid");
  const double tolerance = 3e-6 * clip_.sample_rate / 2.0;
  for (std::size_t r = 0; r < t.rows; ++r)
    ASSERT_NEAR(m.at(r, 0), t.at(r, 0), tolerance) << "frame " << r;
}

TEST_P(Reference, LibrosaRms) {
  // Accumulated in double from float32 samples that are exact: only the float32 output rounds.
  const Table t = expected("librosa_rms");
  const FeatureMatrix m = features(librosa_preset(clip_.sample_rate)).rms;
  expect_shape(m, t, "rms");
  for (std::size_t r = 0; r < t.rows; ++r)
    ASSERT_NEAR(m.at(r, 0), t.at(r, 0), kOutputRelative * t.at(r, 0) + 1e-12) << "frame " << r;
}

TEST_P(Reference, LibrosaZcr) {
  // A count divided by 2048: the counts must be identical (a difference of one crossing is 4.9e-4).
  const Table t = expected("librosa_zcr");
  const FeatureMatrix m = features(librosa_preset(clip_.sample_rate)).zcr;
  expect_shape(m, t, "zcr");
  for (std::size_t r = 0; r < t.rows; ++r)
    ASSERT_EQ(std::lround(m.at(r, 0) * 2048.0), std::lround(t.at(r, 0) * 2048.0)) << "frame " << r;
}

TEST_P(Reference, GlobalFeatures) {
  std::ifstream in(expected_ / "global.json");
  const auto g = nlohmann::json::parse(in);
  EXPECT_EQ(clip_.sample_rate, g["sample_rate"].get<int>());
  EXPECT_EQ(clip_.frames(), g["frames"].get<std::size_t>());
  EXPECT_EQ(psf_preset(clip_.sample_rate).stft.fft_size, g["psf_nfft"].get<int>());
  const GlobalFeatures mine = global_features(clip_.samples, clip_.sample_rate);
  // RMS is accumulated in double over exact samples: agreement to double rounding of a long sum.
  EXPECT_NEAR(mine.rms, g["rms"].get<double>(), 1e-12);
  EXPECT_EQ(mine.zero_crossings, g["zero_crossings"].get<long long>());
  // Whole-signal float32 FFT of up to 88200 points: bin errors ~6e-8 * log2(N) relative to the
  // spectrum's RMS; the magnitude-weighted mean frequency moves by well under 1e-6 of itself.
  const double centroid = g["centroid_hz_mag_rfft_whole"].get<double>();
  EXPECT_NEAR(mine.centroid_hz, centroid, 1e-6 * centroid);
}

TEST_P(Reference, ShapesMatchShapesJson) {
  std::ifstream in(kReference / "shapes.json");
  const auto shapes = nlohmann::json::parse(in).at(GetParam());
  const Features psf = features(psf_preset(clip_.sample_rate));
  const Features lib = features(librosa_preset(clip_.sample_rate));
  auto check = [&](const FeatureMatrix& m, const char* name) {
    EXPECT_EQ(m.rows, shapes.at(name)[0].get<std::size_t>()) << name;
    EXPECT_EQ(m.cols, shapes.at(name)[1].get<std::size_t>()) << name;
  };
  check(psf.mfcc, "psf_mfcc");
  check(psf.log_mel, "psf_logfbank");
  check(lib.mfcc, "librosa_mfcc");
  check(lib.log_mel, "librosa_melspec_db");
  check(lib.centroid, "librosa_centroid");
  check(lib.rms, "librosa_rms");
  check(lib.zcr, "librosa_zcr");
}

INSTANTIATE_TEST_SUITE_P(Inputs, Reference, ::testing::ValuesIn(input_names()),
                         [](const auto& param_info) {
                           return fs::path(param_info.param).stem().string();
                         });

}  // namespace
}  // namespace echoplan::audio
