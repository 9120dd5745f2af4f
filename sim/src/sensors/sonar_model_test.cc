#include "cogmap/sim/sonar_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "sonar_test_support.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using mapper::Pose2;
using testing::noiseless_sonar_options;
using testing::segment_through;
using testing::transducer_frame;

constexpr double kDeg = std::numbers::pi / 180.0;

// A wall perpendicular to the robot's x axis at x = distance_m (robot at the origin, heading 0).
SonarScene wall_ahead(double distance_m) {
  return {{segment_through(Point2(distance_m, 0.0), std::numbers::pi / 2, 10.0)}, {}};
}

TEST(SonarModel, WallAtNormalIncidenceGivesExactGeometricRange) {
  const auto g = mapper::p2at_geometry();
  const SonarModel model(noiseless_sonar_options(), g, 1);
  for (double d : {1.0, 2.0, 3.0, 4.0}) {
    for (int index : {3, 4}) {
      const SonarEcho e = model.geometric_echo(wall_ahead(d), Pose2{}, index);
      ASSERT_TRUE(e.echo) << d;
      EXPECT_FALSE(e.multipath);
      // The nearest point of the wall in the cone is the foot of the perpendicular.
      EXPECT_NEAR(e.range_m, d - g.sonars[static_cast<std::size_t>(index)].x_m, 1e-12);
    }
  }
}

TEST(SonarModel, FrontTransducersReadWallWithinConfiguredNoise) {
  const auto g = mapper::p2at_geometry();
  SonarModelOptions o;
  o.dropout_probability = 0.0;
  SonarModel model(o, g, 42);
  constexpr int kPings = 400;
  for (double d : {1.0, 2.0, 3.0, 4.0}) {
    for (int index : {3, 4}) {
      const double truth = d - g.sonars[static_cast<std::size_t>(index)].x_m;
      const double sd = model.range_noise_sd_m(truth);
      EXPECT_NEAR(sd, std::hypot(0.01 * truth, 0.01), 1e-15);
      double sum = 0.0, sum2 = 0.0;
      int beyond_3sd = 0;
      for (int i = 0; i < kPings; ++i) {
        const mapper::SonarReading r = model.ping(wall_ahead(d), Pose2{}, index, 0.0);
        ASSERT_TRUE(r.echo);
        EXPECT_EQ(r.index, index);
        const double err = r.range_m - truth;
        beyond_3sd += std::abs(err) > 3.0 * sd;
        sum += err;
        sum2 += err * err;
      }
      const double mean = sum / kPings;
      const double sample_sd = std::sqrt((sum2 - kPings * mean * mean) / (kPings - 1));
      EXPECT_NEAR(mean, 0.0, 4.0 * sd / std::sqrt(kPings)) << d << " " << index;
      EXPECT_NEAR(sample_sd / sd, 1.0, 4.0 / std::sqrt(2.0 * (kPings - 1))) << d << " " << index;
      // P(|z| > 3) = 0.27 %: expect ~1 of 400; 6 would be a > 4-sigma binomial excess.
      EXPECT_LE(beyond_3sd, 6) << d << " " << index;
    }
  }
}

// Rotates the robot so that transducer `index` points at `target`, then builds a wall through the
// target whose normal makes `incidence_rad` with the beam axis.
struct ObliqueSetup {
  Pose2 pose;
  testing::TransducerFrame frame;
};

ObliqueSetup aim(const mapper::RobotGeometry& g, int index, double robot_theta_rad) {
  const Pose2 pose{0.3, -0.2, robot_theta_rad};
  return {pose, transducer_frame(g, pose, index)};
}

TEST(SonarModel, FlatWallAt45DegreesGivesNoDirectEcho) {
  const auto g = mapper::p2at_geometry();
  const ObliqueSetup s = aim(g, 3, 0.4);
  // Wall direction axis + 45 deg: its normal is 45 deg off the beam axis, so every ray of the
  // 30 deg cone meets it 30-60 deg off normal.
  const SonarScene scene{{segment_through(s.frame.along(2.0), s.frame.axis_rad + 45 * kDeg, 20)},
                         {}};
  const SonarModel model(noiseless_sonar_options(), g, 3);
  EXPECT_FALSE(model.geometric_echo(scene, s.pose, 3).echo);
  SonarModel noisy(SonarModelOptions{}, g, 3);
  for (int i = 0; i < 200; ++i) {
    const mapper::SonarReading r = noisy.ping(scene, s.pose, 3, 0.0);
    EXPECT_FALSE(r.echo);
    EXPECT_EQ(r.range_m, g.sonar_max_range_m);
  }
  // The same wall turned to 10 deg off normal echoes: the rule is the incidence, not the wall.
  const SonarScene facing{{segment_through(s.frame.along(2.0), s.frame.axis_rad + 80 * kDeg, 20)},
                          {}};
  const SonarEcho e = model.geometric_echo(facing, s.pose, 3);
  ASSERT_TRUE(e.echo);
  EXPECT_NEAR(e.range_m, 2.0 * std::cos(10 * kDeg), 1e-12);
}

TEST(SonarModel, ConvexCornerAt45DegreesEchoes) {
  const auto g = mapper::p2at_geometry();
  const ObliqueSetup s = aim(g, 5, -0.7);
  // A wedge pointing at the transducer: both faces 45 deg off the beam axis.
  const Point2 tip = s.frame.along(2.5);
  const Point2 f1(std::cos(s.frame.axis_rad + 45 * kDeg), std::sin(s.frame.axis_rad + 45 * kDeg));
  const Point2 f2(std::cos(s.frame.axis_rad - 45 * kDeg), std::sin(s.frame.axis_rad - 45 * kDeg));
  SonarScene scene{{{tip, tip + 1.0 * f1}, {tip, tip + 1.0 * f2}}, {}};
  const SonarModel model(noiseless_sonar_options(), g, 4);
  EXPECT_FALSE(model.geometric_echo(scene, s.pose, 5).echo) << "faces alone are specular";
  scene.corners.push_back(tip);
  const SonarEcho e = model.geometric_echo(scene, s.pose, 5);
  ASSERT_TRUE(e.echo);
  EXPECT_FALSE(e.multipath);
  EXPECT_NEAR(e.range_m, 2.5, 1e-12);
  // A corner outside the 30 deg cone is not heard.
  scene.corners = {s.frame.along(2.5, 20 * kDeg)};
  scene.surfaces.clear();
  EXPECT_FALSE(model.geometric_echo(scene, s.pose, 5).echo);
}

TEST(SonarModel, CornerHiddenBehindWallIsNotHeard) {
  const auto g = mapper::p2at_geometry();
  const ObliqueSetup s = aim(g, 3, 0.0);
  // A wall 45 deg off the axis at 1.5 m (no direct echo) hides a corner at 3 m.
  const SonarScene scene{{segment_through(s.frame.along(1.5), s.frame.axis_rad + 45 * kDeg, 5)},
                         {s.frame.along(3.0)}};
  SonarModelOptions o = noiseless_sonar_options();
  o.multipath = false;
  EXPECT_FALSE(SonarModel(o, g, 1).geometric_echo(scene, s.pose, 3).echo);
}

TEST(SonarModel, MultipathViaSecondWallReadsHalfThePath) {
  const auto g = mapper::p2at_geometry();
  const ObliqueSetup s = aim(g, 4, 0.25);
  const double a = s.frame.axis_rad;
  const Point2 along(std::cos(a), std::sin(a));
  const Point2 left(-std::sin(a), std::cos(a));
  // Wall A crosses the axis at 2 m, 45 deg off normal: the axis ray turns 90 deg to the left and
  // meets wall B, 1.5 m away and parallel to the axis, at normal incidence.
  const Point2 hit_a = s.frame.along(2.0);
  const mapper::Segment wall_a = segment_through(hit_a, a + 45 * kDeg, 3.0);
  const mapper::Segment wall_b{s.frame.origin + 0.5 * along + 1.5 * left,
                               s.frame.origin + 3.5 * along + 1.5 * left};
  const SonarScene scene{{wall_a, wall_b}, {}};
  const SonarModel model(noiseless_sonar_options(), g, 5);
  const SonarEcho e = model.geometric_echo(scene, s.pose, 4);
  ASSERT_TRUE(e.echo);
  EXPECT_TRUE(e.multipath);
  // Out-and-back path 2 * (2.0 + 1.5) = 7 m: the receiver reports half, 3.5 m, not 2 m.
  EXPECT_NEAR(e.range_m, 3.5, 1e-9);
  // Without multipath the oblique wall is simply silent.
  SonarModelOptions o = noiseless_sonar_options();
  o.multipath = false;
  EXPECT_FALSE(SonarModel(o, g, 5).geometric_echo(scene, s.pose, 4).echo);
}

TEST(SonarModel, ConcaveCornerRetroReflectsNearItsDistance) {
  const auto g = mapper::p2at_geometry();
  const ObliqueSetup s = aim(g, 3, 1.1);
  const double a = s.frame.axis_rad;
  // A 90 deg room corner 2 m ahead, walls 45 deg off the axis on either side: no single-bounce
  // echo, but two mirrors at right angles send the pulse straight back.
  const Point2 apex = s.frame.along(2.0);
  const Point2 d1(std::cos(a + 135 * kDeg), std::sin(a + 135 * kDeg));
  const Point2 d2(std::cos(a - 135 * kDeg), std::sin(a - 135 * kDeg));
  const SonarScene scene{{{apex, apex + 3.0 * d1}, {apex, apex + 3.0 * d2}}, {}};
  const SonarEcho e = SonarModel(noiseless_sonar_options(), g, 6).geometric_echo(scene, s.pose, 3);
  ASSERT_TRUE(e.echo);
  EXPECT_TRUE(e.multipath);
  // The rays nearest the axis travel 2 * 2 m * cos(offset) out and back via the two walls.
  EXPECT_NEAR(e.range_m, 2.0, 0.02);
  EXPECT_GE(e.range_m, 2.0 * std::cos(3.75 * kDeg) - 1e-9);
}

TEST(SonarModel, NearSurfaceReadsMinRangeAndReadingsStayInLimits) {
  const auto g = mapper::p2at_geometry();
  SonarModelOptions o;
  o.range_noise_fraction = 0.3;  // exaggerated so the clamps are exercised
  SonarModel model(o, g, 7);
  // Transducers 3/4 are 0.245 m forward: a wall at 0.3 m is 5.5 cm away, inside the blanking.
  for (int i = 0; i < 50; ++i) {
    const mapper::SonarReading r = model.ping(wall_ahead(0.3), Pose2{}, 3, 0.0);
    if (r.echo) {
      EXPECT_EQ(r.range_m, g.sonar_min_range_m);
    }
  }
  // A 6 x 4 m room with a pillar: random poses, every transducer.
  const SonarScene room{{{{-3, -2}, {3, -2}},
                         {{3, -2}, {3, 2}},
                         {{3, 2}, {-3, 2}},
                         {{-3, 2}, {-3, -2}},
                         {{1, 0}, {1.3, 0}},
                         {{1.3, 0}, {1.3, 0.3}}},
                        {{1.3, 0}}};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(-2.5, 2.5), uy(-1.5, 1.5), ut(-3.14, 3.14);
  int echoes = 0;
  for (int i = 0; i < 2000; ++i) {
    const Pose2 p{ux(rng), uy(rng), ut(rng)};
    const mapper::SonarReading r = model.ping(room, p, i % 16, 0.0);
    EXPECT_GE(r.range_m, g.sonar_min_range_m);
    EXPECT_LE(r.range_m, g.sonar_max_range_m);
    if (!r.echo) {
      EXPECT_EQ(r.range_m, g.sonar_max_range_m);
    }
    echoes += r.echo;
  }
  EXPECT_GT(echoes, 1000);  // a closed room echoes on most pings
}

TEST(SonarModel, DropoutRateMatchesProbability) {
  const auto g = mapper::p2at_geometry();
  SonarModelOptions o;
  o.dropout_probability = 0.1;
  SonarModel model(o, g, 99);
  constexpr int kPings = 5000;
  int dropped = 0;
  for (int i = 0; i < kPings; ++i) dropped += !model.ping(wall_ahead(2.0), Pose2{}, 4, 0.0).echo;
  const double p = o.dropout_probability;
  EXPECT_NEAR(dropped, kPings * p, 4.0 * std::sqrt(kPings * p * (1 - p)));
}

TEST(SonarModel, SameSeedSameReadings) {
  const auto g = mapper::p2at_geometry();
  SonarModel a(SonarModelOptions{}, g, 5), b(SonarModelOptions{}, g, 5),
      c(SonarModelOptions{}, g, 6);
  bool differs = false;
  for (int i = 0; i < 20; ++i) {
    const auto ra = a.ping(wall_ahead(2.0), Pose2{}, 3, 0.0);
    const auto rb = b.ping(wall_ahead(2.0), Pose2{}, 3, 0.0);
    const auto rc = c.ping(wall_ahead(2.0), Pose2{}, 3, 0.0);
    EXPECT_EQ(ra.range_m, rb.range_m);
    EXPECT_EQ(ra.echo, rb.echo);
    differs = differs || ra.range_m != rc.range_m;
  }
  EXPECT_TRUE(differs);
}

}  // namespace
}  // namespace cogmap::sim
