// The compiled part of the Python module `echoplan` (python/echoplan/__init__.py imports it as
// echoplan._echoplan and adds the parts written in Python). docs/python.md is its guide.
#include <pybind11/pybind11.h>

#include "bindings.h"

PYBIND11_MODULE(_echoplan, m) {
  m.doc() =
      "echoplan's C++ core: problems, beliefs and planners, the exact solver and certify, audio "
      "features and observation models, the loop with robot parts written in Python, and "
      "campaigns. Import `echoplan`, not this module.";
  m.attr("__version__") = ECHOPLAN_VERSION;
  using namespace echoplan::python;
  bind_errors(m);
  bind_problems(m);
  bind_planners(m);
  bind_exact(m);
  bind_perception(m);
  bind_robots(m);
  bind_campaigns(m);
}
