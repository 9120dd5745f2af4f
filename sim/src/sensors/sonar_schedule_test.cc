// The firing schedule (P2OS SONAR_CYCLE and POLLING) and the `robot.sonar` options parser.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "cogmap/sim/sonar_model.h"
#include "sonar_test_support.h"
#include "yaml/config_error_test_support.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using mapper::Pose2;
using testing::scene_of;
using Readings = std::vector<mapper::SonarReading>;
using Polling = std::vector<std::vector<int>>;

SonarScene box_room() {
  return scene_of({{{-3, -2}, {3, -2}}, {{3, -2}, {3, 2}}, {{3, 2}, {-3, 2}}, {{-3, 2}, {-3, -2}}});
}

// The robot turns slowly in place, so every firing sees a different pose.
Pose2 turning(double t_s) { return {0.2, 0.1, 0.3 * t_s}; }

std::vector<int> indices(const Readings& readings) {
  std::vector<int> out;
  for (const auto& r : readings) out.push_back(r.index);
  return out;
}

TEST(SonarSchedule, P2atFiresOneTransducerPerArrayEvery40Ms) {
  SonarModel model(SonarModelOptions{}, mapper::p2at_geometry(), 1);
  EXPECT_EQ(model.cycle_ms(), 40.0);
  EXPECT_EQ(model.polling(), (Polling{{0, 1, 2, 3, 4, 5, 6, 7}, {8, 9, 10, 11, 12, 13, 14, 15}}));
  Readings all;
  for (int c = 0; c < 10; ++c) {
    const double t0 = 0.1 * c, t1 = 0.1 * (c + 1);
    const auto got = model.cycle(box_room(), t0, t1, turning);
    for (const auto& r : got) {
      EXPECT_GT(r.time_s, t0);
      EXPECT_LE(r.time_s, t1);
    }
    all.insert(all.end(), got.begin(), got.end());
  }
  // 1 s / 40 ms = 25 firings of two transducers, front array first, both at the same moment.
  ASSERT_EQ(all.size(), 50u);
  std::vector<std::vector<double>> times(16);
  for (std::size_t k = 0; k < all.size(); ++k) {
    const std::size_t firing = k / 2;
    EXPECT_EQ(all[k].index, static_cast<int>(8 * (k % 2) + firing % 8)) << k;
    EXPECT_NEAR(all[k].time_s, 0.04 * static_cast<double>(firing + 1), 1e-12) << k;
    if (k % 2 == 1) {
      EXPECT_EQ(all[k].time_s, all[k - 1].time_s);
    }
    times[static_cast<std::size_t>(all[k].index)].push_back(all[k].time_s);
  }
  // Each transducer fires every 8 x 40 = 320 ms: 0 and 8 four times (firings 0, 8, 16, 24).
  for (std::size_t i = 0; i < 16; ++i) {
    EXPECT_EQ(times[i].size(), i % 8 == 0 ? 4u : 3u) << i;
    EXPECT_NEAR(times[i][0], 0.04 * static_cast<double>(i % 8 + 1), 1e-12) << i;
    for (std::size_t j = 1; j < times[i].size(); ++j) {
      EXPECT_NEAR(times[i][j] - times[i][j - 1], 0.32, 1e-12) << i;
    }
  }
}

TEST(SonarSchedule, AnyPartitionOfTimeYieldsTheSamePings) {
  const auto g = mapper::p2at_geometry();
  SonarModel whole(SonarModelOptions{}, g, 77);
  const auto reference = whole.cycle(box_room(), 0.0, 10.0, turning);
  ASSERT_EQ(reference.size(), 500u);

  // Irregular cycle lengths, including boundaries exactly on firing times and empty intervals.
  SonarModel split(SonarModelOptions{}, g, 77);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> step(0.0, 0.15);
  std::vector<double> cuts{0.0, 0.04, 0.08, 0.08, 0.12};
  while (cuts.back() < 10.0) cuts.push_back(std::min(10.0, cuts.back() + step(rng)));
  Readings joined;
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
  SonarModelOptions o = testing::noiseless_sonar_options();
  o.detection_gain_db = 20.0;  // near echoes certain (p = 1.0 in double)
  SonarModel model(o, g, 1);
  const SonarModel probe(o, g, 1);
  // Driving toward a wall at 1 m/s: each reading must match the pose at its firing time.
  const SonarScene scene = scene_of({{Point2(5.0, -10.0), Point2(5.0, 10.0)}});
  auto pose_at = [](double t) { return Pose2{t, 0.0, 0.0}; };
  const auto got = model.cycle(scene, 0.0, 1.0, pose_at);
  ASSERT_EQ(got.size(), 50u);
  int certain = 0;
  for (const auto& r : got) {
    const auto c = probe.echo_candidates(scene, pose_at(r.time_s), r.index);
    if (c.empty() || -std::expm1(-c[0].strength) != 1.0) continue;
    // The nearest candidate is always heard, so the reading is its range at this pose.
    EXPECT_TRUE(r.echo);
    EXPECT_EQ(r.range_m, c[0].range_m);
    ++certain;
  }
  // Transducers 3 and 4 (+/-10 deg; a ray of the fan meets the wall square) fire 3 times each.
  EXPECT_GE(certain, 6);
}

TEST(SonarSchedule, PollingOptionSequencesEachArray) {
  const auto g = mapper::p2at_geometry();
  SonarModelOptions o;
  o.polling = {{3, 3, 4}, {12}};  // repeats allowed
  SonarModel model(o, g, 1);
  EXPECT_EQ(model.polling(), o.polling);
  EXPECT_EQ(indices(model.cycle(box_room(), 0.0, 0.25, turning)),
            (std::vector<int>{3, 12, 3, 12, 4, 12, 3, 12, 3, 12, 4, 12}));
  o.polling = {{}, {9, 8}};  // an empty sequence silences the front array
  SonarModel rear(o, g, 1);
  const auto got = rear.cycle(box_room(), 0.0, 0.21, turning);
  EXPECT_EQ(indices(got), (std::vector<int>{9, 8, 9, 8, 9}));
  ASSERT_EQ(got.size(), 5u);
  EXPECT_NEAR(got[4].time_s, 0.2, 1e-12);
  o.polling = {{1, 2}};  // arrays not named keep the default order
  EXPECT_EQ(SonarModel(o, g, 1).polling(), (Polling{{1, 2}, {8, 9, 10, 11, 12, 13, 14, 15}}));
  o.polling = {std::vector<int>(16, 7)};  // 16 entries is the P2OS limit
  EXPECT_NO_THROW(SonarModel(o, g, 1));
}

TEST(SonarSchedule, InvalidScheduleOptionsThrow) {
  const auto g = mapper::p2at_geometry();
  auto throws = [&](const Polling& polling, double cycle_ms) {
    SonarModelOptions o;
    o.polling = polling;
    o.cycle_ms = cycle_ms;
    try {
      SonarModel(o, g, 1);
    } catch (const std::invalid_argument&) {
      return true;
    }
    return false;
  };
  EXPECT_FALSE(throws({}, 40.0));
  EXPECT_FALSE(throws({}, 2.0));
  EXPECT_FALSE(throws({}, 120.0));
  EXPECT_TRUE(throws({}, 1.99));
  EXPECT_TRUE(throws({}, 120.01));
  EXPECT_TRUE(throws({{0}, {8}, {16}}, 40.0));  // the P2-AT has two arrays
  EXPECT_TRUE(throws({{8}}, 40.0));             // transducer 8 is on array 1
  EXPECT_TRUE(throws({{0}, {7}}, 40.0));
  EXPECT_TRUE(throws({{-1}}, 40.0));
  EXPECT_TRUE(throws({std::vector<int>(17, 0)}, 40.0));
}

TEST(SonarSchedule, SetCycleMsChangesTheRateFromNowOn) {
  SonarModel model(SonarModelOptions{}, mapper::p2at_geometry(), 1);
  auto times = [](const Readings& r) {
    std::vector<double> out;
    for (std::size_t k = 0; k < r.size(); k += 2) out.push_back(r[k].time_s);
    return out;
  };
  EXPECT_EQ(indices(model.cycle(box_room(), 0.0, 0.1, turning)), (std::vector<int>{0, 8, 1, 9}));
  // At 0.13 s the cycle becomes 100 ms: the next firing is at 0.23 s, then every 100 ms; the
  // polling sequences go on where they were.
  model.set_cycle_ms(100.0, 0.13);
  EXPECT_EQ(model.cycle_ms(), 100.0);
  auto got = model.cycle(box_room(), 0.1, 0.5, turning);
  EXPECT_EQ(indices(got), (std::vector<int>{2, 10, 3, 11, 4, 12}));
  const std::vector<double> expect{0.23, 0.33, 0.43};
  ASSERT_EQ(times(got).size(), expect.size());
  for (std::size_t k = 0; k < expect.size(); ++k) EXPECT_NEAR(times(got)[k], expect[k], 1e-12);
  // The fastest cycle, 2 ms, from 0.5 s: 24 firings in (0.5, 0.549].
  model.set_cycle_ms(2.0, 0.5);
  got = model.cycle(box_room(), 0.5, 0.549, turning);
  ASSERT_EQ(got.size(), 48u);
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_NEAR(got[k].time_s, 0.5 + 0.002 * static_cast<double>(k / 2 + 1), 1e-12);
    EXPECT_EQ(got[k].index, static_cast<int>(8 * (k % 2) + (5 + k / 2) % 8));
  }
  EXPECT_THROW(model.set_cycle_ms(1.99, 0.6), std::invalid_argument);
  EXPECT_THROW(model.set_cycle_ms(120.5, 0.6), std::invalid_argument);
  EXPECT_EQ(model.cycle_ms(), 2.0);  // a refused change changes nothing
}

TEST(SonarSchedule, SetPollingResequencesOneArray) {
  SonarModel model(SonarModelOptions{}, mapper::p2at_geometry(), 1);
  EXPECT_EQ(indices(model.cycle(box_room(), 0.0, 0.1, turning)), (std::vector<int>{0, 8, 1, 9}));
  // The front array restarts with its new sequence; the rear one goes on.
  model.set_polling(0, {5, 5, 2});
  EXPECT_EQ(indices(model.cycle(box_room(), 0.1, 0.26, turning)),
            (std::vector<int>{5, 10, 5, 11, 2, 12, 5, 13}));
  model.set_polling(1, {});  // silences the rear array
  const auto got = model.cycle(box_room(), 0.26, 0.37, turning);
  EXPECT_EQ(indices(got), (std::vector<int>{5, 2, 5}));
  ASSERT_EQ(got.size(), 3u);
  EXPECT_NEAR(got[0].time_s, 0.28, 1e-12);
  EXPECT_NEAR(got[2].time_s, 0.36, 1e-12);

  EXPECT_THROW(model.set_polling(2, {}), std::invalid_argument);
  EXPECT_THROW(model.set_polling(-1, {}), std::invalid_argument);
  EXPECT_THROW(model.set_polling(0, {8}), std::invalid_argument);
  EXPECT_THROW(model.set_polling(1, {7}), std::invalid_argument);
  EXPECT_THROW(model.set_polling(1, {16}), std::invalid_argument);
  EXPECT_THROW(model.set_polling(0, {-1}), std::invalid_argument);
  EXPECT_THROW(model.set_polling(0, std::vector<int>(17, 1)), std::invalid_argument);
  EXPECT_EQ(model.polling(), (Polling{{5, 5, 2}, {}}));  // refused changes changed nothing
  model.set_polling(1, std::vector<int>(16, 15));
  EXPECT_EQ(indices(model.cycle(box_room(), 0.37, 0.41, turning)), (std::vector<int>{5, 15}));
}

TEST(SonarSchedule, ModelRejectsOptionsOutOfRange) {
  const auto g = mapper::p2at_geometry();
  auto throws = [&](auto change) {
    SonarModelOptions o = testing::reference_options();
    change(o);
    try {
      SonarModel(o, g, 1);
    } catch (const std::invalid_argument&) {
      return true;
    }
    return false;
  };
  EXPECT_FALSE(throws([](SonarModelOptions&) {}));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.beam_sigma_deg = 0.0; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.beam_sigma_deg = 90.5; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.fan_half_width_deg = 0.0; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.fan_half_width_deg = 90.0; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.rays_per_cone = 0; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.detection_gain_db = 60.5; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.detection_gain_db = std::nan(""); }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.corner_strength = -0.1; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.threshold_walk_m = 1.01; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.range_noise_fraction = -0.01; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.range_noise_floor_m = -0.01; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.dropout_probability = 1.01; }));
  EXPECT_TRUE(throws([](SonarModelOptions& o) { o.corner_radius_m = -0.01; }));
  EXPECT_FALSE(throws([](SonarModelOptions& o) { o.rays_per_cone = 1; }));
  EXPECT_FALSE(throws([](SonarModelOptions& o) { o.detection_gain_db = -60.0; }));
}

using yaml::testing::config_error_of;

TEST(SonarOptions, ParsesEveryKey) {
  const auto root = yaml::Node::load_string(
      "sonar:\n"
      "  beam_sigma_deg: 7.5\n"
      "  fan_half_width_deg: 30\n"
      "  rays_per_cone: 31\n"
      "  detection_gain_db: -2.5\n"
      "  corner_strength: 12\n"
      "  threshold_walk_m: 0.08\n"
      "  diffuse_range_gain_exponent: 1.5\n"
      "  range_noise_fraction: 0.02\n"
      "  range_noise_floor_m: 0.005\n"
      "  dropout_probability: 0.1\n"
      "  multipath: false\n"
      "  cycle_ms: 60\n"
      "  polling: [[3, 4, 3], [], [16, 17]]\n"
      "  corner_radius_m: 0.1\n",
      "exp.yaml");
  const SonarModelOptions o = parse_sonar_options(root["sonar"]);
  EXPECT_EQ(o.beam_sigma_deg, 7.5);
  EXPECT_EQ(o.fan_half_width_deg, 30.0);
  EXPECT_EQ(o.rays_per_cone, 31);
  EXPECT_EQ(o.detection_gain_db, -2.5);
  EXPECT_EQ(o.corner_strength, 12.0);
  EXPECT_EQ(o.threshold_walk_m, 0.08);
  EXPECT_EQ(o.diffuse_range_gain_exponent, 1.5);
  EXPECT_EQ(o.range_noise_fraction, 0.02);
  EXPECT_EQ(o.range_noise_floor_m, 0.005);
  EXPECT_EQ(o.dropout_probability, 0.1);
  EXPECT_FALSE(o.multipath);
  EXPECT_EQ(o.cycle_ms, 60.0);
  EXPECT_EQ(o.polling, (Polling{{3, 4, 3}, {}, {16, 17}}));
  EXPECT_EQ(o.corner_radius_m, 0.1);

  const SonarModelOptions d = parse_sonar_options(yaml::Node::load_string("{}", "e.yaml"));
  const SonarModelOptions def;
  EXPECT_EQ(d.beam_sigma_deg, def.beam_sigma_deg);
  EXPECT_EQ(d.fan_half_width_deg, def.fan_half_width_deg);
  EXPECT_EQ(d.rays_per_cone, def.rays_per_cone);
  EXPECT_EQ(d.detection_gain_db, def.detection_gain_db);
  EXPECT_EQ(d.corner_strength, def.corner_strength);
  EXPECT_EQ(d.threshold_walk_m, def.threshold_walk_m);
  EXPECT_EQ(d.diffuse_range_gain_exponent, def.diffuse_range_gain_exponent);
  EXPECT_EQ(d.range_noise_fraction, def.range_noise_fraction);
  EXPECT_EQ(d.range_noise_floor_m, def.range_noise_floor_m);
  EXPECT_EQ(d.dropout_probability, def.dropout_probability);
  EXPECT_TRUE(d.multipath);
  EXPECT_EQ(d.cycle_ms, 40.0);
  EXPECT_TRUE(d.polling.empty());
  EXPECT_EQ(d.corner_radius_m, def.corner_radius_m);
}

// The message of parsing `sonar:\n  <line>\n` from file t.yaml.
std::string sonar_error_of(const std::string& line) {
  const auto root = yaml::Node::load_string("sonar:\n  " + line + "\n", "t.yaml");
  return config_error_of([&] { parse_sonar_options(root["sonar"]); });
}

bool starts_with(const std::string& s, const std::string& prefix) {
  return s.rfind(prefix, 0) == 0;
}

TEST(SonarOptions, RejectsUnknownAndRemovedKeys) {
  const auto root = yaml::Node::load_string(
      "robot:\n  sonar:\n    cycle_ms: 20\n    multipth: true\n", "exp.yaml");
  const std::string msg = config_error_of([&] { parse_sonar_options(root["robot"]["sonar"]); });
  EXPECT_TRUE(starts_with(msg, "exp.yaml:4: robot.sonar.multipth: unknown key")) << msg;
  // The keys of the old model are gone: an old experiment file must fail loudly.
  for (const char* old :
       {"critical_angle_deg: 20", "transducer_period_s: 0.05", "firing_order: [3, 4]"}) {
    const std::string key = std::string(old).substr(0, std::string(old).find(':'));
    const std::string m = sonar_error_of(old);
    EXPECT_TRUE(starts_with(m, "t.yaml:2: sonar." + key + ": unknown key")) << m;
  }
}

TEST(SonarOptions, RejectsWrongTypesAndValuesOutOfRange) {
  EXPECT_TRUE(starts_with(sonar_error_of("rays_per_cone: many"),
                          "t.yaml:2: sonar.rays_per_cone: expected an integer"));
  EXPECT_TRUE(starts_with(sonar_error_of("multipath: maybe"),
                          "t.yaml:2: sonar.multipath: expected true or false"));
  EXPECT_TRUE(starts_with(sonar_error_of("cycle_ms: fast"),
                          "t.yaml:2: sonar.cycle_ms: expected a finite number"));
  const std::vector<std::pair<std::string, std::string>> bad{
      {"beam_sigma_deg: 0", "must be in (0, 90]"},
      {"beam_sigma_deg: 91", "must be in (0, 90]"},
      {"fan_half_width_deg: 89.5", "must be in (0, 89]"},
      {"rays_per_cone: 0", "must be in [1, 1000]"},
      {"detection_gain_db: 61", "must be in [-60, 60]"},
      {"corner_strength: -1", "must be in [0, 1e6]"},
      {"threshold_walk_m: 1.5", "must be in [0, 1]"},
      {"diffuse_range_gain_exponent: -11", "must be in [-10, 10]"},
      {"range_noise_fraction: -0.1", "must be in [0, 1]"},
      {"range_noise_floor_m: 2", "must be in [0, 1]"},
      {"dropout_probability: 1.5", "must be in [0, 1]"},
      {"cycle_ms: 1", "must be in [2, 120] (P2OS SONAR_CYCLE)"},
      {"cycle_ms: 121", "must be in [2, 120] (P2OS SONAR_CYCLE)"},
      {"corner_radius_m: 2", "must be in [0, 1]"}};
  for (const auto& [line, what] : bad) {
    const std::string key = line.substr(0, line.find(':'));
    const std::string m = sonar_error_of(line);
    EXPECT_TRUE(starts_with(m, "t.yaml:2: sonar." + key + ": " + what)) << m;
  }
}

TEST(SonarOptions, RejectsMalformedPolling) {
  std::string m = sonar_error_of("polling: [[0, 1], [8, 3]]");
  EXPECT_TRUE(starts_with(m, "t.yaml:2: sonar.polling[1][1]: array 1 holds transducers 8-15")) << m;
  m = sonar_error_of("polling: [[0, x]]");
  EXPECT_TRUE(starts_with(m, "t.yaml:2: sonar.polling[0][1]: expected an integer")) << m;
  m = sonar_error_of("polling: [1, 2]");
  EXPECT_TRUE(starts_with(m, "t.yaml:2: sonar.polling[0]: expected a list")) << m;
  m = sonar_error_of("polling: 3");
  EXPECT_TRUE(starts_with(m, "t.yaml:2: sonar.polling: expected a list")) << m;
  m = sonar_error_of("polling: [[], [], [], [], []]");
  EXPECT_TRUE(starts_with(m, "t.yaml:2: sonar.polling: at most 4 sonar arrays")) << m;
  m = sonar_error_of("polling: [[0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0]]");
  EXPECT_TRUE(starts_with(m, "t.yaml:2: sonar.polling[0]: a polling sequence holds at most 16"))
      << m;
  m = sonar_error_of("polling: [[0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 7]]");
  EXPECT_EQ(m, "");
}

}  // namespace
}  // namespace cogmap::sim
