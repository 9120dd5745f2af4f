// The translation from revisited walls and the end-of-run relaxation of the rooms' positions on
// a corridor whose odometry slips sideways: each moves the map back onto the walls, the first
// room by room as they end (optionally the estimate too), the second all rooms at once.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "cogmap/mapper/mapper.h"
#include "facade/mapper_test_support.h"

namespace cogmap::mapper {
namespace {

using test::drive;
using test::median_wall_error;

/// A 22 m corridor cut into 4 m ASRs while the odometry slips sideways 2 cm per metre (no
/// heading drift): the walls of each cut lie 8 cm further off than the last cut's.
struct SlipRun {
  Pose2 final_estimate;
  double median_wall_error_m = 0.0;
  MapperStats stats;
  std::vector<std::pair<int, Pose2>> moves;  ///< what the end-of-run relaxation re-placed
};

SlipRun map_slipping_corridor(bool translation, bool moves_estimate, bool relax = false) {
  const RobotGeometry robot = p2at_geometry();
  const std::vector<Segment> walls{{{-1.0, -1.2}, {25.0, -1.2}}, {{-1.0, 1.2}, {25.0, 1.2}}};
  const auto frames = drive({{0.0, 0.0}, {22.0, 0.0}}, walls, robot, 0.0, 0.02);
  MapperOptions options;
  options.boundary = BoundaryKind::kDistance;
  options.distance.asr_distance_m = 4.0;
  options.translation.enabled = translation;
  options.translation.moves_estimate = moves_estimate;
  options.relaxation.enabled = relax;
  MemoryAsrStore store;
  Mapper mapper(options, robot, store, Pose2{});
  for (const SensorFrame& f : frames) mapper.process(f);
  SlipRun out;
  mapper.finish();
  out.final_estimate = mapper.pose_estimate();
  out.median_wall_error_m = median_wall_error(mapper.master_map(true), walls);
  out.stats = mapper.stats();
  out.moves = mapper.room_moves();
  for (const auto& [id, move] : out.moves) {
    // The store and the graph hold the rooms where the relaxation put them.
    const Asr stored = store.load(id);
    const std::optional<AsrNode> node = mapper.graph().node(id);
    EXPECT_TRUE(node && node->pose.x_m == stored.pose.x_m && node->pose.y_m == stored.pose.y_m);
  }
  return out;
}

TEST(Mapper, TranslationPlacesTheMapOnlyByDefault) {
  EXPECT_TRUE(MapperOptions{}.translation.enabled);
  EXPECT_FALSE(MapperOptions{}.translation.moves_estimate);
}

// Each cut is shifted back onto the corridor walls of the cuts before it: the map stays where
// the first cut put it, while the estimate the robot steers by keeps odometry's slip unless the
// shift is applied to it too.
TEST(Mapper, TranslationPutsEachCutBackOnTheWallsSeenBefore) {
  const SlipRun off = map_slipping_corridor(false, false);
  const SlipRun map_only = map_slipping_corridor(true, false);
  const SlipRun moved = map_slipping_corridor(true, true);
  EXPECT_EQ(off.stats.translations, 0u);
  EXPECT_EQ(map_only.stats.translations, 5u);  // 6 cuts, the first has no reference
  // Without it the 44 cm of slip spreads the walls (measured 0.211 m); with it the map stays
  // on them (0.051 m, the 10 cm cells' quantisation).
  EXPECT_GT(off.median_wall_error_m, 0.18);
  EXPECT_LT(map_only.median_wall_error_m, 0.065);
  // The map only: the estimate is odometry's, 0.44 m to the left at the end.
  EXPECT_NEAR(map_only.final_estimate.y_m, off.final_estimate.y_m, 1e-6);
  EXPECT_NEAR(off.final_estimate.y_m, 0.44, 0.01);
  // Moved too: the estimate is back near the corridor's centre line (measured 0.042 m: the
  // last cut's own 8 cm of slip, half of it before its middle).
  EXPECT_LT(std::abs(moved.final_estimate.y_m), 0.055);
  EXPECT_LT(moved.median_wall_error_m, 0.065);
}

TEST(Mapper, RelaxationIsOnByDefault) { EXPECT_TRUE(MapperOptions{}.relaxation.enabled); }

// The same slipping corridor without the online translation: at the end of the run the cuts are
// shifted together onto the walls they share, the estimate left as it was.
TEST(Mapper, RelaxationPullsTheCutsOntoTheWallsTheyShare) {
  const SlipRun off = map_slipping_corridor(false, false, false);
  const SlipRun relaxed = map_slipping_corridor(false, false, true);
  EXPECT_TRUE(off.moves.empty());
  EXPECT_EQ(off.stats.relaxed_rooms, 0u);
  // Cuts 1-5 move (room 0 stays where the start pose put it); across the corridor only.
  ASSERT_EQ(relaxed.moves.size(), 5u);
  EXPECT_EQ(relaxed.stats.relaxed_rooms, 5u);
  for (const auto& [id, move] : relaxed.moves) {
    EXPECT_GT(id, 0);
    EXPECT_LT(move.y_m, 0.0);  // back towards the right: the odometry slipped to the left
    EXPECT_NEAR(move.theta_rad, 0.0, 1e-12);
  }
  // 0.211 m without (measured) against 0.080 m: the pairs weigh against the drift the chain
  // allows between 4 m cuts (0.064 m), so each cut keeps part of its slip.
  EXPECT_GT(off.median_wall_error_m, 0.18);
  EXPECT_LT(relaxed.median_wall_error_m, 0.10);
  EXPECT_EQ(relaxed.final_estimate.y_m, off.final_estimate.y_m);
  EXPECT_GT(relaxed.stats.relaxation_pairs, 5u);
}

}  // namespace
}  // namespace cogmap::mapper
