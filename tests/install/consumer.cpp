// Builds on an installed echoplan: plans Tiger with ABT and measures a tone's spectral centroid.
// Usage: consumer <prefix>/share/echoplan/problems/tiger.pomdp. Exit 0 when both answers are right.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "audio/features.h"
#include "pomdp/make_belief.h"
#include "pomdp/problem.h"
#include "solvers/make_solver.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  using namespace echoplan;
  const pomdp::Problem tiger = pomdp::load_problem(argv[1]);
  Rng rng(1);
  auto solver = solvers::make_solver("abt", tiger.model, solvers::SearchOptions{});
  solver->reset(*pomdp::make_belief(tiger, rng), rng);
  solver->improve(solvers::Budget::episodes(2000), rng);
  const std::string action = tiger.model->spec().action_names[solver->best_action()];

  std::vector<float> tone(22050);  // 1 s of 1 kHz
  for (std::size_t i = 0; i < tone.size(); ++i)
    tone[i] = static_cast<float>(std::sin(2.0 * std::numbers::pi * 1000.0 * i / 22050.0));
  const double centroid = audio::global_features(tone, 22050).centroid_hz;

  std::printf("tiger, first action: %s; centroid of a 1 kHz tone: %.1f Hz\n", action.c_str(),
              centroid);
  return action == "listen" && std::abs(centroid - 1000.0) < 5.0 ? 0 : 1;
}
