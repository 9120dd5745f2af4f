#pragma once
/// Test support: the message of the yaml::ConfigError a call throws ("" when it throws none),
/// so tests can check that an error names the file, line and key.

#include <functional>
#include <string>

#include "cogmap/sim/yaml_strict.h"

namespace cogmap::yaml::testing {

inline std::string config_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

}  // namespace cogmap::yaml::testing
