// libFuzzer entry: any bytes as a world file through the strict YAML reader and the world
// loader must end in a parsed world or a yaml::ConfigError, never a crash, a hang or another
// exception (scripts/fuzz; docs/reliability.md).
#include <cstddef>
#include <cstdint>
#include <string>

#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const cogmap::sim::WorldSpec world =
        cogmap::sim::parse_world(cogmap::yaml::Node::load_string(text, "fuzz.yaml"));
    (void)cogmap::sim::world_bounds(world);
  } catch (const cogmap::yaml::ConfigError&) {
  }
  return 0;
}
