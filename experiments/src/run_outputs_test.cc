#include "cogmap/experiments/run_outputs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <nlohmann/json.hpp>

#include "cogmap/experiments/number_format.h"
#include "cogmap/experiments/run_metrics.h"

namespace cogmap::experiments {
namespace {

TEST(NumberFormat, AppendedTextIsTheFormattedText) {
  const double cases[] = {0.0,
                          -0.0,
                          0.1,
                          -2.5,
                          1e-7,
                          1.0 / 3.0,
                          std::numeric_limits<double>::denorm_min(),
                          std::numeric_limits<double>::max(),
                          std::numeric_limits<double>::infinity(),
                          -std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::quiet_NaN()};
  const char* expected[] = {"0",      "-0",
                            "0.1",    "-2.5",
                            "1e-07",  "0.3333333333333333",
                            "5e-324", "1.7976931348623157e+308",
                            "inf",    "-inf",
                            "nan"};
  for (std::size_t i = 0; i < std::size(cases); ++i) {
    std::string out = "x=";
    append_double(out, cases[i]);
    EXPECT_EQ(out, std::string("x=") + expected[i]);
    EXPECT_EQ(format_double(cases[i]), expected[i]);
  }
}

TEST(RunOutputs, TrajectoryCsvColumnsAndEmptyTruth) {
  std::vector<TrajectoryRow> rows(2);
  rows[0] = {0.1, mapper::Pose2{1.0, 2.0, 0.5}, {1.0, 2.0, 0.5}, {1.0, 2.0, 0.5}};
  rows[1] = {0.2, std::nullopt, {1.25, 2.0, -0.1}, {1.2, 2.0, 0.0}};
  EXPECT_EQ(trajectory_csv(rows),
            "t_s,true_x_m,true_y_m,true_theta_rad,odom_x_m,odom_y_m,odom_theta_rad,est_x_m,"
            "est_y_m,est_theta_rad\n"
            "0.1,1,2,0.5,1,2,0.5,1,2,0.5\n"
            "0.2,,,,1.25,2,-0.1,1.2,2,0\n");
}

TEST(RunOutputs, TrajectoryCsvInChunksIsTheSameText) {
  std::vector<TrajectoryRow> rows;
  for (int i = 0; i < 5; ++i) {
    rows.push_back({0.1 * (i + 1), std::nullopt, {1.0 * i, 0.0, 0.0}, {1.0 * i, 0.5, 0.0}});
  }
  std::vector<std::string> pieces;
  trajectory_csv_chunks(
      rows, [&](std::string_view p) { pieces.emplace_back(p); }, 2);
  ASSERT_EQ(pieces.size(), 3u);  // rows 1-2 (with the header), 3-4, 5
  EXPECT_EQ(pieces[2], "0.5,,,,4,0,0,4,0.5,0\n");
  EXPECT_EQ(pieces[0] + pieces[1] + pieces[2], trajectory_csv(rows));
  EXPECT_EQ(std::count(pieces[1].begin(), pieces[1].end(), '\n'), 2);
}

TEST(RunOutputs, NavTraceCsvColumnsEmptyFieldsAndChunks) {
  std::vector<NavTraceRow> rows(3);
  rows[0] = {0.1, "drive", 0,   0.5, 0.25, true, 1.5, false, mapper::Point2(0.0, 0.0),
             0.0, 0.0,     0.4, 0.1};
  rows[1] = {0.2,  "door_cross", 3,   -1.0, -1.0, true, std::numeric_limits<double>::infinity(),
             true, {2.5, -1.0},  1.5, 0.75, 0.3,  0.0};
  rows[2] = {0.3, "blocked", 3,   2.0, 0.0, false, 0.2, false, mapper::Point2(0.0, 0.0),
             0.0, 0.0,       0.0, -1.0};
  std::vector<std::string> pieces;
  nav_trace_csv_chunks(
      rows, [&](std::string_view p) { pieces.emplace_back(p); }, 2);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0] + pieces[1],
            "t_s,mode,waypoint_index,target_rad,direction_rad,has_direction,front_clearance_m,"
            "door_active,door_x_m,door_y_m,door_normal_rad,door_width_m,v_mps,w_radps\n"
            "0.1,drive,0,0.5,0.25,1,1.5,0,,,,,0.4,0.1\n"
            "0.2,door_cross,3,-1,-1,1,,1,2.5,-1,1.5,0.75,0.3,0\n"
            "0.3,blocked,3,2,,0,0.2,0,,,,,0,-1\n");
  EXPECT_EQ(pieces[1], "0.3,blocked,3,2,,0,0.2,0,,,,,0,-1\n");
}

TEST(RunOutputs, SegmentsCsv) {
  const std::vector<mapper::Mapper::MapSegment> s{{3, {{0.5, -1.0}, {2.0, 0.1}}}};
  EXPECT_EQ(segments_csv(s), "asr_id,x1_m,y1_m,x2_m,y2_m\n3,0.5,-1,2,0.1\n");
}

TEST(RunOutputs, SvgFlipsYAndHasAScaleBar) {
  SvgMap m;
  m.map = {{0, {{0.0, 0.0}, {4.0, 0.0}}}, {0, {{0.0, 0.0}, {0.0, 3.0}}}};
  m.truth = {{{0.0, 0.0}, {4.0, 0.0}}};
  const std::string svg = map_svg(m);
  // Bounds x 0..4, y 0..3 grown by 0.5 (and 0.8 below for the bar): the world origin maps to
  // (0.5, 3.5) and (0, 3) to (0.5, 0.5) — north is up.
  EXPECT_NE(svg.find("<line x1=\"0.5\" y1=\"3.5\" x2=\"0.5\" y2=\"0.5\"/>"), std::string::npos)
      << svg;
  EXPECT_NE(svg.find("id=\"truth\""), std::string::npos);
  EXPECT_NE(svg.find(">1 m</text>"), std::string::npos);
}

// A stray non-UTF-8 byte in a name (load_experiment refuses them; code that sets a name itself
// might not) must not throw after a whole run: it becomes U+FFFD.
TEST(RunMetrics, JsonOfANameThatIsNotUtf8IsWritten) {
  RunMetrics m;
  m.name = "a\xff\xfe";
  const std::string text = metrics_json_text(m);
  EXPECT_NE(text.find("\"name\": \"a\xef\xbf\xbd\xef\xbf\xbd\""), std::string::npos) << text;
}

TEST(RunMetrics, JsonHasTheRequiredKeysAndOmitsTruthMetricsWithoutTruth) {
  RunMetrics m;
  m.asr_count = 2;
  m.memory.polyline_bytes = 80;
  m.memory.grid_bytes = 1000;
  m.memory.compression_ratio = 0.04;
  m.sim_time_s = 10.0;
  m.wall_time_s = 0.5;
  m.max_room_travel_m = 4.5;
  const std::string without = metrics_json_text(m);
  EXPECT_NE(without.find("\"max_room_travel_m\": 4.5"), std::string::npos) << without;
  EXPECT_EQ(without.find("wall_error_median_m"), std::string::npos);
  EXPECT_EQ(without.find("\"localization\": {"), std::string::npos);
  EXPECT_NE(without.find("\"real_time_factor\": 20.0"), std::string::npos) << without;
  m.map = MapAccuracy{};
  m.map->wall_error_median_m = 0.04;
  m.localization =
      LocalizationAccuracy{6.1, 0.7, 1.9, 0.21, 10, std::nullopt, {}, {1.01, 2.5, 0.3}};
  const std::string with = metrics_json_text(m);
  EXPECT_NE(with.find("\"wall_error_median_m\": 0.04"), std::string::npos);
  EXPECT_NE(with.find("\"wall_coverage\": null"), std::string::npos);
  EXPECT_NE(with.find("\"heading_error_final_deg\": {\n      \"odometry\": 6.1,\n      "
                      "\"corrected\": 0.7,\n      \"closed\": null\n    }"),
            std::string::npos)
      << with;
  m.localization->heading_error_final_closed_deg = 0.5;
  EXPECT_NE(metrics_json_text(m).find("\"corrected\": 0.7,\n      \"closed\": 0.5\n    }"),
            std::string::npos);
  const auto j = nlohmann::json::parse(with);
  const auto& similarity = j["localization"]["similarity"];
  EXPECT_DOUBLE_EQ(similarity["odometry"]["scale"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(similarity["corrected"]["scale"].get<double>(), 1.01);
  EXPECT_DOUBLE_EQ(similarity["corrected"]["rotation_deg"].get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(similarity["corrected"]["residual_rmse_m"].get<double>(), 0.3);
}

TEST(RunMetrics, PerRoomMappingTimeIsInMillisecondsUnderTiming) {
  RunMetrics m;
  m.room_cpu_s = {0.002, 0.0005};
  const auto j = nlohmann::json::parse(metrics_json_text(m));
  ASSERT_EQ(j["timing"]["room_cpu_ms"].size(), 2u);
  EXPECT_DOUBLE_EQ(j["timing"]["room_cpu_ms"][0].get<double>(), 2.0);
  EXPECT_DOUBLE_EQ(j["timing"]["room_cpu_ms"][1].get<double>(), 0.5);
  m.room_wall_s = {0.25, 0.0125};
  const auto walls = nlohmann::json::parse(metrics_json_text(m))["timing"]["room_wall_ms"];
  ASSERT_EQ(walls.size(), 2u);
  EXPECT_DOUBLE_EQ(walls[0].get<double>(), 250.0);
  EXPECT_DOUBLE_EQ(walls[1].get<double>(), 12.5);
  m.room_cpu_s.clear();
  m.room_wall_s.clear();
  EXPECT_TRUE(nlohmann::json::parse(metrics_json_text(m))["timing"]["room_cpu_ms"].empty());
  EXPECT_TRUE(nlohmann::json::parse(metrics_json_text(m))["timing"]["room_wall_ms"].empty());
}

TEST(RunMetrics, TheScanMatchBlockIsWrittenOnlyWhenMatching) {
  RunMetrics m;
  EXPECT_FALSE(nlohmann::json::parse(metrics_json_text(m)).contains("scan_match"));
  m.scan_match = RunMetrics::ScanMatch{310, 204, 96.5, 4.25};
  const auto j = nlohmann::json::parse(metrics_json_text(m))["scan_match"];
  EXPECT_EQ(j["matches"].get<int>(), 310);
  EXPECT_EQ(j["measured"].get<int>(), 204);
  EXPECT_DOUBLE_EQ(j["rotation_total_deg"].get<double>(), 96.5);
  EXPECT_DOUBLE_EQ(j["shift_total_m"].get<double>(), 4.25);
  // From the mapper's figures: none when off, the rotations in degrees when on.
  mapper::MapperOptions options;
  mapper::MapperStats stats;
  stats.scan_matches = 12;
  stats.scan_matches_measured = 9;
  stats.scan_match_rotation_abs_rad = std::numbers::pi / 36.0;
  stats.scan_match_shift_abs_m = 0.3;
  EXPECT_FALSE(scan_match_metrics(options, stats).has_value());
  options.scan_match.enabled = true;
  const auto block = scan_match_metrics(options, stats);
  ASSERT_TRUE(block.has_value());
  EXPECT_EQ(block->matches, 12u);
  EXPECT_EQ(block->measured, 9u);
  EXPECT_NEAR(block->rotation_total_deg, 5.0, 1e-12);
  EXPECT_DOUBLE_EQ(block->shift_total_m, 0.3);
}

TEST(RunMetrics, EachRoomSaysWhatEmMeasuredInDegrees) {
  mapper::Localization fix;
  fix.measured_rotation_rad = -0.1;
  fix.measurement_sigma_rad = 0.02;
  fix.prior_sigma_rad = 0.04;
  fix.gain = 0.8;
  fix.applied = true;
  fix.longest_wall_m = 2.75;
  const RoomLocalizationReport r = room_localization_report(fix);
  EXPECT_EQ(r.longest_wall_m, 2.75);
  EXPECT_NEAR(r.measured_rotation_deg, -0.1 * 180.0 / M_PI, 1e-12);
  EXPECT_NEAR(r.measurement_sd_deg, 0.02 * 180.0 / M_PI, 1e-12);
  ASSERT_TRUE(r.prior_sd_deg.has_value());
  EXPECT_NEAR(*r.prior_sd_deg, 0.04 * 180.0 / M_PI, 1e-12);
  // No prior (the thesis's EM): none reported, not an infinity JSON cannot hold.
  fix.prior_sigma_rad = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(room_localization_report(fix).prior_sd_deg.has_value());

  RunMetrics m;
  m.rooms.resize(2);
  m.rooms[1].localization = r;
  const auto j = nlohmann::json::parse(metrics_json_text(m));
  EXPECT_TRUE(j["rooms"][0]["localization"].is_null());  // the first room: nothing to match
  const auto& l = j["rooms"][1]["localization"];
  EXPECT_DOUBLE_EQ(l["measured_rotation_deg"].get<double>(), r.measured_rotation_deg);
  EXPECT_DOUBLE_EQ(l["measurement_sd_deg"].get<double>(), r.measurement_sd_deg);
  EXPECT_DOUBLE_EQ(l["longest_wall_m"].get<double>(), 2.75);
  EXPECT_DOUBLE_EQ(l["prior_sd_deg"].get<double>(), *r.prior_sd_deg);
  EXPECT_DOUBLE_EQ(l["gain"].get<double>(), 0.8);
  EXPECT_TRUE(l["applied"].get<bool>());
}

}  // namespace
}  // namespace cogmap::experiments
