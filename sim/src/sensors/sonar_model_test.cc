// The echo physics of the sonar model on exact synthetic scenes: every expected value is worked
// out in the test (geometry by hand, strengths by the formulas of docs/sonar-model.md written out
// in sonar_test_support.h), never by asking the model.
#include "cogmap/sim/sonar_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "sonar_test_support.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using mapper::Pose2;
using testing::builtin_index;
using testing::kDeg;
using testing::noiseless_sonar_options;
using testing::ray_offset_rad;
using testing::ray_width_rad;
using testing::reference_beam;
using testing::reference_surface_strength;
using testing::scene_of;
using testing::single_transducer_geometry;

// A wall square to the single transducer's axis at x = d. Its direction (0, 8) makes every ray's
// hit distance exactly d / cos(offset) and the axis ray's exactly d.
SonarScene wall_at(double d) { return scene_of({{Point2(d, -4.0), Point2(d, 4.0)}}); }

using testing::builtin;

TEST(SonarModel, SquareWallReadsItsPerpendicularDistance) {
  const auto g = single_transducer_geometry();
  const SonarModelOptions o =
      testing::reference_options();  // 21 rays over +/-25 deg: ray 10 lies on the axis
  const SonarModel model(o, g, 1);
  const SonarModel no_walk(noiseless_sonar_options(), g, 1);
  const SonarMaterial& paint = builtin("painted_wall");
  const double dphi = ray_width_rad(21, 25.0);
  for (double d : {0.5, 1.0, 2.0, 3.5, 4.5}) {
    SCOPED_TRACE(d);
    const auto c = model.echo_candidates(wall_at(d), Pose2{}, 0);
    ASSERT_EQ(c.size(), 21u);  // one per ray; the mirrored pulse leaves the scene
    EXPECT_EQ(c[0].range_m, d);
    EXPECT_FALSE(c[0].multipath);
    const double s0 = reference_surface_strength(paint, 0.0, d, 1.0, dphi);
    EXPECT_NEAR(c[0].strength / s0, 1.0, 1e-12);
    EXPECT_GT(-std::expm1(-c[0].strength), 0.999);
    // Every other ray: slant range d / cos(offset), incidence |offset|, weighted by the beam.
    double total = 0.0;
    for (int i = 0; i < 21; ++i) {
      const double phi = ray_offset_rad(i, 21, 25.0);
      const double r = d / std::cos(phi);
      const double s = reference_beam(phi, 6.0 * kDeg) *
                       reference_surface_strength(paint, std::abs(phi), r, 1.0, dphi);
      total += s;
      const std::size_t k = static_cast<std::size_t>(2 * std::abs(i - 10) - (i < 10 ? 1 : 0));
      const std::size_t rank = i == 10 ? 0 : k;  // sorted: axis, then -/+ 2.5, -/+ 5 deg ...
      EXPECT_NEAR(c[rank].range_m, r, 1e-12) << i;
      EXPECT_NEAR(c[rank].strength / s, 1.0, 1e-9) << i;
    }
    EXPECT_NEAR(model.echo_probability(wall_at(d), Pose2{}, 0), -std::expm1(-total), 1e-15);
    EXPECT_GT(model.echo_probability(wall_at(d), Pose2{}, 0), 0.999);
    const SonarEcho exact = no_walk.geometric_echo(wall_at(d), Pose2{}, 0);
    ASSERT_TRUE(exact.echo);
    EXPECT_FALSE(exact.multipath);
    EXPECT_EQ(exact.range_m, d);
    // With the default walk the reading is long by walk * (1 - p) = 0.15 exp(-s0).
    EXPECT_NEAR(model.geometric_echo(wall_at(d), Pose2{}, 0).range_m, d + 0.15 * std::exp(-s0),
                1e-14);
  }
}

TEST(SonarModel, P2atTransducersUseTheirMounts) {
  const auto g = mapper::p2at_geometry();
  const SonarModel model(noiseless_sonar_options(), g, 1);
  const Pose2 pose{0.3, -0.2, 0.4};
  for (int index : {0, 3, 4, 11}) {
    const auto f = testing::transducer_frame(g, pose, index);
    const SonarScene scene =
        scene_of({testing::segment_through(f.along(1.7), f.axis_rad + 90 * kDeg, 4.0)});
    const SonarEcho e = model.geometric_echo(scene, pose, index);
    ASSERT_TRUE(e.echo) << index;
    EXPECT_NEAR(e.range_m, 1.7, 1e-12) << index;
  }
  EXPECT_THROW(model.echo_candidates(scene_of({}), pose, 16), std::out_of_range);
}

TEST(SonarModel, SquareWallReadingsHaveTheConfiguredNoise) {
  const auto g = single_transducer_geometry();
  SonarModelOptions o = testing::reference_options();
  o.dropout_probability = 0.0;
  SonarModel model(o, g, 42);
  constexpr int kPings = 400;
  const double dphi = ray_width_rad(21, 25.0);
  for (double d : {1.0, 2.0, 3.0, 4.0}) {
    // The axis echo is heard with p = 1 - exp(-s0) and reads walk (1 - p) long.
    const double s0 = reference_surface_strength(builtin("painted_wall"), 0.0, d, 1.0, dphi);
    const double truth = d + 0.15 * std::exp(-s0);
    const double sd = model.range_noise_sd_m(truth);
    EXPECT_NEAR(sd, std::sqrt(0.0001 * truth * truth + 0.0001), 1e-15);
    double sum = 0.0, sum2 = 0.0;
    int beyond_3sd = 0;
    for (int i = 0; i < kPings; ++i) {
      const mapper::SonarReading r = model.ping(wall_at(d), Pose2{}, 0, 0.0);
      ASSERT_TRUE(r.echo);
      const double err = r.range_m - truth;
      beyond_3sd += std::abs(err) > 3.0 * sd;
      sum += err;
      sum2 += err * err;
    }
    const double mean = sum / kPings;
    const double sample_sd = std::sqrt((sum2 - kPings * mean * mean) / (kPings - 1));
    // 4 sd of the sample mean, and of the sample sd (sd of s/sigma ~ 1 / sqrt(2 (n - 1))).
    EXPECT_NEAR(mean, 0.0, 4.0 * sd / std::sqrt(kPings)) << d;
    EXPECT_NEAR(sample_sd / sd, 1.0, 4.0 / std::sqrt(2.0 * (kPings - 1))) << d;
    // P(|z| > 3) = 0.27 %: ~1 of 400 expected; 6 would be a > 4-sd binomial excess.
    EXPECT_LE(beyond_3sd, 6) << d;
  }
}

TEST(SonarModel, BeamPatternWeighsCornersByTheirOffset) {
  const auto g = single_transducer_geometry();
  for (double sigma : {6.0, 9.0}) {
    SonarModelOptions o = testing::reference_options();
    o.beam_sigma_deg = sigma;
    const SonarModel model(o, g, 1);
    const auto on = model.echo_candidates(scene_of({}, {Point2(2.0, 0.0)}), Pose2{}, 0);
    ASSERT_EQ(on.size(), 1u);
    EXPECT_EQ(on[0].range_m, 2.0);
    EXPECT_EQ(on[0].strength, 20.0);  // corner_strength on the axis, gain 0 dB
    EXPECT_FALSE(on[0].multipath);
    for (double off : {12.0, -12.0}) {
      const Point2 c = 2.0 * Point2(std::cos(off * kDeg), std::sin(off * kDeg));
      const auto oblique = model.echo_candidates(scene_of({}, {c}), Pose2{}, 0);
      ASSERT_EQ(oblique.size(), 1u);
      EXPECT_NEAR(oblique[0].range_m, 2.0, 1e-15);
      EXPECT_NEAR(oblique[0].strength / on[0].strength,
                  std::exp(-0.5 * (12.0 / sigma) * (12.0 / sigma)), 1e-13);
    }
    // The fan (+/-25 deg) bounds what is considered at all.
    const auto inside = model.echo_candidates(
        scene_of({}, {2.0 * Point2(std::cos(24.9 * kDeg), std::sin(24.9 * kDeg))}), Pose2{}, 0);
    EXPECT_EQ(inside.size(), 1u);
    const auto outside = model.echo_candidates(
        scene_of({}, {2.0 * Point2(std::cos(25.1 * kDeg), std::sin(25.1 * kDeg))}), Pose2{}, 0);
    EXPECT_TRUE(outside.empty());
  }
}

// Glass wall A at 45 deg crossing the axis at 2 m turns the axis ray 90 deg to the left onto
// painted wall B, parallel to the axis 1.5 m away (normal incidence there). B ends at x = 3 so
// that no direct ray reaches it (the 25 deg ray meets y = 1.5 at x = 3.2).
SonarScene glass_then_paint() {
  return scene_of({{Point2(1.0, -1.0), Point2(3.0, 1.0)}, {Point2(0.5, 1.5), Point2(3.0, 1.5)}}, {},
                  {builtin_index("glass"), builtin_index("painted_wall")});
}

TEST(SonarModel, MultipathViaGlassReadsTheSumOfBothLegs) {
  const auto g = single_transducer_geometry();
  const SonarModel model(noiseless_sonar_options(), g, 5);
  const SonarScene scene = glass_then_paint();
  const SonarEcho e = model.geometric_echo(scene, Pose2{}, 0);
  ASSERT_TRUE(e.echo);
  EXPECT_TRUE(e.multipath);
  // Out-and-back path 2 (2.0 + 1.5) m: the receiver reports half, t1 + t2 = 3.5 m, not 2 m.
  EXPECT_NEAR(e.range_m, 3.5, 1e-12);
  // Its strength: glass passes on 0.95 of the pulse; B answers square at 3.5 m.
  const double expect = 0.95 * reference_surface_strength(builtin("painted_wall"), 0.0, 3.5, 1.0,
                                                          ray_width_rad(21, 25.0));
  int found = 0;
  for (const EchoCandidate& c : model.echo_candidates(scene, Pose2{}, 0)) {
    if (std::abs(c.range_m - 3.5) < 1e-9) {
      ++found;
      EXPECT_TRUE(c.multipath);
      EXPECT_NEAR(c.strength / expect, 1.0, 1e-9);
    }
    // Nothing nearer is audible: the glass returns at least 20 deg off normal, at most
    // 80 N(20 deg; 4 deg) beam(25 deg) dphi = 1.3e-8 detections per ray.
    if (c.range_m < 3.5 - 1e-9) {
      EXPECT_LT(c.strength, 2e-8) << c.range_m;
    }
  }
  EXPECT_EQ(found, 1);
  // Without multipath the oblique glass is silent.
  SonarModelOptions o = noiseless_sonar_options();
  o.multipath = false;
  const SonarModel direct(o, g, 5);
  EXPECT_FALSE(direct.geometric_echo(scene, Pose2{}, 0).echo);
  EXPECT_LT(direct.echo_probability(scene, Pose2{}, 0), 21 * 2e-8);
}

TEST(SonarModel, ConcaveGlassCornerRetroReflectsNearItsDistance) {
  const auto g = single_transducer_geometry();
  SonarModelOptions o = noiseless_sonar_options();
  o.rays_per_cone = 20;  // no ray straight into the apex
  const SonarModel model(o, g, 6);
  // A 90 deg corner 2 m ahead: wall 1 on x + y = 2, wall 2 on x - y = 2, both 45 deg off the
  // axis, so no single bounce comes back; two mirrors at right angles send the pulse back.
  const int glass = builtin_index("glass");
  const SonarScene scene =
      scene_of({{Point2(2.0, 0.0), Point2(0.0, 2.0)}, {Point2(2.0, 0.0), Point2(0.0, -2.0)}}, {},
               {glass, glass});
  // The ray nearest the axis, phi = 25/19 deg, meets wall 1 at t1 = 2 / (cos + sin), leaves
  // along (-sin, -cos), meets wall 2 after s, and the transducer is t3 = |h2| away from there.
  const double phi = ray_offset_rad(10, 20, 25.0);
  const double t1 = 2.0 / (std::cos(phi) + std::sin(phi));
  const Point2 h1 = t1 * Point2(std::cos(phi), std::sin(phi));
  const double s = (2.0 + h1.y() - h1.x()) / (std::cos(phi) - std::sin(phi));
  const Point2 h2 = h1 + s * Point2(-std::sin(phi), -std::cos(phi));
  const double range = 0.5 * (t1 + s + h2.norm());
  EXPECT_GT(range, 2.0);
  EXPECT_LT(range, 2.001);
  const SonarEcho e = model.geometric_echo(scene, Pose2{}, 0);
  ASSERT_TRUE(e.echo);
  EXPECT_TRUE(e.multipath);
  EXPECT_NEAR(e.range_m, range, 1e-12);
  // Strength: it leaves at phi and arrives from the direction of h2; after two mirrors it travels
  // along -ray, off the line back to the transducer by |phi - arrival|.
  const double arrival = std::atan2(h2.y(), h2.x());
  const SonarMaterial& m = builtin("glass");
  const double strength =
      std::sqrt(reference_beam(phi, 6.0 * kDeg) * reference_beam(arrival, 6.0 * kDeg)) * 0.95 *
      0.95 * m.specular_strength * testing::normal_pdf(phi - arrival, m.specular_lobe_deg * kDeg) *
      ray_width_rad(20, 25.0);
  int found = 0;
  for (const EchoCandidate& c : model.echo_candidates(scene, Pose2{}, 0)) {
    if (std::abs(c.range_m - range) > 1e-12) continue;
    ++found;  // one from each side of the axis
    EXPECT_TRUE(c.multipath);
    EXPECT_NEAR(c.strength / strength, 1.0, 1e-9);
  }
  EXPECT_EQ(found, 2);
  o.multipath = false;
  EXPECT_LT(SonarModel(o, g, 6).echo_probability(scene, Pose2{}, 0), 1e-6);
}

TEST(SonarModel, CornerBehindAWallIsHeardOnlyWithinCornerRadius) {
  const auto g = single_transducer_geometry();
  SonarModelOptions o = noiseless_sonar_options();
  o.multipath = false;
  const SonarModel model(o, g, 1);
  // Glass on y = x - 1.5 crosses the axis at 1.5 m and is silent; corners on the axis behind it.
  const mapper::Segment glass{Point2(0.0, -1.5), Point2(3.0, 1.5)};
  const std::vector<int> mat{builtin_index("glass")};
  auto corner_strength_at = [&](double x) {
    double best = 0.0;
    for (const EchoCandidate& c :
         model.echo_candidates(scene_of({glass}, {Point2(x, 0.0)}, mat), Pose2{}, 0)) {
      if (!c.multipath && std::abs(c.range_m - x) < 1e-12) best = c.strength;
    }
    return best;
  };
  EXPECT_EQ(corner_strength_at(3.0), 0.0);    // hidden
  EXPECT_EQ(corner_strength_at(1.56), 0.0);   // 6 cm behind: beyond the 5 cm radius
  EXPECT_EQ(corner_strength_at(1.54), 20.0);  // 4 cm behind: the corner of that very wall
  EXPECT_EQ(corner_strength_at(1.2), 20.0);   // in front
}

TEST(SonarModel, DetectionGainMultipliesEveryCandidate) {
  const auto g = single_transducer_geometry();
  SonarScene scene = glass_then_paint();
  scene.corners.push_back(Point2(1.5, 0.3));  // in sight, 11.3 deg off the axis
  const SonarModel base(testing::reference_options(), g, 1);
  const auto ref = base.echo_candidates(scene, Pose2{}, 0);
  ASSERT_GT(ref.size(), 21u);
  for (double db : {10.0 * std::log10(2.0), 3.0, -7.5}) {
    SonarModelOptions o = testing::reference_options();
    o.detection_gain_db = db;
    const auto got = SonarModel(o, g, 1).echo_candidates(scene, Pose2{}, 0);
    ASSERT_EQ(got.size(), ref.size());
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_EQ(got[k].range_m, ref[k].range_m);
      EXPECT_EQ(got[k].multipath, ref[k].multipath);
      const double factor = std::pow(10.0, db / 10.0);
      EXPECT_NEAR(got[k].strength, factor * ref[k].strength, 1e-12 * factor * ref[k].strength) << k;
    }
  }
}

TEST(SonarModel, WeakEchoReadsLongByTheThresholdWalk) {
  const auto g = single_transducer_geometry();
  SonarModelOptions o = noiseless_sonar_options();
  o.threshold_walk_m = 0.2;
  o.corner_strength = std::log(4.0 / 3.0);  // a lone corner on the axis: p = 1 - 3/4
  const SonarScene corner = scene_of({}, {Point2(2.0, 0.0)});
  SonarModel model(o, g, 17);
  EXPECT_NEAR(model.echo_probability(corner, Pose2{}, 0), 0.25, 1e-15);
  EXPECT_FALSE(model.geometric_echo(corner, Pose2{}, 0).echo);  // p < 0.5
  SonarModelOptions o45 = o;
  o45.corner_strength = -std::log(0.55);  // p = 0.45: still below the geometric echo's 1/2
  EXPECT_FALSE(SonarModel(o45, g, 1).geometric_echo(corner, Pose2{}, 0).echo);
  constexpr int kPings = 4000;
  int heard = 0;
  for (int i = 0; i < kPings; ++i) {
    const mapper::SonarReading r = model.ping(corner, Pose2{}, 0, 0.0);
    if (!r.echo) continue;
    ++heard;
    EXPECT_NEAR(r.range_m, 2.0 + 0.2 * 0.75, 1e-12);
  }
  // Binomial(4000, 0.25): sd 27.4; 4 sd = 110.
  EXPECT_NEAR(heard, 1000, 110);
  // With range noise on, the mean of the heard readings is still walk (1 - p) long; ~1000 readings
  // of sd hypot(0.01 r, 0.01) = 2.4 cm give a 4-sd tolerance of 3.0 mm.
  o.range_noise_fraction = 0.01;
  o.range_noise_floor_m = 0.01;
  SonarModel noisy(o, g, 18);
  double sum = 0.0;
  int n = 0;
  for (int i = 0; i < kPings; ++i) {
    const mapper::SonarReading r = noisy.ping(corner, Pose2{}, 0, 0.0);
    if (r.echo) {
      sum += r.range_m;
      ++n;
    }
  }
  ASSERT_GT(n, 800);
  EXPECT_NEAR(sum / n - 2.0, 0.15, 4.0 * noisy.range_noise_sd_m(2.15) / std::sqrt(n));
  // Heard more often than not: the deterministic view reads the same walk, 0.2 (1 - 0.6).
  o.corner_strength = std::log(2.5);
  const SonarEcho e = SonarModel(o, g, 1).geometric_echo(corner, Pose2{}, 0);
  ASSERT_TRUE(e.echo);
  EXPECT_NEAR(e.range_m, 2.0 + 0.2 * 0.4, 1e-12);
}

TEST(SonarModel, FirstHeardCandidateWins) {
  const auto g = single_transducer_geometry();
  SonarModelOptions o = noiseless_sonar_options();
  o.threshold_walk_m = 0.2;
  o.corner_strength = 40.0;  // p = 1 - exp(-40), 1.0 in double, on the axis
  // Off the axis by theta the beam leaves ln 2 detections: p = 1/2.
  const double theta = 6.0 * kDeg * std::sqrt(2.0 * std::log(40.0 / std::log(2.0)));
  const SonarScene scene =
      scene_of({}, {1.0 * Point2(std::cos(theta), std::sin(theta)),
                    2.0 * Point2(std::cos(-theta), std::sin(-theta)), Point2(3.0, 0.0)});
  SonarModel model(o, g, 23);
  EXPECT_NEAR(model.echo_probability(scene, Pose2{}, 0), 1.0, 1e-15);
  constexpr int kPings = 8000;
  int at1 = 0, at2 = 0, at3 = 0;
  for (int i = 0; i < kPings; ++i) {
    const mapper::SonarReading r = model.ping(scene, Pose2{}, 0, 0.0);
    ASSERT_TRUE(r.echo);
    if (std::abs(r.range_m - 1.1) < 1e-9) {
      ++at1;
    } else if (std::abs(r.range_m - 2.1) < 1e-9) {
      ++at2;
    } else {
      EXPECT_NEAR(r.range_m, 3.0, 1e-12);
      ++at3;
    }
  }
  // 1/2, 1/4, 1/4 of 8000; binomial sd 44.7 and 38.7: tolerance 4 sd.
  EXPECT_NEAR(at1, 4000, 179);
  EXPECT_NEAR(at2, 2000, 155);
  EXPECT_NEAR(at3, 2000, 155);
}

// A lone corner on the axis with corner_strength 100: heard with p = 1.0 exactly.
SonarScene certain_corner() { return scene_of({}, {Point2(2.0, 0.0)}); }

TEST(SonarModel, DropoutRateMatchesProbability) {
  SonarModelOptions o = testing::reference_options();
  o.dropout_probability = 0.1;
  o.corner_strength = 100.0;
  SonarModel model(o, single_transducer_geometry(), 99);
  constexpr int kPings = 20000;
  int dropped = 0;
  for (int i = 0; i < kPings; ++i) dropped += !model.ping(certain_corner(), Pose2{}, 0, 0.0).echo;
  // Binomial(20000, 0.1): sd 42.4, tolerance 4 sd.
  EXPECT_NEAR(dropped, 2000, 170);
}

// Walls, corners, glass and paint: many candidates, multipath and retro paths.
SonarScene busy_scene() {
  SonarScene s = glass_then_paint();
  for (const auto& seg : wall_at(4.0).surfaces) s.surfaces.push_back(seg);
  s.surface_material.push_back(0);
  s.corners = {Point2(1.5, 0.3), Point2(2.5, -0.4)};
  return s;
}

TEST(SonarModel, EveryPingDrawsANormalAUniformAndASeedWhateverTheScene) {
  // A replica of the main stream: per ping z ~ N(0, 1) (noise), u ~ U(0, 1) (dropout) and one
  // raw draw seeding the detector; scenes with 0 or ~50 candidates in between change nothing.
  SonarModelOptions o = testing::reference_options();
  o.range_noise_fraction = 0.0;
  o.range_noise_floor_m = 0.01;
  o.dropout_probability = 0.3;
  o.threshold_walk_m = 0.0;
  o.corner_strength = 100.0;
  SonarModel model(o, single_transducer_geometry(), 1234);
  std::mt19937_64 replica(1234);
  const SonarScene probe = certain_corner(), busy = busy_scene(), empty = scene_of({});
  int checked = 0;
  for (int k = 0; k < 300; ++k) {
    const SonarScene& s = k % 3 == 0 ? probe : k % 3 == 1 ? busy : empty;
    const double z = std::normal_distribution<double>(0.0, 1.0)(replica);
    const double u = std::uniform_real_distribution<double>(0.0, 1.0)(replica);
    replica();
    const double x = 0.1 * (k % 5);
    const mapper::SonarReading r = model.ping(s, Pose2{x, 0.0, 0.0}, 0, 0.0);
    if (k % 3 != 0) continue;
    ASSERT_EQ(r.echo, u >= 0.3) << k;
    if (r.echo) {
      EXPECT_NEAR(r.range_m, 2.0 - x + 0.01 * z, 1e-12) << k;
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);  // ~70 of the 100 probe pings pass the dropout
}

TEST(SonarModel, SameSeedSameReadingsWhateverWasPingedBefore) {
  const auto g = mapper::p2at_geometry();
  SonarModel a(testing::reference_options(), g, 5), b(testing::reference_options(), g, 5),
      c(testing::reference_options(), g, 6);
  for (int i = 0; i < 50; ++i) {
    a.ping(scene_of({}), Pose2{}, i % 16, 0.0);
    b.ping(busy_scene(), Pose2{0.1, 0.2, 0.01 * i}, (3 * i) % 16, 0.0);
    c.ping(scene_of({}), Pose2{}, i % 16, 0.0);
  }
  bool differs = false;
  for (int i = 0; i < 50; ++i) {
    const Pose2 p{0.05 * i, 0.0, 0.1};
    const auto ra = a.ping(busy_scene(), p, i % 16, 0.0);
    const auto rb = b.ping(busy_scene(), p, i % 16, 0.0);
    const auto rc = c.ping(busy_scene(), p, i % 16, 0.0);
    EXPECT_EQ(ra.range_m, rb.range_m) << i;
    EXPECT_EQ(ra.echo, rb.echo) << i;
    differs = differs || ra.range_m != rc.range_m;
  }
  EXPECT_TRUE(differs);
}

TEST(SonarModel, ReadingsStayWithinMinAndMaxRange) {
  // A wall 5 cm ahead is inside the receiver's blanking: it reads exactly min range, 0.1 m.
  SonarModel blanked(noiseless_sonar_options(), single_transducer_geometry(), 7);
  for (int i = 0; i < 50; ++i) {
    const mapper::SonarReading r = blanked.ping(wall_at(0.05), Pose2{}, 0, 0.0);
    EXPECT_TRUE(r.echo);
    EXPECT_EQ(r.range_m, 0.1);
  }
  const auto g = mapper::p2at_geometry();
  SonarModelOptions o = testing::reference_options();
  o.range_noise_fraction = 0.3;  // exaggerated so the clamps are exercised
  SonarModel model(o, g, 7);
  // A 6 x 4 m room with a pillar: random poses, every transducer.
  const SonarScene room = scene_of({{{-3, -2}, {3, -2}},
                                    {{3, -2}, {3, 2}},
                                    {{3, 2}, {-3, 2}},
                                    {{-3, 2}, {-3, -2}},
                                    {{1, 0}, {1.3, 0}},
                                    {{1.3, 0}, {1.3, 0.3}}},
                                   {{1.3, 0}});
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> ux(-2.5, 2.5), uy(-1.5, 1.5), ut(-3.14, 3.14);
  for (int i = 0; i < 2000; ++i) {
    const mapper::SonarReading r = model.ping(room, Pose2{ux(rng), uy(rng), ut(rng)}, i % 16, 0.0);
    EXPECT_GE(r.range_m, g.sonar_min_range_m);
    EXPECT_LE(r.range_m, g.sonar_max_range_m);
    if (!r.echo) {
      EXPECT_EQ(r.range_m, g.sonar_max_range_m);
    }
  }
}

TEST(SonarModel, NothingBeyondACertainEchoIsListed) {
  // A corner on the axis with strength >= 37 is heard with p = 1.0 in double: the receiver
  // always triggers on it, so the wall behind it is never listed; a weaker corner lets it be.
  const auto g = single_transducer_geometry();
  SonarModelOptions o = testing::reference_options();
  const SonarScene scene = scene_of({{Point2(3.0, -4.0), Point2(3.0, 4.0)}}, {Point2(1.0, 0.0)});
  o.corner_strength = 40.0;
  const auto certain = SonarModel(o, g, 1).echo_candidates(scene, Pose2{}, 0);
  ASSERT_EQ(certain.size(), 1u);
  EXPECT_EQ(certain[0].range_m, 1.0);
  o.corner_strength = 30.0;  // p = 1 - 9.4e-14 < 1
  const auto heard = SonarModel(o, g, 1).echo_candidates(scene, Pose2{}, 0);
  ASSERT_EQ(heard.size(), 22u);  // the corner and one direct echo per ray
  EXPECT_EQ(heard[1].range_m, 3.0);
}

}  // namespace
}  // namespace cogmap::sim
