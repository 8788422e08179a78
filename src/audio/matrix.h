// A dense feature matrix: one row per frame, one column per coefficient (mel band, cepstrum, ...).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace echoplan::audio {

// Row-major rows x cols values. Invariant: values.size() == rows * cols.
struct FeatureMatrix {
  std::size_t rows = 0;
  std::size_t cols = 0;
  std::vector<float> values;

  // Reshapes to rows x cols; keeps the allocation when the size does not grow. Contents are
  // unspecified.
  void resize(std::size_t new_rows, std::size_t new_cols) {
    rows = new_rows;
    cols = new_cols;
    values.resize(rows * cols);
  }
  float& at(std::size_t row, std::size_t col) { return values[row * cols + col]; }
  float at(std::size_t row, std::size_t col) const { return values[row * cols + col]; }
  std::span<float> row(std::size_t r) { return {values.data() + r * cols, cols}; }
  std::span<const float> row(std::size_t r) const { return {values.data() + r * cols, cols}; }
};

}  // namespace echoplan::audio
