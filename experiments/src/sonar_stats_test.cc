#include "cogmap/experiments/sonar_stats.h"

#include <gtest/gtest.h>

#include <numbers>
#include <sstream>

namespace cogmap::experiments {
namespace {

// Two transducers at +90 and -30 degrees.
mapper::RobotGeometry two_sonars() {
  mapper::RobotGeometry g;
  g.sonars = {{0.1, 0.1, std::numbers::pi / 2}, {0.2, -0.1, -std::numbers::pi / 6}};
  return g;
}

mapper::SensorFrame frame(double t_s, double x_m, std::vector<mapper::SonarReading> sonar) {
  mapper::SensorFrame f;
  f.time_s = t_s;
  f.odometry = {x_m, 0.0, 0.0};
  f.sonar = std::move(sonar);
  return f;
}

mapper::SonarReading reading(int index, double range_m, bool echo = true) {
  mapper::SonarReading r;
  r.index = index;
  r.range_m = range_m;
  r.echo = echo;
  return r;
}

TEST(SonarStats, CountsOnlyMovingFramesAndEchoesBelowTheLimit) {
  SonarStatsCollector c(two_sonars());
  c.add(frame(0.0, 0.0, {reading(0, 9.0)}));  // the first frame only sets the reference
  // Standing still (0.01 m in 0.1 s = 0.1 m/s is the limit, so 0.005 m is below): not counted.
  c.add(frame(0.1, 0.005, {reading(0, 1.0), reading(1, 2.0)}));
  // Moving at 0.5 m/s: four frames.
  c.add(frame(0.2, 0.055, {reading(0, 1.0), reading(1, 2.0)}));
  c.add(frame(0.3, 0.105, {reading(0, 2.0), reading(1, 4.95)}));  // 4.95 m: not an echo
  c.add(frame(0.4, 0.155, {reading(0, 3.0), reading(1, 5.0, false)}));
  c.add(frame(0.5, 0.205, {reading(0, 4.0)}));
  const SonarStats s = c.result();
  EXPECT_EQ(s.moving_frames, 4);
  EXPECT_NEAR(s.moving_time_s, 0.4, 1e-12);
  EXPECT_NEAR(s.readings_per_frame, 7.0 / 4.0, 1e-12);
  EXPECT_NEAR(s.median_speed_mps, 0.5, 1e-9);
  ASSERT_EQ(s.transducers.size(), 2u);
  const TransducerStats& a = s.transducers[0];
  EXPECT_NEAR(a.bearing_deg, 90.0, 1e-12);
  EXPECT_EQ(a.firings, 4);
  EXPECT_EQ(a.echoes, 4);
  EXPECT_DOUBLE_EQ(a.echo_fraction, 1.0);
  // Ranges 1, 2, 3, 4: linear interpolation between order statistics at q (n - 1).
  EXPECT_NEAR(a.p10_m, 1.3, 1e-12);
  EXPECT_NEAR(a.p50_m, 2.5, 1e-12);
  EXPECT_NEAR(a.p90_m, 3.7, 1e-12);
  EXPECT_NEAR(a.firings_per_100ms, 1.0, 1e-12);
  const TransducerStats& b = s.transducers[1];
  EXPECT_NEAR(b.bearing_deg, -30.0, 1e-12);
  EXPECT_EQ(b.firings, 3);
  EXPECT_EQ(b.echoes, 1);
  EXPECT_NEAR(b.echo_fraction, 1.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(b.p50_m, 2.0);
  EXPECT_NEAR(b.firings_per_100ms, 0.75, 1e-12);
}

TEST(SonarStats, SilentTransducerHasZeroFractionAndNoQuantiles) {
  SonarStatsCollector c(two_sonars());
  c.add(frame(0.0, 0.0, {}));
  c.add(frame(0.1, 0.05, {reading(1, 5.0, false)}));
  const SonarStats s = c.result();
  EXPECT_EQ(s.transducers[0].firings, 0);
  EXPECT_EQ(s.transducers[0].echo_fraction, 0.0);
  EXPECT_EQ(s.transducers[1].firings, 1);
  EXPECT_EQ(s.transducers[1].echoes, 0);
  EXPECT_EQ(s.transducers[1].p50_m, 0.0);
}

TEST(SonarStats, TimeGoingBackwardsOrUnknownTransducersAreNotCounted) {
  SonarStatsCollector c(two_sonars());
  c.add(frame(1.0, 0.0, {}));
  c.add(frame(0.5, 1.0, {reading(0, 1.0)}));  // backwards: a second pooled recording starts
  c.add(frame(0.6, 1.05, {reading(0, 1.0), reading(7, 1.0)}));
  const SonarStats s = c.result();
  EXPECT_EQ(s.moving_frames, 1);
  EXPECT_EQ(s.transducers[0].firings, 1);
}

TEST(SonarStats, ComparisonMatchesTransducersByBearing) {
  SonarStats a, b;
  a.transducers = {{0, 90.0, 10, 9, 0.9, 0.5, 1.0, 1.5, 0.3125},
                   {1, 50.0, 10, 5, 0.5, 1.0, 2.0, 3.0, 0.3125}};
  b.transducers = {{3, 50.0, 10, 8, 0.8, 1.0, 3.0, 3.0, 0.157}};
  std::ostringstream out;
  write_sonar_stats_comparison(out, a, b, "real", "sim");
  const std::string text = out.str();
  EXPECT_NE(text.find("no transducer at this bearing"), std::string::npos) << text;
  // 50 deg: echo 0.50 vs 0.80 (+0.30), p50 2.00 vs 3.00 (ratio 1.50).
  EXPECT_NE(text.find("+0.30"), std::string::npos) << text;
  EXPECT_NE(text.find("1.50"), std::string::npos) << text;
}

TEST(SonarStats, CsvHasOneRowPerTransducer) {
  SonarStats s;
  s.transducers = {{0, 90.0, 4, 2, 0.5, 1.0, 1.5, 2.0, 0.25}};
  std::ostringstream out;
  write_sonar_stats_csv(out, s);
  EXPECT_EQ(out.str(),
            "index,bearing_deg,firings,echoes,echo_fraction,p10_m,p50_m,p90_m,firings_per_100ms\n"
            "0,90,4,2,0.5,1,1.5,2,0.25\n");
}

}  // namespace
}  // namespace cogmap::experiments
