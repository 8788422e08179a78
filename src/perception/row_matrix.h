// Feature rows as an Eigen matrix, for the row classifiers (row_classifier.h).
#pragma once

#include <Eigen/Dense>
#include <span>
#include <vector>

namespace echoplan::perception {

// rows as an n x D matrix; InputError for ragged rows or when `labels` is not one per row.
Eigen::MatrixXd rows_to_matrix(std::span<const std::vector<double>> rows, std::size_t labels);

}  // namespace echoplan::perception
