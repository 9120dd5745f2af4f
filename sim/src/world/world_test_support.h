#pragma once
// Helpers the simulator's tests share: one definition each, since a unity build compiles a
// target's test files as one translation unit.

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cogmap/sim/world_spec.h"

namespace cogmap::sim::testing {

/// A world read from YAML text, as the file "w.yaml" (the name its errors give).
inline WorldSpec parse(const std::string& text) {
  return parse_world(yaml::Node::load_string(text, "w.yaml"));
}

/// The source tree: $COGMAP_SOURCE_DIR (ctest sets it), else the one this test was built from.
inline std::filesystem::path source_dir() {
  if (const char* env = std::getenv("COGMAP_SOURCE_DIR")) return env;
  return COGMAP_SOURCE_DIR_FALLBACK;
}

}  // namespace cogmap::sim::testing
