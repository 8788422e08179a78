#include "perception/synthetic_feature_set.h"

#include <fmt/format.h>

#include <fstream>
#include <random>

#include "common/error.h"

namespace echoplan::perception {

namespace {

namespace fs = std::filesystem;
using Rows = std::vector<std::vector<double>>;

void check_spec(const SyntheticSpec& spec) {
  if (spec.objects < 1 || spec.sessions < 1 || spec.repeats < 1)
    throw InputError("a synthetic feature set needs at least one object, session and repeat");
  if (spec.actions.empty() || spec.modalities.empty())
    throw InputError("a synthetic feature set needs at least one action and one modality");
  if (!spec.action_scales.empty() && spec.action_scales.size() != spec.actions.size())
    throw InputError(fmt::format("{} action scales for {} actions", spec.action_scales.size(),
                                 spec.actions.size()));
  for (const SyntheticModality& m : spec.modalities)
    if (m.features < 1 || m.name.empty())
      throw InputError("every synthetic modality needs a name and at least one feature");
  if (spec.group_size < 0) throw InputError("the group size cannot be negative");
  if (!(spec.lookalike_share >= 0 && spec.lookalike_share <= 1) ||
      !(spec.lookalike_pull >= 0 && spec.lookalike_pull <= 1))
    throw InputError(fmt::format("the lookalike share ({}) and pull ({}) must lie in [0, 1]",
                                 spec.lookalike_share, spec.lookalike_pull));
  if (spec.lookalike_share > 0 && (spec.group_size < 1 || spec.objects <= spec.group_size))
    throw InputError("lookalike objects look like another group: they need at least two groups");
}

int group_count(const SyntheticSpec& spec) {
  return spec.group_size > 0 ? (spec.objects + spec.group_size - 1) / spec.group_size : 1;
}

void write_groups(const fs::path& dir, const SyntheticSpec& spec) {
  std::ofstream out(dir / "groups.csv");
  out << "object,group\n";
  for (int o = 0; o < spec.objects; ++o)
    out << synthetic_object_name(o) << "," << synthetic_group_name(o / spec.group_size) << "\n";
}

}  // namespace

std::string synthetic_object_name(int o) { return "obj" + std::to_string(o); }
std::string synthetic_group_name(int g) { return "group" + std::to_string(g); }

std::vector<int> synthetic_lookalikes(const SyntheticSpec& spec) {
  check_spec(spec);
  std::vector<int> lookalike(static_cast<std::size_t>(spec.objects));
  for (int o = 0; o < spec.objects; ++o)
    lookalike[static_cast<std::size_t>(o)] = spec.group_size > 0 ? o / spec.group_size : 0;
  if (spec.lookalike_share <= 0) return lookalike;
  std::mt19937_64 rng(spec.seed + 1);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::uniform_int_distribution<int> other(1, group_count(spec) - 1);
  for (int& group : lookalike) {
    const bool atypical = uniform(rng) < spec.lookalike_share;
    const int shift = other(rng);  // drawn for every object, so the draws keep one order
    if (atypical) group = (group + shift) % group_count(spec);
  }
  return lookalike;
}

void write_synthetic_feature_set(const fs::path& dir, const SyntheticSpec& spec) {
  check_spec(spec);
  // The draws keep one order (per action and modality: group means, object means, then each
  // session's offset and its repeats' noise), so a spec always makes the same numbers.
  const std::vector<int> lookalike = synthetic_lookalikes(spec);
  std::mt19937_64 rng(spec.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const int groups = group_count(spec);
  for (std::size_t a = 0; a < spec.actions.size(); ++a) {
    const std::string& action = spec.actions[a];
    const double scale = spec.action_scales.empty() ? 1.0 : spec.action_scales[a];
    fs::create_directories(dir / action);
    for (const SyntheticModality& m : spec.modalities) {
      auto draw = [&](int count) {
        Rows v(static_cast<std::size_t>(count));
        for (auto& row : v)
          for (int j = 0; j < m.features; ++j) row.push_back(normal(rng));
        return v;
      };
      const Rows group_means = draw(groups);
      const Rows object_means = draw(spec.objects);
      const double separation = scale * m.separation;
      std::ofstream out(dir / action / (m.name + ".csv"));
      out.precision(6);
      out << "object,session";
      for (int j = 0; j < m.features; ++j) out << ",f" << j;
      out << "\n";
      for (int o = 0; o < spec.objects; ++o)
        for (int s = 0; s < spec.sessions; ++s) {
          const auto session = draw(1)[0];
          const int g = spec.group_size > 0 ? o / spec.group_size : 0;
          const int h = lookalike[static_cast<std::size_t>(o)];
          const double pull = h == g ? 0.0 : spec.lookalike_pull;
          for (int r = 0; r < spec.repeats; ++r) {
            out << synthetic_object_name(o) << ",s" << s;
            for (int j = 0; j < m.features; ++j)
              out << ","
                  << spec.group_separation *
                             ((1 - pull) * group_means[g][j] + pull * group_means[h][j]) +
                         separation * object_means[o][j] + spec.session_sd * session[j] +
                         normal(rng);
            out << "\n";
          }
        }
      if (!out) throw InputError((dir / action / (m.name + ".csv")).string(), 0, "cannot write");
    }
  }
  if (spec.group_size > 0) write_groups(dir, spec);
}

}  // namespace echoplan::perception
