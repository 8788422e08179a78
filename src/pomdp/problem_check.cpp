#include "pomdp/problem_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace echoplan::pomdp {

namespace {

constexpr double kSame = 1e-12;  // probabilities closer than this count as equal

std::string state_name(const ModelSpec& spec, const TabularModel& t, int s) {
  // A tabular model from a .pomdp names its states; the object model's last state is 'done'.
  const auto& names = spec.state.discrete_value_names.empty() ? std::vector<std::string>{}
                                                              : spec.state.discrete_value_names[0];
  if (s < static_cast<int>(names.size())) return names[s];
  return s == t.num_states() - 1 ? "done" : "state " + std::to_string(s);
}

// True when some action waits for `action` (Model::prerequisites): then it helps by what it opens.
bool opens_another(const Model& model, int action) {
  for (int a = 0; a < model.num_actions(); ++a) {
    const std::vector<int> required = model.prerequisites(a);
    if (std::find(required.begin(), required.end(), action) != required.end()) return true;
  }
  return false;
}

void check_tables(const Model& model, const TabularModel& t, std::vector<std::string>& out) {
  const ModelSpec& spec = model.spec();
  const int ns = t.num_states(), na = t.num_actions(), no = t.num_observations();
  const std::vector<double> start = t.initial_belief();

  for (int a = 0; a < na; ++a) {
    if (opens_another(model, a)) continue;
    bool keeps_state = true, same_everywhere = true;
    int first = -1;
    for (int s = 0; s < ns && (keeps_state || same_everywhere); ++s) {
      if (t.terminal(s)) continue;
      keeps_state = keeps_state && t.transition(s, a, s) == 1.0;
      if (first < 0) {
        first = s;
        continue;
      }
      for (int o = 0; o < no; ++o) {
        if (std::abs(t.observation(a, s, o) - t.observation(a, first, o)) > kSame)
          same_everywhere = false;
      }
    }
    if (keeps_state && same_everywhere && first >= 0) {
      out.push_back(
          "action '" + spec.action_names[a] +
          "' never changes the state and its observations are the same in every state, so it can "
          "never help: remove it or give it observation rows that differ between states");
    }
  }

  for (int s = 0; s < ns; ++s) {
    if (t.terminal(s) && start[s] > 0.0) {
      std::ostringstream msg;
      msg << "the start belief gives probability " << start[s] << " to terminal state '"
          << state_name(spec, t, s)
          << "', so episodes can be over before they start: give it 0 in the start belief";
      out.push_back(msg.str());
    }
  }

  // Reachability from the start belief over any action sequence (breadth-first over T > 0).
  std::vector<bool> reached(ns, false);
  std::vector<int> frontier;
  for (int s = 0; s < ns; ++s) {
    if (start[s] > 0.0) {
      reached[s] = true;
      frontier.push_back(s);
    }
  }
  std::vector<bool> emitted(no, false);
  while (!frontier.empty()) {
    const int s = frontier.back();
    frontier.pop_back();
    if (t.terminal(s)) continue;
    for (int a = 0; a < na; ++a) {
      for (int s2 = 0; s2 < ns; ++s2) {
        if (t.transition(s, a, s2) <= 0.0) continue;
        for (int o = 0; o < no; ++o) emitted[o] = emitted[o] || t.observation(a, s2, o) > 0.0;
        if (!reached[s2]) {
          reached[s2] = true;
          frontier.push_back(s2);
        }
      }
    }
  }
  for (int s = 0; s < ns; ++s) {
    if (!reached[s]) {
      out.push_back(
          "state '" + state_name(spec, t, s) +
          "' cannot be reached from the start belief: remove it or give it start probability");
    }
  }
  for (int o = 0; o < no; ++o) {
    if (!emitted[o]) {
      out.push_back("observation '" + spec.observation.names[o] +
                    "' can never occur: remove it or give it probability in some O row");
    }
  }
}

void check_objects(const ObjectProblemData& d, std::vector<std::string>& out) {
  const int k = static_cast<int>(d.objects.size());
  double worst = d.collision_reward;
  for (const auto& row : d.sorting_reward)
    worst = std::min(worst, *std::min_element(row.begin(), row.end()));
  for (int i = 0; i < k; ++i) {
    if (d.prior[i] == 0.0) {
      out.push_back(
          "object '" + d.objects[i] +
          "' has prior 0 and will never be considered: give it weight in initial_belief.objects "
          "or remove it");
    }
    bool any_better = false;
    for (const auto& row : d.sorting_reward) any_better = any_better || row[i] > worst;
    if (!any_better) {
      out.push_back("no sorting action pays more than the worst outcome for object '" +
                    d.objects[i] +
                    "': give one sorting action a better reward for it in reward.sorting");
    }
  }
  for (int i = 0; i < k; ++i) {
    for (int j = i + 1; j < k; ++j) {
      bool identical = true;
      for (std::size_t a = 0; a < d.sensing.size() && identical; ++a) {
        for (std::size_t o = 0; o < d.observation_symbols.size(); ++o) {
          if (std::abs(d.observation_table[a][i][o] - d.observation_table[a][j][o]) > kSame)
            identical = false;
        }
      }
      bool same_place = true;
      for (const auto& row : d.sorting_reward) same_place = same_place && row[i] == row[j];
      if (identical && !same_place) {
        out.push_back(
            "objects '" + d.objects[i] + "' and '" + d.objects[j] +
            "' sound the same under every sensing action but belong in different places, so no "
            "policy can sort them reliably: add a sensing action that tells them apart");
      }
    }
  }
}

}  // namespace

std::vector<std::string> check_problem(const Problem& problem) {
  std::vector<std::string> out;
  if (const ObjectIdentificationModel* object_model = problem.model->object_identification()) {
    check_objects(object_model->data(), out);
  }
  if (const TabularModel* t = problem.model->tabular()) check_tables(*problem.model, *t, out);
  return out;
}

}  // namespace echoplan::pomdp
