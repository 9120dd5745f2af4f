#include <gtest/gtest.h>

#include "yaml/config_error_test_support.h"

#include <functional>
#include <random>
#include <string>

#include "cogmap/sim/sonar_model.h"
#include "sonar_test_support.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using mapper::Pose2;

SonarScene box_room() {
  return {{{{-3, -2}, {3, -2}}, {{3, -2}, {3, 2}}, {{3, 2}, {-3, 2}}, {{-3, 2}, {-3, -2}}}, {}};
}

// The robot turns slowly in place, so every firing sees a different pose.
Pose2 turning(double t_s) { return {0.2, 0.1, 0.3 * t_s}; }

TEST(SonarSchedule, OneSecondFiresRoundRobinEvery40Ms) {
  SonarModel model(SonarModelOptions{}, mapper::p2at_geometry(), 1);
  std::vector<mapper::SonarReading> all;
  for (int c = 0; c < 10; ++c) {
    const double t0 = 0.1 * c, t1 = 0.1 * (c + 1);
    const auto got = model.cycle(box_room(), t0, t1, turning);
    for (const auto& r : got) {
      EXPECT_GT(r.time_s, t0);
      EXPECT_LE(r.time_s, t1);
    }
    all.insert(all.end(), got.begin(), got.end());
  }
  // 1 s / 40 ms = 25 firings: 25 / 16 = 1.5625 per transducer, so 0..8 twice and 9..15 once.
  ASSERT_EQ(all.size(), 25u);
  std::vector<int> per(16, 0);
  for (std::size_t k = 0; k < all.size(); ++k) {
    EXPECT_EQ(all[k].index, static_cast<int>(k % 16));
    EXPECT_NEAR(all[k].time_s, 0.04 * static_cast<double>(k + 1), 1e-12);
    if (k > 0) {
      EXPECT_GT(all[k].time_s, all[k - 1].time_s);
    }
    ++per[static_cast<std::size_t>(all[k].index)];
  }
  for (int i = 0; i < 16; ++i) EXPECT_EQ(per[static_cast<std::size_t>(i)], i <= 8 ? 2 : 1) << i;
}

TEST(SonarSchedule, AnyPartitionOfTimeYieldsTheSamePings) {
  const auto g = mapper::p2at_geometry();
  SonarModel whole(SonarModelOptions{}, g, 77);
  const auto reference = whole.cycle(box_room(), 0.0, 10.0, turning);
  ASSERT_EQ(reference.size(), 250u);

  // Irregular cycle lengths, including boundaries exactly on firing times and empty intervals.
  SonarModel split(SonarModelOptions{}, g, 77);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> step(0.0, 0.15);
  std::vector<double> cuts{0.0, 0.04, 0.08, 0.08, 0.12};
  while (cuts.back() < 10.0) cuts.push_back(std::min(10.0, cuts.back() + step(rng)));
  std::vector<mapper::SonarReading> joined;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const auto got = split.cycle(box_room(), cuts[i], cuts[i + 1], turning);
    joined.insert(joined.end(), got.begin(), got.end());
  }
  ASSERT_EQ(joined.size(), reference.size());  // no duplicates, none lost
  for (std::size_t k = 0; k < joined.size(); ++k) {
    EXPECT_EQ(joined[k].index, reference[k].index);
    EXPECT_EQ(joined[k].time_s, reference[k].time_s);
    // The random stream is consumed ping by ping, so the noise is identical too.
    EXPECT_EQ(joined[k].range_m, reference[k].range_m);
    EXPECT_EQ(joined[k].echo, reference[k].echo);
  }
}

TEST(SonarSchedule, EachPingUsesThePoseAtItsOwnTime) {
  const auto g = mapper::p2at_geometry();
  SonarModel model(testing::noiseless_sonar_options(), g, 1);
  SonarModel probe(testing::noiseless_sonar_options(), g, 1);
  // Driving toward a wall at 1 m/s: each reading must match the pose at its firing time.
  const SonarScene scene{{testing::segment_through(Point2(5.0, 0.0), 1.5707963267948966, 10)}, {}};
  auto pose_at = [](double t) { return Pose2{t, 0.0, 0.0}; };
  for (const auto& r : model.cycle(scene, 0.0, 1.0, pose_at)) {
    const SonarEcho e = probe.geometric_echo(scene, pose_at(r.time_s), r.index);
    EXPECT_EQ(r.echo, e.echo);
    if (e.echo) {
      EXPECT_DOUBLE_EQ(r.range_m, e.range_m);
    }
  }
}

TEST(SonarSchedule, CustomFiringOrderAndValidation) {
  const auto g = mapper::p2at_geometry();
  SonarModelOptions o;
  o.firing_order = {3, 4, 12, 11};
  o.transducer_period_s = 0.05;
  SonarModel model(o, g, 1);
  const auto got = model.cycle(box_room(), 0.0, 0.4, turning);
  ASSERT_EQ(got.size(), 8u);
  const std::vector<int> expect{3, 4, 12, 11, 3, 4, 12, 11};
  for (std::size_t k = 0; k < got.size(); ++k) EXPECT_EQ(got[k].index, expect[k]);
  o.firing_order = {0, 16};
  EXPECT_THROW(SonarModel(o, g, 1), std::invalid_argument);
  o.firing_order.clear();
  o.rays_per_cone = 0;
  EXPECT_THROW(SonarModel(o, g, 1), std::invalid_argument);
}

using yaml::testing::config_error_of;

TEST(SonarOptions, ParsesEveryKey) {
  const auto root = yaml::Node::load_string(
      "sonar:\n  critical_angle_deg: 20\n  rays_per_cone: 5\n  range_noise_fraction: 0.02\n"
      "  range_noise_floor_m: 0.005\n  dropout_probability: 0.1\n  multipath: false\n"
      "  transducer_period_s: 0.05\n  firing_order: [3, 4]\n  corner_radius_m: 0.1\n",
      "exp.yaml");
  const SonarModelOptions o = parse_sonar_options(root["sonar"]);
  EXPECT_EQ(o.critical_angle_deg, 20.0);
  EXPECT_EQ(o.rays_per_cone, 5);
  EXPECT_EQ(o.range_noise_fraction, 0.02);
  EXPECT_EQ(o.range_noise_floor_m, 0.005);
  EXPECT_EQ(o.dropout_probability, 0.1);
  EXPECT_FALSE(o.multipath);
  EXPECT_EQ(o.transducer_period_s, 0.05);
  EXPECT_EQ(o.firing_order, (std::vector<int>{3, 4}));
  EXPECT_EQ(o.corner_radius_m, 0.1);
  const SonarModelOptions d = parse_sonar_options(yaml::Node::load_string("{}", "e.yaml"));
  EXPECT_EQ(d.critical_angle_deg, SonarModelOptions{}.critical_angle_deg);
  EXPECT_TRUE(d.firing_order.empty());
}

TEST(SonarOptions, RejectsUnknownKeysWrongTypesAndBadValues) {
  const auto root = yaml::Node::load_string(
      "robot:\n  sonar:\n    critical_angle_deg: 20\n    multipth: true\n", "exp.yaml");
  std::string msg = config_error_of([&] { parse_sonar_options(root["robot"]["sonar"]); });
  EXPECT_EQ(msg.rfind("exp.yaml:4: robot.sonar.multipth: unknown key", 0), 0u) << msg;

  const auto typed = yaml::Node::load_string("sonar:\n  rays_per_cone: many\n", "t.yaml");
  msg = config_error_of([&] { parse_sonar_options(typed["sonar"]); });
  EXPECT_EQ(msg.rfind("t.yaml:2: sonar.rays_per_cone: expected an integer", 0), 0u) << msg;

  const auto bad = yaml::Node::load_string("sonar:\n  dropout_probability: 1.5\n", "b.yaml");
  msg = config_error_of([&] { parse_sonar_options(bad["sonar"]); });
  EXPECT_EQ(msg.rfind("b.yaml:2: sonar.dropout_probability: must be in [0, 1]", 0), 0u) << msg;

  const auto order = yaml::Node::load_string("sonar:\n  firing_order: [1, x]\n", "o.yaml");
  msg = config_error_of([&] { parse_sonar_options(order["sonar"]); });
  EXPECT_NE(msg.find("sonar.firing_order[1]: expected an integer"), std::string::npos) << msg;
}

}  // namespace
}  // namespace cogmap::sim
