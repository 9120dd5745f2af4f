// An error at a key no --set override wrote, but which the overrides made invalid, keeps the
// file's line and lists the overrides applied: on its own the file's line looks right.
#include <gtest/gtest.h>

#include <string>

#include "cogmap/experiments/experiment_config.h"
#include "experiment_config_test_support.h"

namespace cogmap::experiments {
namespace {

using test::error_of;
using test::write_temp;

const char* const kRoute = R"(name: r
world: w.yaml
controller:
  type: route
  waypoints: [[2.5, 3.0], [7.5, 3.0]]
)";

TEST(ExperimentOverrideErrors, AKeyMadeInvalidByAnOverrideNamesTheOverrides) {
  const auto p = write_temp("route.yaml", kRoute);
  EXPECT_EQ(error_of(p, {"controller.type=explore", "seed=3"}),
            p.string() +
                ":5: controller.waypoints: waypoints are only used by a route controller (with "
                "--set controller.type=explore, --set seed=3)");
  // Shown printable, as an override that caused the error is.
  EXPECT_EQ(error_of(p, {"controller.type=explore", "name=a\nb"}),
            p.string() +
                ":5: controller.waypoints: waypoints are only used by a route controller (with "
                "--set controller.type=explore, --set name=a\\nb)");
  // Without overrides the message is the file's alone.
  const auto bad = write_temp("explore.yaml",
                              "name: r\nworld: w.yaml\ncontroller:\n  type: "
                              "explore\n  waypoints: [[1, 1]]\n");
  EXPECT_EQ(error_of(bad), bad.string() +
                               ":5: controller.waypoints: waypoints are only used by a "
                               "route controller");
  // An error the override wrote itself still names that override alone.
  const std::string own = error_of(p, {"seed=3", "controller.type=walk"});
  EXPECT_EQ(own.rfind(p.string() + ":4: controller.type: ", 0), 0u) << own;
  EXPECT_TRUE(own.ends_with(" (from --set controller.type=walk)")) << own;
}

}  // namespace
}  // namespace cogmap::experiments
