#include "cogmap/experiments/experiment_config.h"

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>

#include "experiment_config_test_support.h"

namespace cogmap::experiments {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using test::write_temp;

const char* const kGood = R"(name: two_rooms_route
world: ../worlds/two_rooms.yaml
seed: 7
duration_s: 600
robot:
  source: sim
  model: p2at
controller:
  type: route
  speed_mps: 0.4
  waypoints: [[2.5, 3.0], [7.5, 3.0]]
mapper:
  grid: bayes
  cell_scale_mm: 55
  occupied_threshold: 8
  vertex_tolerance_cells: 3
  polyline_gap_cells: 5
  asr_boundary: distance
  asr_distance_m: 4.0
  localization: none
  door_close_side_m: 0.7
output:
  figures: false
)";

TEST(ExperimentConfig, ParsesEveryKey) {
  const fs::path p = write_temp("good.yaml", kGood);
  const Experiment e = load_experiment(p);
  EXPECT_EQ(e.name, "two_rooms_route");
  EXPECT_EQ(e.world, (p.parent_path() / "../worlds/two_rooms.yaml").lexically_normal());
  EXPECT_EQ(e.seed, 7u);
  EXPECT_DOUBLE_EQ(e.duration_s, 600.0);
  EXPECT_EQ(e.robot_source, RobotSource::kSim);
  ASSERT_TRUE(e.robot.has_value());
  EXPECT_EQ(e.controller.type, ControllerKind::kRoute);
  EXPECT_DOUBLE_EQ(e.controller.speed_mps, 0.4);
  ASSERT_EQ(e.controller.waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(e.controller.waypoints[1].x(), 7.5);
  EXPECT_EQ(e.mapper.grid, mapper::GridKind::kBayes);
  EXPECT_DOUBLE_EQ(e.mapper.grid_options.cell_scale_mm, 55.0);
  EXPECT_DOUBLE_EQ(e.mapper.builder.occupied_threshold, 8.0);
  EXPECT_DOUBLE_EQ(e.mapper.builder.vertex_tolerance_cells, 3.0);
  EXPECT_DOUBLE_EQ(e.mapper.builder.polyline_gap_cells, 5.0);
  EXPECT_EQ(e.mapper.boundary, mapper::BoundaryKind::kDistance);
  EXPECT_DOUBLE_EQ(e.mapper.distance.asr_distance_m, 4.0);
  EXPECT_EQ(e.mapper.localization, mapper::LocalizationKind::kNone);
  EXPECT_DOUBLE_EQ(e.mapper.doorway.close_side_m, 0.7);
  EXPECT_FALSE(e.figures);
}

TEST(ExperimentConfig, DefaultsAreTheThesisValues) {
  const fs::path p = write_temp("minimal.yaml", "name: m\nworld: w.yaml\n");
  const Experiment e = load_experiment(p);
  EXPECT_EQ(e.mapper.grid, mapper::GridKind::kMhimm);
  EXPECT_DOUBLE_EQ(e.mapper.grid_options.cell_scale_mm, 100.0);    // ℘, Table 4.1
  EXPECT_DOUBLE_EQ(e.mapper.builder.occupied_threshold, 7.0);      // ε
  EXPECT_DOUBLE_EQ(e.mapper.builder.vertex_tolerance_cells, 2.0);  // τ
  EXPECT_DOUBLE_EQ(e.mapper.builder.polyline_gap_cells, 4.0);      // γ
  EXPECT_EQ(e.controller.type, ControllerKind::kNone);
  EXPECT_TRUE(e.figures);
}

TEST(ExperimentConfig, AnExplorerCutsLongRoomsUnlessTheExperimentSaysOtherwise) {
  const fs::path p = write_temp("explore_cut.yaml", R"(name: explore
world: ../worlds/two_rooms.yaml
duration_s: 600
controller:
  type: explore
mapper:
  grid: mhimm
)");
  Experiment e = load_experiment(p);
  EXPECT_EQ(e.mapper.max_room_travel_m, kExploreMaxRoomTravelM);
  EXPECT_EQ(kExploreMaxRoomTravelM, 4.5);  // the thesis's hallway cut, §3.1.2
  EXPECT_EQ(load_experiment(p, {"mapper.max_room_travel_m=0"}).mapper.max_room_travel_m, 0.0);
  // cogmap drive --controller changes the type after loading: the default follows it.
  e.controller.type = ControllerKind::kRoute;
  apply_controller_defaults(e);
  EXPECT_EQ(e.mapper.max_room_travel_m, 0.0);
  Experiment given =
      load_experiment(write_temp("route_cut.yaml", kGood), {"mapper.max_room_travel_m=6"});
  given.controller.type = ControllerKind::kExplore;
  apply_controller_defaults(given);
  EXPECT_EQ(given.mapper.max_room_travel_m, 6.0);
}

TEST(ExperimentConfig, AnExplorersMapIsDrawnWithTheMatcherItDoesNotSteerBy) {
  const fs::path p = write_temp("explore_match.yaml", R"(name: explore
world: ../worlds/two_rooms.yaml
controller:
  type: explore
)");
  Experiment e = load_experiment(p);
  EXPECT_TRUE(e.mapper.scan_match.enabled);
  EXPECT_FALSE(e.mapper.scan_match.shift);  // turning only
  EXPECT_TRUE(e.controller.steer_by_plain_estimate);
  EXPECT_FALSE(e.controller.steer_by_truth);
  // cogmap drive --controller route: the library's defaults and the map's own estimate.
  e.controller.type = ControllerKind::kRoute;
  apply_controller_defaults(e);
  EXPECT_FALSE(e.mapper.scan_match.enabled);
  EXPECT_TRUE(e.mapper.scan_match.shift);
  EXPECT_FALSE(e.controller.steer_by_plain_estimate);
  // What the experiment gives is kept, each key on its own.
  const Experiment pose = load_experiment(p, {"controller.pose=estimate"});
  EXPECT_FALSE(pose.controller.steer_by_plain_estimate);
  EXPECT_TRUE(pose.mapper.scan_match.enabled);
  const Experiment truth = load_experiment(p, {"controller.pose=truth"});
  EXPECT_TRUE(truth.controller.steer_by_truth);
  EXPECT_FALSE(truth.controller.steer_by_plain_estimate);
  const Experiment off = load_experiment(p, {"mapper.scan_match=false"});
  EXPECT_FALSE(off.mapper.scan_match.enabled);
  EXPECT_TRUE(off.controller.steer_by_plain_estimate);
  const Experiment shift = load_experiment(p, {"mapper.scan_match_shift=true"});
  EXPECT_TRUE(shift.mapper.scan_match.shift);
  // A route gets none of it unless asked.
  const Experiment route = load_experiment(write_temp("route_match.yaml", kGood));
  EXPECT_NE(route.controller.type, ControllerKind::kExplore);
  EXPECT_FALSE(route.mapper.scan_match.enabled);
  EXPECT_FALSE(route.controller.steer_by_plain_estimate);
  Experiment route_given = load_experiment(write_temp("route_match2.yaml", kGood),
                                           {"mapper.scan_match=true", "controller.pose=estimate"});
  route_given.controller.type = ControllerKind::kExplore;
  apply_controller_defaults(route_given);
  EXPECT_TRUE(route_given.mapper.scan_match.enabled);
  EXPECT_FALSE(route_given.mapper.scan_match.shift);             // not given: the explorer's
  EXPECT_FALSE(route_given.controller.steer_by_plain_estimate);  // given: kept
}

TEST(ExperimentConfig, OverridesAndSeedApplyBeforeValidation) {
  const fs::path p = write_temp("good2.yaml", kGood);
  const Experiment e = load_experiment(
      p, {"mapper.cell_scale_mm=85", "mapper.grid=himm", "output.figures=true"}, std::uint64_t{42});
  EXPECT_DOUBLE_EQ(e.mapper.grid_options.cell_scale_mm, 85.0);
  EXPECT_EQ(e.mapper.grid, mapper::GridKind::kHimm);
  EXPECT_TRUE(e.figures);
  EXPECT_FALSE(e.nav_trace);  // off unless asked for
  EXPECT_EQ(e.seed, 42u);
  EXPECT_NE(e.resolved_yaml.find("cell_scale_mm: 85"), std::string::npos);
  EXPECT_TRUE(load_experiment(p, {"output.nav_trace=true"}).nav_trace);
  EXPECT_NE(error_of(p, {"output.nav_trace=sometimes"}), "no error");
  EXPECT_FALSE(e.explore_map);  // the explorer's map: off unless asked for
  EXPECT_TRUE(load_experiment(p, {"output.explore_map=true"}).explore_map);
  EXPECT_NE(error_of(p, {"output.explore_map=7"}), "no error");
}

TEST(ExperimentConfig, DoorSearchIsTheControllersDefaultUnlessSet) {
  const fs::path p = write_temp("good_door_search.yaml", kGood);
  EXPECT_FALSE(load_experiment(p, {}).controller.door_search.has_value());
  EXPECT_EQ(load_experiment(p, {"controller.door_search=false"}).controller.door_search,
            std::optional<bool>(false));
  EXPECT_EQ(load_experiment(p, {"controller.door_search=true"}).controller.door_search,
            std::optional<bool>(true));
  EXPECT_NE(error_of(p, {"controller.door_search=sometimes"}), "no error");
}

TEST(ExperimentConfig, GrazingWallsAreOffUnlessAskedFor) {
  const fs::path p = write_temp("good_grazing_walls.yaml", kGood);
  EXPECT_FALSE(load_experiment(p, {}).controller.grazing_walls);
  EXPECT_TRUE(load_experiment(p, {"controller.grazing_walls=true"}).controller.grazing_walls);
  EXPECT_NE(error_of(p, {"controller.grazing_walls=7"}), "no error");
}

// A route experiment refuses an explore-only controller key, naming it as such.
void expect_only_for_explore(const std::string& file_name, const std::string& setting) {
  const fs::path route = write_temp(file_name, kGood);
  const std::string error = error_of(route, {setting});
  EXPECT_NE(error.find("only used by explore"), std::string::npos) << error;
}

TEST(ExperimentConfig, PlanOverTrailIsOnForExploreAndOnlyThere) {
  const fs::path x =
      write_temp("xtrail.yaml", "name: r\nworld: w.yaml\ncontroller: {type: explore}\n");
  EXPECT_TRUE(load_experiment(x, {}).controller.plan_over_trail);
  EXPECT_FALSE(load_experiment(x, {"controller.plan_over_trail=false"}).controller.plan_over_trail);
  EXPECT_NE(error_of(x, {"controller.plan_over_trail=maybe"}), "no error");
  expect_only_for_explore("xtrail_route.yaml", "controller.plan_over_trail=false");
}

TEST(ExperimentConfig, ProgressAlongThePathIsOffByDefaultAndForExploreOnly) {
  const fs::path x =
      write_temp("xalong.yaml", "name: r\nworld: w.yaml\ncontroller: {type: explore}\n");
  EXPECT_FALSE(load_experiment(x, {}).controller.progress_along_path);
  EXPECT_TRUE(
      load_experiment(x, {"controller.progress_along_path=true"}).controller.progress_along_path);
  EXPECT_NE(error_of(x, {"controller.progress_along_path=2"}), "no error");
  expect_only_for_explore("xalong_route.yaml", "controller.progress_along_path=true");
}

TEST(ExperimentConfig, BlockedPathSecondsAreForExploreWithinTheirRange) {
  const fs::path x =
      write_temp("xblocked.yaml", "name: r\nworld: w.yaml\ncontroller: {type: explore}\n");
  EXPECT_EQ(load_experiment(x, {}).controller.blocked_path_s, 10.0);
  EXPECT_EQ(load_experiment(x, {"controller.blocked_path_s=0"}).controller.blocked_path_s, 0.0);
  EXPECT_EQ(load_experiment(x, {"controller.blocked_path_s=2.5"}).controller.blocked_path_s, 2.5);
  EXPECT_NE(error_of(x, {"controller.blocked_path_s=-1"}), "no error");
  EXPECT_NE(error_of(x, {"controller.blocked_path_s=3601"}), "no error");
  EXPECT_NE(error_of(x, {"controller.blocked_path_s=.nan"}), "no error");
  expect_only_for_explore("xblocked_route.yaml", "controller.blocked_path_s=5");
}

TEST(ExperimentConfig, ArcGuardSecondsAreOptionalWithinTheirRange) {
  const fs::path x =
      write_temp("xarc.yaml", "name: r\nworld: w.yaml\ncontroller: {type: explore}\n");
  EXPECT_FALSE(load_experiment(x, {}).controller.arc_guard_s.has_value());
  EXPECT_EQ(load_experiment(x, {"controller.arc_guard_s=0"}).controller.arc_guard_s, 0.0);
  EXPECT_EQ(load_experiment(x, {"controller.arc_guard_s=1.5"}).controller.arc_guard_s, 1.5);
  EXPECT_NE(error_of(x, {"controller.arc_guard_s=-0.1"}), "no error");
  EXPECT_NE(error_of(x, {"controller.arc_guard_s=5.5"}), "no error");
  EXPECT_NE(error_of(x, {"controller.arc_guard_s=.inf"}), "no error");
  // Routes take it too.
  const fs::path route = write_temp("xarc_route.yaml", kGood);
  EXPECT_EQ(load_experiment(route, {"controller.arc_guard_s=0.5"}).controller.arc_guard_s, 0.5);
}

TEST(ExperimentConfig, UnknownKeyNamesFileLineAndKey) {
  std::string text = kGood;
  text.replace(text.find("  cell_scale_mm"), 15, "  cell_scale_nm");
  const fs::path p = write_temp("typo.yaml", text);
  EXPECT_EQ(error_of(p).rfind(p.string() + ":14: mapper.cell_scale_nm: unknown key", 0), 0u)
      << error_of(p);
}

TEST(ExperimentConfig, WrongTypeNamesFileLineAndKey) {
  std::string text = kGood;
  text.replace(text.find("cell_scale_mm: 55"), 17, "cell_scale_mm: big");
  const fs::path p = write_temp("type.yaml", text);
  EXPECT_EQ(error_of(p),
            p.string() + ":14: mapper.cell_scale_mm: expected a finite number, got 'big'");
}

TEST(ExperimentConfig, OutOfRangeAndBadEnumAreErrors) {
  std::string text = kGood;
  text.replace(text.find("grid: bayes"), 11, "grid: sonar");
  const fs::path p = write_temp("enum.yaml", text);
  EXPECT_NE(error_of(p).find(":13: mapper.grid: unknown grid 'sonar'"), std::string::npos)
      << error_of(p);
  const fs::path p2 = write_temp("range.yaml", kGood);
  EXPECT_NE(error_of(p2, {"mapper.cell_scale_mm=0"}).find("mapper.cell_scale_mm: must be in"),
            std::string::npos);
}

TEST(ExperimentConfig, OverrideOfUnknownKeyIsAnError) {
  const fs::path p = write_temp("good3.yaml", kGood);
  const std::string err = error_of(p, {"mapper.cel_scale_mm=55"});
  EXPECT_EQ(err.rfind(p.string() + ":13: mapper.cel_scale_mm: unknown key", 0), 0u) << err;
  EXPECT_NE(err.find("(from --set mapper.cel_scale_mm=55)"), std::string::npos) << err;
  EXPECT_NE(error_of(p, {"nonsense"}).find("expected key=value"), std::string::npos);
}

TEST(ExperimentConfig, RouteNeedsWaypoints) {
  const fs::path p =
      write_temp("route.yaml", "name: r\nworld: w.yaml\ncontroller: {type: route}\n");
  EXPECT_NE(error_of(p).find(":3: controller: a route controller needs"), std::string::npos)
      << error_of(p);
}

TEST(ExperimentConfig, ControllerPoseSource) {
  const fs::path p =
      write_temp("pose.yaml", "name: r\nworld: w.yaml\ncontroller: {type: explore, pose: truth}\n");
  EXPECT_TRUE(load_experiment(p).controller.steer_by_truth);
  const fs::path est = write_temp("est.yaml", "name: r\nworld: w.yaml\ncontroller: {type: none}\n");
  EXPECT_FALSE(load_experiment(est).controller.steer_by_truth);
  EXPECT_FALSE(load_experiment(est).controller.steer_by_plain_estimate);
  const Experiment plain = load_experiment(est, {"controller.pose=plain_estimate"});
  EXPECT_TRUE(plain.controller.steer_by_plain_estimate);
  EXPECT_FALSE(plain.controller.steer_by_truth);
  const fs::path bad = write_temp(
      "badpose.yaml", "name: r\nworld: w.yaml\ncontroller:\n  type: explore\n  pose: gps\n");
  EXPECT_NE(error_of(bad).find(":5: controller.pose: unknown pose source 'gps' (expected "
                               "estimate, plain_estimate or truth)"),
            std::string::npos)
      << error_of(bad);
}

TEST(ExperimentConfig, ExploreStrategyAndBudgets) {
  const fs::path def =
      write_temp("xdef.yaml", "name: r\nworld: w.yaml\ncontroller: {type: explore}\n");
  const Experiment d = load_experiment(def);
  EXPECT_EQ(d.controller.explore_strategy, mapper::nav::ExploreStrategy::kFrontier);
  EXPECT_EQ(d.controller.explore_time_budget_s, 0.0);
  EXPECT_EQ(d.controller.explore_distance_budget_m, 0.0);
  const fs::path p =
      write_temp("xedge.yaml",
                 "name: r\nworld: w.yaml\ncontroller:\n  type: explore\n"
                 "  strategy: edge\n  time_budget_s: 300\n  distance_budget_m: 80\n");
  const Experiment e = load_experiment(p);
  EXPECT_EQ(e.controller.explore_strategy, mapper::nav::ExploreStrategy::kEdge);
  EXPECT_EQ(e.controller.explore_time_budget_s, 300.0);
  EXPECT_EQ(e.controller.explore_distance_budget_m, 80.0);
  EXPECT_EQ(load_experiment(p, {"controller.strategy=heading"}).controller.explore_strategy,
            mapper::nav::ExploreStrategy::kHeading);
  const fs::path bad = write_temp(
      "xbad.yaml", "name: r\nworld: w.yaml\ncontroller:\n  type: explore\n  strategy: spiral\n");
  EXPECT_NE(error_of(bad).find(":5: controller.strategy: unknown explore strategy 'spiral'"),
            std::string::npos)
      << error_of(bad);
  const fs::path route = write_temp("xroute.yaml",
                                    "name: r\nworld: w.yaml\ncontroller:\n  type: route\n"
                                    "  waypoints: [[1, 1]]\n  time_budget_s: 10\n");
  EXPECT_NE(error_of(route).find(":6: controller.time_budget_s: time_budget_s is only used by "
                                 "explore"),
            std::string::npos)
      << error_of(route);
  const fs::path negative =
      write_temp("xneg.yaml",
                 "name: r\nworld: w.yaml\ncontroller:\n  type: explore\n  distance_budget_m: -1\n");
  EXPECT_NE(error_of(negative).find(":5: controller.distance_budget_m: must be in [0,"),
            std::string::npos)
      << error_of(negative);
}

TEST(ExperimentConfig, RecordsRealRobotSources) {
  const fs::path p = write_temp("p2os.yaml", "name: r\nworld: w.yaml\nrobot: {source: p2os}\n");
  EXPECT_EQ(load_experiment(p).robot_source, RobotSource::kP2os);
  const fs::path bad = write_temp("src.yaml", "name: r\nworld: w.yaml\nrobot: {source: wifi}\n");
  EXPECT_NE(error_of(bad).find("robot.source: unknown robot source 'wifi'"), std::string::npos);
}

// Waypoints and the start share the world's coordinate bound (sim::kMaxCoordinateM): a
// waypoint at 1e155 m overflowed the distance to it and counted as reached at once, and a
// start at 1e9 m ran although a world file refuses it.
TEST(ExperimentConfig, WaypointsAndStartKeepTheWorldsCoordinateBound) {
  const fs::path far = write_temp("far_wp.yaml",
                                  "name: r\nworld: w.yaml\ncontroller:\n  type: route\n"
                                  "  waypoints: [[1, 2],\n              [1e155, 3]]\n");
  EXPECT_EQ(error_of(far), far.string() +
                               ":6: controller.waypoints[1][0]: coordinate 1e+155 m is beyond "
                               "the +/-1000 m the simulator supports (single-precision physics)");
  const fs::path p = write_temp("good_wp.yaml", kGood);
  // From --set the value has no line: the error takes the overridden key's (line 11).
  const std::string set = error_of(p, {"controller.waypoints=[[2, -1000.5]]"});
  EXPECT_EQ(set.rfind(p.string() + ":11: controller.waypoints[0][1]: coordinate -1000.5 m", 0), 0u)
      << set;
  EXPECT_NE(set.find("(from --set controller.waypoints=[[2, -1000.5]])"), std::string::npos) << set;
  const Experiment edge = load_experiment(p, {"controller.waypoints=[[1000, -1000]]"});
  EXPECT_EQ(edge.controller.waypoints[0].x(), 1000.0);
  EXPECT_EQ(edge.controller.waypoints[0].y(), -1000.0);

  const fs::path start =
      write_temp("far_start.yaml", "name: r\nworld: w.yaml\nstart:\n  x_m: 1e9\n  y_m: 0\n");
  EXPECT_EQ(error_of(start).rfind(start.string() + ":4: start.x_m: coordinate 1e+09 m is beyond "
                                                   "the +/-1000 m",
                                  0),
            0u)
      << error_of(start);
  const fs::path ok = write_temp("start.yaml", "name: r\nworld: w.yaml\nstart: {x_m: 1, y_m: 2}\n");
  EXPECT_NE(error_of(ok, {"start.y_m=-2e3"}).find(":3: start.y_m: coordinate -2000 m is beyond"),
            std::string::npos)
      << error_of(ok, {"start.y_m=-2e3"});
  EXPECT_DOUBLE_EQ(load_experiment(ok).start->y_m, 2.0);
}

// Names and descriptions reach metrics.json, which holds UTF-8 only: a name of bytes FF FE ran
// the whole simulation and then failed writing it. Refused at parse time, with the line.
TEST(ExperimentConfig, NamesAndDescriptionsMustBeUtf8) {
  const fs::path bad = write_temp("bad_name.yaml", "name: \"\xff\xfe\"\nworld: w.yaml\n");
  EXPECT_EQ(error_of(bad), bad.string() +
                               ":1: name: not valid UTF-8 text (byte 0xff at offset 0); the run "
                               "writes it into metrics.json, which holds UTF-8 only");
  const fs::path desc =
      write_temp("bad_desc.yaml", "name: r\ndescription: caf\xc3 au lait\nworld: w.yaml\n");
  EXPECT_NE(error_of(desc).find(":2: description: not valid UTF-8 text (byte 0xc3 at offset 3)"),
            std::string::npos)
      << error_of(desc);
  const fs::path good = write_temp("utf8.yaml",
                                   "name: \"r\xc3\xa4ume \xe2\x9c\x93 \xf0\x9d\x84\x9e\"\n"
                                   "description: \"\xc3\xa9t\xc3\xa9\"\nworld: w.yaml\n");
  EXPECT_EQ(load_experiment(good).name, "r\xc3\xa4ume \xe2\x9c\x93 \xf0\x9d\x84\x9e");
  // Overlong "/", a UTF-16 surrogate, past U+10FFFF, a cut sequence; from --set too.
  for (const char* name : {"\xc0\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "ok\xe2\x9c"}) {
    const std::string e = error_of(good, {std::string("name=") + name});
    EXPECT_NE(e.find("name: not valid UTF-8 text"), std::string::npos) << e;
    EXPECT_NE(e.find("(from --set name="), std::string::npos) << e;
  }
  const std::string world = error_of(good, {"world=w\xff.yaml"});
  EXPECT_NE(world.find("world: not valid UTF-8 text (byte 0xff at offset 1)"), std::string::npos)
      << world;
  EXPECT_NE(world.find("(from --set world=w\\xff.yaml)"), std::string::npos) << world;
}

// YAML::Load keeps a text's first document: `--set 'duration_s=3\n---\nx: 1'` set 3 and dropped
// the rest. A value is one document, like a file.
TEST(ExperimentConfig, OverrideWithASecondDocumentIsRefused) {
  const fs::path p = write_temp("two_docs.yaml", kGood);
  const std::string e = error_of(p, {"duration_s=3\n---\nx: 1"});
  EXPECT_EQ(e, p.string() +
                   ":4: duration_s: value holds a second YAML document (or text after the end "
                   "of the first) at its line 2: a --set value is exactly one YAML value (from "
                   "--set duration_s=3\\n---\\nx: 1)");
}

// An empty value is reported on its key's line: yaml-cpp marks it at the next key.
TEST(ExperimentConfig, EmptyValuesAreReportedOnTheirOwnLine) {
  const fs::path name = write_temp("no_name.yaml", "name:\nworld: w.yaml\nseed: 3\n");
  EXPECT_EQ(error_of(name), name.string() + ":1: name: must not be empty");
  const fs::path world = write_temp("no_world.yaml", "name: r\nworld:\n");
  EXPECT_EQ(error_of(world),
            world.string() + ":2: world: must not be empty (a world file, or 'none')");
  const fs::path null_world = write_temp("null_world.yaml", "name: r\nworld: ~\nseed: 3\n");
  EXPECT_EQ(error_of(null_world),
            null_world.string() + ":2: world: must not be empty (a world file, or 'none')");
  const fs::path desc = write_temp("no_desc.yaml", "name: r\ndescription:\nworld: w.yaml\n");
  EXPECT_EQ(error_of(desc),
            desc.string() + ":2: description: expected a string (or no key at all)");
  const fs::path quoted = write_temp("quoted.yaml", "name: \"\"\nworld: w.yaml\n");
  EXPECT_EQ(error_of(quoted), quoted.string() + ":1: name: must not be empty");
}

// An override that creates or changes a parent of the node an error is at still says so, with
// the line of the closest node the file wrote.
TEST(ExperimentConfig, OverrideErrorsAboveTheOverriddenKeyNameTheOverride) {
  const fs::path p = write_temp("parents.yaml", kGood);
  const std::string unknown = error_of(p, {"a.b=1"});
  EXPECT_EQ(unknown.rfind(p.string() + ":1: a: unknown key (allowed: name,", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("(from --set a.b=1)"), std::string::npos) << unknown;
  // `grid: bayes` (line 13) is no mapping to set a key in.
  EXPECT_EQ(
      error_of(p, {"mapper.grid.x=1"}),
      p.string() + ":13: mapper.grid.x: 'grid' is not a mapping (from --set mapper.grid.x=1)");
  // Without a `grid` key the override makes one, a mapping: the line is its block's.
  const fs::path no_grid =
      write_temp("no_grid.yaml", "name: m\nworld: w.yaml\nmapper:\n  cell_scale_mm: 100\n");
  EXPECT_EQ(error_of(no_grid, {"mapper.grid.x=1"}),
            no_grid.string() + ":4: mapper.grid: expected a string (from --set mapper.grid.x=1)");
  // An error inside the override's own value is still the override's.
  EXPECT_NE(error_of(p, {"mapper.cell_scale_mm=big"})
                .find(":14: mapper.cell_scale_mm: expected a finite number, got 'big' (from "
                      "--set mapper.cell_scale_mm=big)"),
            std::string::npos)
      << error_of(p, {"mapper.cell_scale_mm=big"});
  // A malformed override names no line: nothing in the file is wrong.
  EXPECT_EQ(error_of(p, {"nonsense"}),
            p.string() + ": nonsense: expected key=value (from --set nonsense)");
}

// Every boolean key takes YAML 1.2's booleans only, in the file, in the robot block and from
// --set (yaml-cpp took `figures: no`, `multipath: On` and `--set mapper.relax=off`), and a
// block scalar where a number is expected is named as one.
TEST(ExperimentConfig, BooleanKeysTakeTrueOrFalseOnly) {
  const std::string yaml11 = ": a YAML 1.1 boolean, which YAML 1.2 reads as a string (write ";
  const fs::path out =
      write_temp("figures_no.yaml", "name: b\nworld: w.yaml\noutput:\n  figures: no\n");
  EXPECT_EQ(error_of(out), out.string() + ":4: output.figures: expected true or false, got 'no'" +
                               yaml11 + "false)");
  const fs::path sonar =
      write_temp("multipath_on.yaml", "name: b\nworld: w.yaml\nrobot:\n  sonar: {multipath: On}\n");
  EXPECT_EQ(error_of(sonar), sonar.string() +
                                 ":4: robot.sonar.multipath: expected true or false, got 'On'" +
                                 yaml11 + "true)");
  const fs::path p = write_temp("good_bools.yaml", kGood);
  EXPECT_EQ(error_of(p, {"mapper.relax=off"}),
            p.string() + ":13: mapper.relax: expected true or false, got 'off'" + yaml11 +
                "false) (from --set mapper.relax=off)");
  EXPECT_EQ(error_of(p, {"controller.door_search=Y"}),
            p.string() + ":9: controller.door_search: expected true or false, got 'Y'" + yaml11 +
                "true) (from --set controller.door_search=Y)");
  EXPECT_EQ(error_of(p, {"output.nav_trace='true'"}),
            p.string() +
                ":23: output.nav_trace: expected true or false, got the quoted string 'true' "
                "(write it without quotes) (from --set output.nav_trace='true')");
  EXPECT_TRUE(load_experiment(p, {"mapper.translation_moves_estimate=TRUE"})
                  .mapper.translation.moves_estimate);
  const fs::path block = write_temp("block.yaml",
                                    "name: b\nworld: w.yaml\nduration_s: |\n  2\noutput:\n  "
                                    "figures: >-\n    false\n");
  EXPECT_EQ(error_of(block), block.string() +
                                 ":3: duration_s: expected a number, got a block scalar (| or "
                                 ">) holding '2', a string in YAML (write the plain 2 instead)");
}

TEST(ExperimentConfig, MissingFileIsAConfigError) {
  EXPECT_NE(error_of("/nonexistent/x.yaml").find("cannot open file"), std::string::npos);
}

}  // namespace
}  // namespace cogmap::experiments
