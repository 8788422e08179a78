#include "perception/row_matrix.h"

#include <fmt/format.h>

#include "common/error.h"

namespace echoplan::perception {

Eigen::MatrixXd rows_to_matrix(std::span<const std::vector<double>> rows, std::size_t labels) {
  if (labels != rows.size()) throw InputError("one label per feature row is needed");
  const auto d = rows.empty() ? Eigen::Index{0} : static_cast<Eigen::Index>(rows[0].size());
  Eigen::MatrixXd x(static_cast<Eigen::Index>(rows.size()), d);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (static_cast<Eigen::Index>(rows[i].size()) != d)
      throw InputError(fmt::format("feature rows have {} values, got {}", d, rows[i].size()));
    x.row(static_cast<Eigen::Index>(i)) = Eigen::Map<const Eigen::RowVectorXd>(rows[i].data(), d);
  }
  return x;
}

}  // namespace echoplan::perception
