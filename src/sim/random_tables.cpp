#include "sim/random_tables.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <numbers>
#include <string_view>

#include "common/error.h"
#include "common/rng.h"
#include "sim/modal_model.h"

namespace echoplan::sim {
namespace {

// The tables' stream under a seed ("rtabl"), apart from every other draw.
constexpr std::uint64_t kRandomTablesStream = 0x727461626c;
constexpr std::string_view kPrefix = "random:";
constexpr int kMostTables = 1000;
// Loss factors are met at 1 kHz: eta = alpha / omega + beta * omega.
constexpr double kOmega = 2.0 * std::numbers::pi * 1000.0;
constexpr double kMassShare = 0.2;  // of the loss factor taken by alpha

double log_uniform(Rng& rng, double lo, double hi) {
  return std::exp(std::log(lo) + uniform01(rng) * (std::log(hi) - std::log(lo)));
}
double uniform(Rng& rng, double lo, double hi) { return lo + uniform01(rng) * (hi - lo); }

Material damped(std::string name, double density, double modulus, double poisson,
                double loss_factor) {
  return Material{.name = std::move(name),
                  .density = density,
                  .youngs_modulus = modulus,
                  .poisson_ratio = poisson,
                  .alpha = kMassShare * loss_factor * kOmega,
                  .beta = (1.0 - kMassShare) * loss_factor / kOmega};
}

std::uint64_t tag_stream(const std::string& tag) {
  std::uint64_t h = 0;
  for (unsigned char c : tag) h = splitmix64(h ^ c);
  return h;
}

// N of "random:N"; 0 for any other name. InputError for a malformed or out-of-range N.
int random_count(const std::string& name) {
  if (name.rfind(kPrefix, 0) != 0) return 0;
  const std::string_view digits = std::string_view(name).substr(kPrefix.size());
  int n = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), n);
  if (error != std::errc{} || end != digits.data() + digits.size() || n < 1 || n > kMostTables)
    throw InputError(
        fmt::format("'{}': random tables are written random:N, N a whole number from 1 to {}", name,
                    kMostTables));
  return n;
}

}  // namespace

TableSpec random_table(std::uint64_t seed, const std::string& tag, int index,
                       const std::string& name, const TableSpec& lab) {
  Rng rng(
      derive_seed(seed, {kRandomTablesStream, tag_stream(tag), static_cast<std::uint64_t>(index)}));
  TableSpec t;
  t.name = name;
  const double modulus = log_uniform(rng, 2e9, 2.2e11);
  const double density = log_uniform(rng, 500.0, 8000.0);
  const double poisson = uniform(rng, 0.20, 0.35);
  const double loss = log_uniform(rng, 4e-4, 0.05);
  t.material = damped(name + "_top", density, modulus, poisson, loss);
  t.thickness = log_uniform(rng, 0.005, 0.040);
  t.surface = t.material;
  if (uniform01(rng) < 0.3)
    t.surface = damped(name + "_surface", 1200.0, log_uniform(rng, 2e6, 2e9), 0.45,
                       log_uniform(rng, 0.05, 0.4));
  t.friction = uniform(rng, 0.4, 0.9);
  t.dense = lab.dense;
  t.contact_loss_factor = lab.contact_loss_factor *
                          plate_point_impedance(lab.material, lab.thickness) /
                          plate_point_impedance(t.material, t.thickness);
  return t;
}

std::vector<std::string> expand_random_tables(Catalogue& catalogue,
                                              const std::vector<std::string>& names,
                                              std::uint64_t seed, const std::string& tag) {
  std::vector<std::string> out;
  int drawn = 0;
  for (const std::string& name : names) {
    const int n = random_count(name);
    if (n == 0) {
      out.push_back(name);
      continue;
    }
    for (int i = 0; i < n; ++i) {
      ++drawn;
      const std::string table_name =
          fmt::format("{}random_{}", tag.empty() ? "" : tag + "_", drawn);
      catalogue.tables[table_name] = random_table(seed, tag, drawn, table_name, catalogue.table);
      out.push_back(table_name);
    }
  }
  return out;
}

}  // namespace echoplan::sim
