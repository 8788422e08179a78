// Synthetic feature sets for the tests: Gaussian classes whose separations are known, written to
// disk in the feature-set format (docs/feature-sets.md) so the tests also go through the loader.
// Every number comes from the spec's seed.
//
// For action a, modality m and feature j, object o's mean is
//   group_separation * G[group(o)][a][m][j] + separation_m * O[o][a][m][j]
// with G, O independent standard normals; a performance is that mean plus session_sd * S (one
// draw per (session, action, modality, feature), shared by the session's repeats: correlated
// repeats) plus a standard normal. A modality with separation 0 and group_separation 0 is pure
// noise.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace echoplan::perception::test_features {

struct SyntheticModality {
  std::string name;
  int features = 5;
  double separation = 3.0;  // spread of object means, in noise standard deviations
};

struct SyntheticSpec {
  int objects = 10;
  int sessions = 5;  // per object
  int repeats = 1;   // performances of each action per session
  std::vector<std::string> actions{"strike"};
  std::vector<SyntheticModality> modalities{{"audio", 5, 3.0}};
  int group_size = 0;  // objects per group (object o is in group o / group_size); 0: no groups
  double group_separation = 0.0;
  double session_sd = 0.0;
  unsigned long long seed = 1;
};

inline std::string object_name(int o) { return "obj" + std::to_string(o); }
inline std::string group_name(int g) { return "group" + std::to_string(g); }

// Writes DIR/<action>/<modality>.csv and, with groups, DIR/groups.csv (an ignored file in DIR).
inline void write_synthetic_feature_set(const std::filesystem::path& dir,
                                        const SyntheticSpec& spec) {
  std::mt19937_64 rng(spec.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const int groups =
      spec.group_size > 0 ? (spec.objects + spec.group_size - 1) / spec.group_size : 1;
  for (const std::string& action : spec.actions) {
    std::filesystem::create_directories(dir / action);
    for (const SyntheticModality& m : spec.modalities) {
      auto draw = [&](int count) {
        std::vector<std::vector<double>> v(static_cast<std::size_t>(count));
        for (auto& row : v)
          for (int j = 0; j < m.features; ++j) row.push_back(normal(rng));
        return v;
      };
      const auto group_means = draw(groups);
      const auto object_means = draw(spec.objects);
      std::ofstream out(dir / action / (m.name + ".csv"));
      out.precision(6);
      out << "object,session";
      for (int j = 0; j < m.features; ++j) out << ",f" << j;
      out << "\n";
      for (int o = 0; o < spec.objects; ++o)
        for (int s = 0; s < spec.sessions; ++s) {
          const auto session = draw(1)[0];
          const int g = spec.group_size > 0 ? o / spec.group_size : 0;
          for (int r = 0; r < spec.repeats; ++r) {
            out << object_name(o) << ",s" << s;
            for (int j = 0; j < m.features; ++j)
              out << ","
                  << spec.group_separation * group_means[g][j] + m.separation * object_means[o][j] +
                         spec.session_sd * session[j] + normal(rng);
            out << "\n";
          }
        }
    }
  }
  if (spec.group_size > 0) {
    std::ofstream out(dir / "groups.csv");
    out << "object,group\n";
    for (int o = 0; o < spec.objects; ++o)
      out << object_name(o) << "," << group_name(o / spec.group_size) << "\n";
  }
}

// A fresh empty folder under the system's temporary folder.
inline std::filesystem::path fresh_folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("echoplan_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace echoplan::perception::test_features
