// Synthetic feature sets: Gaussian classes whose separations are known, written to disk in the
// feature-set format (docs/feature-sets.md), for the tests, the benchmarks and anyone trying
// echoplan without a robot (`bench/make_feature_set`). Every number comes from the spec's seed.
//
// For action a, modality m and feature j, object o's mean is
//   group_separation * G[group(o)][a][m][j] + action_scale[a] * separation_m * O[o][a][m][j]
// with G, O independent standard normals; a performance is that mean plus session_sd * S (one
// draw per (session, action, modality, feature), shared by the session's repeats: correlated
// repeats) plus a standard normal. A modality with separation 0 and group_separation 0 is pure
// noise; actions with different scales differ in how informative they are.
//
// Atypical objects (lookalike_share > 0, with groups): a share of the objects look like another
// group in every action at once, as a real object unlike its category does (a weighted can, a
// foam-filled bottle): their group term is (1 - pull) G[group(o)] + pull G[lookalike(o)], the same
// lookalike group for all actions. So their errors are correlated across behaviours, which the
// independent object terms O alone never make. Which objects, and their lookalikes, are drawn
// from a stream of their own (seed + 1), so a spec without them makes the same numbers as before.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace echoplan::perception {

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
  // Per action, multiplies every modality's separation; empty: 1 for every action.
  std::vector<double> action_scales;
  std::vector<SyntheticModality> modalities{{"audio", 5, 3.0}};
  int group_size = 0;  // objects per group (object o is in group o / group_size); 0: no groups
  double group_separation = 0.0;
  double session_sd = 0.0;
  double lookalike_share = 0.0;  // in [0, 1]: the chance that an object looks like another group
  double lookalike_pull = 0.6;   // in [0, 1]: how far towards its lookalike group it sits
  unsigned long long seed = 1;
};

std::string synthetic_object_name(int o);  // "obj<o>"
std::string synthetic_group_name(int g);   // "group<g>"

// Per object, the group it looks like in every action: its own group, or for an atypical object
// another group (drawn from the spec's seed as write_synthetic_feature_set draws it).
std::vector<int> synthetic_lookalikes(const SyntheticSpec& spec);

// Writes DIR/<action>/<modality>.csv and, with groups, DIR/groups.csv (a file the feature-set
// loader ignores). Throws InputError for a spec that cannot make a feature set (no objects,
// actions or modalities, a count below 1, action_scales of the wrong length, atypical objects
// without two groups or with a share or pull outside [0, 1]).
void write_synthetic_feature_set(const std::filesystem::path& dir, const SyntheticSpec& spec);

}  // namespace echoplan::perception
