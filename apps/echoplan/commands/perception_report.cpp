#include "commands/perception_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace echoplan::cli {

std::string accuracy_text(const perception::ConfusionMatrix& c) {
  int right = 0, known = 0;
  for (std::size_t k = 0; k < c.objects.size(); ++k) {
    const auto it = std::find(c.symbols.begin(), c.symbols.end(), c.objects[k]);
    if (it == c.symbols.end()) continue;
    right += c.counts[k][static_cast<std::size_t>(it - c.symbols.begin())];
    for (int n : c.counts[k]) known += n;
  }
  return fmt::format("{:.3f} ({} of {})", c.accuracy(), right, known);
}

void print_confusion(const std::string& title, const perception::ConfusionMatrix& c) {
  fmt::print("{}: accuracy {}\n", title, accuracy_text(c));
  std::size_t width = 12;  // "true \\ heard"
  for (const auto& o : c.objects) width = std::max(width, o.size());
  std::size_t cell = 5;
  for (const auto& s : c.symbols) cell = std::max(cell, s.size());
  fmt::print("  {:<{}}", "true \\ heard", width);
  for (const auto& s : c.symbols) fmt::print(" {:>{}}", s, cell);
  fmt::print("\n");
  for (std::size_t k = 0; k < c.objects.size(); ++k) {
    fmt::print("  {:<{}}", c.objects[k], width);
    for (int n : c.counts[k]) fmt::print(" {:>{}}", n, cell);
    fmt::print("\n");
  }
}

nlohmann::json confusion_json(const perception::ConfusionMatrix& c) {
  return {{"accuracy", c.accuracy()},
          {"objects", c.objects},
          {"symbols", c.symbols},
          {"confusion", c.counts}};
}

}  // namespace echoplan::cli
