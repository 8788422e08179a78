#include "perception/observation_grades.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/error.h"

namespace echoplan::perception {

const char* observation_kind_name(ObservationKind kind) {
  switch (kind) {
    case ObservationKind::graded:
      return "graded";
    case ObservationKind::levels:
      return "levels";
    case ObservationKind::labels:
      break;
  }
  return "labels";
}

const std::vector<std::string>& observation_kind_names() {
  static const std::vector<std::string> names{"labels", "graded", "levels"};
  return names;
}

ObservationKind parse_observation_kind(const std::string& name) {
  if (name == "labels") return ObservationKind::labels;
  if (name == "graded") return ObservationKind::graded;
  if (name == "levels") return ObservationKind::levels;
  throw InputError(fmt::format("observations '{}' is not one of: {}", name,
                               fmt::join(observation_kind_names(), ", ")));
}

int grade_of(const GradeCalibration& grades, double confidence) {
  int grade = 0;
  while (grade < static_cast<int>(grades.edges.size()) &&
         confidence >= grades.edges[static_cast<std::size_t>(grade)])
    ++grade;
  return grade;
}

namespace {

// The terciles of the confidences (kGrades - 1 edges), so each grade holds about a third of the
// decisions; 1/3 and 2/3 without decisions.
std::vector<double> quantile_edges(std::span<const double> confidence) {
  std::vector<double> edges;
  std::vector<double> sorted(confidence.begin(), confidence.end());
  std::sort(sorted.begin(), sorted.end());
  for (int g = 1; g < kGrades; ++g) {
    if (sorted.empty()) {
      edges.push_back(static_cast<double>(g) / kGrades);
      continue;
    }
    const auto at = static_cast<std::size_t>(g) * sorted.size() / kGrades;
    edges.push_back(sorted[std::min(at, sorted.size() - 1)]);
  }
  return edges;
}

// The log-likelihood of `right` right and `wrong` wrong decisions under their own share right.
double band_log_likelihood(double right, double wrong) {
  const double n = right + wrong;
  double ll = 0.0;
  if (right > 0.0) ll += right * std::log(right / n);
  if (wrong > 0.0) ll += wrong * std::log(wrong / n);
  return ll;
}

// (counts + 1) / (n + kGrades): one pseudo-count per grade, so no grade rules a class out.
std::vector<double> smoothed(const std::vector<double>& counts) {
  double total = 0.0;
  for (double c : counts) total += c;
  std::vector<double> p;
  for (double c : counts) p.push_back((c + 1.0) / (total + kGrades));
  return p;
}

}  // namespace

GradeCalibration fit_grades(std::span<const double> confidence, const std::vector<bool>& right) {
  return fit_grades(confidence, right, quantile_edges(confidence));
}

std::vector<double> informative_edges(std::span<const double> score,
                                      const std::vector<bool>& right) {
  static_assert(kGrades == 3, "two cuts");
  if (score.size() != right.size())
    throw std::invalid_argument("informative_edges: one rightness flag per score");
  const std::size_t n = score.size();
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return score[a] < score[b]; });
  // rights_before[k]: right decisions among the k lowest scores.
  std::vector<double> rights_before(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) rights_before[k + 1] = rights_before[k] + right[order[k]];
  const std::size_t least = std::max<std::size_t>(5, n / 20);
  constexpr std::size_t kMostCuts = 128;
  // A cut at rank k puts the k lowest scores below it; only between distinct scores.
  std::vector<std::size_t> cuts;
  for (std::size_t c = 1; c < kMostCuts; ++c) {
    const std::size_t k = c * n / kMostCuts;
    if (k >= least && n - k >= least && score[order[k - 1]] < score[order[k]] &&
        (cuts.empty() || cuts.back() != k))
      cuts.push_back(k);
  }
  const auto band = [&](std::size_t from, std::size_t to) {
    const double r = rights_before[to] - rights_before[from];
    return band_log_likelihood(r, static_cast<double>(to - from) - r);
  };
  double best = -std::numeric_limits<double>::infinity();
  std::vector<double> edges;
  for (std::size_t i = 0; i < cuts.size(); ++i)
    for (std::size_t j = i + 1; j < cuts.size(); ++j) {
      if (cuts[j] - cuts[i] < least) continue;
      const double ll = band(0, cuts[i]) + band(cuts[i], cuts[j]) + band(cuts[j], n);
      if (ll > best) best = ll, edges = {score[order[cuts[i]]], score[order[cuts[j]]]};
    }
  return edges.empty() ? quantile_edges(score) : edges;
}

GradeCalibration fit_grades(std::span<const double> confidence, const std::vector<bool>& right,
                            std::vector<double> edges) {
  if (confidence.size() != right.size())
    throw std::invalid_argument("fit_grades: one rightness flag per confidence");
  GradeCalibration grades;
  grades.edges = std::move(edges);
  std::vector<double> right_counts(kGrades, 0.0), wrong_counts(kGrades, 0.0);
  for (std::size_t i = 0; i < confidence.size(); ++i)
    (right[i] ? right_counts
              : wrong_counts)[static_cast<std::size_t>(grade_of(grades, confidence[i]))] += 1.0;
  grades.given_right = smoothed(right_counts);
  grades.given_wrong = smoothed(wrong_counts);
  return grades;
}

std::vector<std::vector<double>> graded_table(const std::vector<std::vector<double>>& labels,
                                              const GradeCalibration& grades, int num_classes) {
  std::vector<std::vector<double>> table;
  for (std::size_t c = 0; c < labels.size(); ++c) {
    std::vector<double> row;
    for (int h = 0; h < num_classes; ++h) {
      const std::vector<double>& given =
          static_cast<std::size_t>(h) == c ? grades.given_right : grades.given_wrong;
      for (int g = 0; g < kGrades; ++g)
        row.push_back(labels[c][static_cast<std::size_t>(h)] * given[static_cast<std::size_t>(g)]);
    }
    // `unknown`, when the model rejects, stays one symbol.
    for (std::size_t s = static_cast<std::size_t>(num_classes); s < labels[c].size(); ++s)
      row.push_back(labels[c][s]);
    table.push_back(std::move(row));
  }
  return table;
}

std::vector<std::string> graded_symbols(const std::vector<std::string>& classes, bool reject,
                                        ObservationKind kind) {
  std::vector<std::string> symbols;
  for (const std::string& c : classes)
    for (int g = 0; g < kGrades; ++g) symbols.push_back(graded_name(c, g, kind));
  if (reject) symbols.emplace_back("unknown");
  return symbols;
}

int graded_symbol(int symbol, int grade, int num_classes) {
  return symbol >= num_classes ? num_classes * kGrades : symbol * kGrades + grade;
}

std::string graded_name(const std::string& label, int grade, ObservationKind kind) {
  const auto& names = kind == ObservationKind::levels ? kLevelNames : kGradeNames;
  return label + "@" + names.at(static_cast<std::size_t>(grade));
}

std::string class_of_symbol(const std::string& symbol) {
  for (const ObservationKind kind : {ObservationKind::graded, ObservationKind::levels})
    for (int g = 0; g < kGrades; ++g) {
      const std::string suffix = graded_name("", g, kind);
      if (symbol.size() > suffix.size() && symbol.ends_with(suffix))
        return symbol.substr(0, symbol.size() - suffix.size());
    }
  return symbol;
}

}  // namespace echoplan::perception
