// libFuzzer target: arbitrary bytes as an object catalogue and as a simulator configuration,
// through the YAML reader (common/yaml_reader.h). Bad input must end in echoplan::InputError;
// anything else (a crash, a sanitizer report, another exception, a hang) is a bug.
#include <cstddef>
#include <cstdint>
#include <string>

#include "common/error.h"
#include "sim/catalogue.h"
#include "sim/sim_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const echoplan::sim::Catalogue catalogue = echoplan::sim::parse_catalogue(text, "fuzz.yaml");
    for (const auto& name : catalogue.object_names()) {
      const auto& object = catalogue.object(name);
      (void)object.total_mass();
      (void)object.inertia_diagonal();
    }
  } catch (const echoplan::InputError&) {
  }
  try {
    (void)echoplan::sim::parse_sim_config(text, "fuzz.yaml");
  } catch (const echoplan::InputError&) {
  }
  return 0;
}
