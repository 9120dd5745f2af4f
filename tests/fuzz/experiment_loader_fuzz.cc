// libFuzzer entry: any bytes as an experiment file through the strict YAML reader and the
// experiment parser must end in an Experiment or a yaml::ConfigError (scripts/fuzz).
#include <cstddef>
#include <cstdint>
#include <string>

#include "cogmap/experiments/experiment_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)cogmap::experiments::load_experiment_text(text, "fuzz.yaml");
  } catch (const cogmap::yaml::ConfigError&) {
  }
  return 0;
}
