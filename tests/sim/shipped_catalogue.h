// Test fixtures shared by the sim tests: the catalogue shipped in objects/ and the nominal trial.
#pragma once

#include <string>

#include "../common/source_dir.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

namespace echoplan::sim {

inline const Catalogue& shipped_catalogue() {
  static const Catalogue c =
      load_catalogue(echoplan::testing::source_dir() + "/objects/catalogue.yaml");
  return c;
}

// Every truncated Gaussian at its mean, no tilt.
inline ActionVariation nominal_trial() {
  const VariabilityConfig v;
  ActionVariation p;
  p.impact_speed = v.impact_speed.mean;
  p.grasp_height = v.grasp_height.mean;
  p.push_speed = v.push_speed.mean;
  return p;
}

}  // namespace echoplan::sim
