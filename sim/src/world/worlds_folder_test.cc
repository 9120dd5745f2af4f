// Every shipped world loads through the real parser and builds a physics world: a broken file
// in worlds/ fails here, not in the middle of an experiment.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "cogmap/sim/physics_world.h"
#include "cogmap/sim/world_geometry.h"
#include "world/world_test_support.h"

namespace cogmap::sim {
namespace {

using testing::source_dir;

TEST(WorldsFolder, EveryWorldLoads) {
  const std::filesystem::path dir = source_dir() / "worlds";
  ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    ++count;
    WorldSpec world;
    ASSERT_NO_THROW(world = load_world(entry.path()));
    EXPECT_EQ(world.name, entry.path().stem().string());
    const WorldSurfaces surfaces = world_surfaces(world);
    EXPECT_GT(surfaces.surfaces.size(), 8u);
    EXPECT_FALSE(surfaces.corners.empty());
    PhysicsWorld physics(world);
    EXPECT_GT(physics.static_fixture_count(), 0);
    // A standing robot at the checked start pose touches nothing.
    physics.step({}, 0.01);
    EXPECT_FALSE(physics.in_contact());
  }
  EXPECT_GE(count, 4);
}

}  // namespace
}  // namespace cogmap::sim
