// Sonar materials: the built-in table, how a scene maps surfaces to materials, what each material
// does to the echoes (strengths worked out by the formulas of docs/sonar-model.md, written out in
// sonar_test_support.h), and that a world file's materials reach the sonar's scene.
#include "cogmap/sim/sonar_material.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cogmap/sim/sonar_model.h"
#include "cogmap/sim/world_geometry.h"
#include "cogmap/sim/world_spec.h"
#include "sonar_test_support.h"

namespace cogmap::sim {
namespace {

using mapper::Point2;
using mapper::Pose2;
using testing::builtin_index;
using testing::kDeg;
using testing::ray_offset_rad;
using testing::ray_width_rad;
using testing::reference_beam;
using testing::reference_surface_strength;
using testing::scene_of;
using testing::single_transducer_geometry;

using testing::builtin;

TEST(SonarMaterial, BuiltinTable) {
  const auto& t = builtin_sonar_materials();
  ASSERT_EQ(t.size(), 5u);
  const std::vector<std::string> names{"painted_wall", "wood", "glass", "metal", "fabric"};
  for (std::size_t i = 0; i < t.size(); ++i) EXPECT_EQ(t[i].name, names[i]);
  EXPECT_EQ(t[0].name, kDefaultSonarMaterial);
  for (const SonarMaterial& m : t) {
    EXPECT_GT(m.specular_strength, 0.0) << m.name;
    EXPECT_GT(m.specular_lobe_deg, 0.0) << m.name;
    EXPECT_GE(m.diffuse_strength, 0.0) << m.name;
    EXPECT_GE(m.mirror_reflectivity, 0.0) << m.name;
    EXPECT_LE(m.mirror_reflectivity, 1.0) << m.name;
  }
  EXPECT_EQ(builtin("glass").diffuse_strength, 0.0);  // a perfect mirror: no backscatter
  // The default is the calibrated wall (sonar_material.h): pin it, a change must be deliberate.
  const SonarMaterial& p = t[0];
  EXPECT_EQ(p.specular_strength, 60.0);
  EXPECT_EQ(p.specular_lobe_deg, 6.0);
  EXPECT_EQ(p.diffuse_strength, 8.0);
  EXPECT_EQ(p.diffuse_incidence_exponent, 0.5);
  EXPECT_EQ(p.mirror_reflectivity, 0.5);
}

TEST(SonarMaterial, FindAndListNames) {
  const auto& t = builtin_sonar_materials();
  EXPECT_EQ(find_sonar_material(t, "painted_wall"), 0);
  EXPECT_EQ(find_sonar_material(t, "glass"), 2);
  EXPECT_EQ(find_sonar_material(t, "fabric"), 4);
  EXPECT_FALSE(find_sonar_material(t, "Glass").has_value());
  EXPECT_FALSE(find_sonar_material(t, "").has_value());
  EXPECT_EQ(sonar_material_names(t), "painted_wall, wood, glass, metal, fabric");
  EXPECT_EQ(sonar_material_names({}), "");
  std::vector<SonarMaterial> custom = t;
  custom.push_back(SonarMaterial{"felt", 1.0, 20.0, 1.0, 1.0, 0.0});
  EXPECT_EQ(find_sonar_material(custom, "felt"), 5);
  EXPECT_EQ(sonar_material_names(custom), "painted_wall, wood, glass, metal, fabric, felt");
}

TEST(SonarMaterial, SceneMapsSurfacesToMaterials) {
  const mapper::Segment s{Point2(0, 0), Point2(1, 0)};
  const SonarScene plain = scene_of({s, s});
  EXPECT_EQ(plain.material_of(0).name, "painted_wall");
  EXPECT_EQ(plain.material_of(1).name, "painted_wall");
  const SonarScene builtins = scene_of({s, s}, {}, {2, 3});
  EXPECT_EQ(builtins.material_of(0).name, "glass");
  EXPECT_EQ(builtins.material_of(1).name, "metal");
  const SonarScene own =
      scene_of({s, s}, {}, {1, 0},
               {SonarMaterial{"a", 1, 2, 3, 4, 0.1}, SonarMaterial{"b", 5, 6, 7, 8, 0.2}});
  EXPECT_EQ(own.material_of(0).name, "b");
  EXPECT_EQ(own.material_of(0).diffuse_incidence_exponent, 8.0);
  EXPECT_EQ(own.material_of(1).name, "a");
  const SonarScene first_of_own = scene_of({s}, {}, {}, {SonarMaterial{"only", 1, 2, 3, 4, 0.1}});
  EXPECT_EQ(first_of_own.material_of(0).name, "only");
}

// A wall on y = x - c seen by the single transducer (origin, along +x): ray phi meets it at
// t = c / (cos phi - sin phi) with incidence 45 deg + phi, if within the 5 m range.
struct Expected {
  double range_m, strength;
};
std::vector<Expected> wall_45(const SonarMaterial& m, double c, double g = 1.0) {
  std::vector<Expected> out;
  for (int i = 0; i < 21; ++i) {
    const double phi = ray_offset_rad(i, 21, 25.0);
    const double t = c / (std::cos(phi) - std::sin(phi));
    if (t > 5.0) continue;
    out.push_back(
        {t, reference_beam(phi, 6.0 * kDeg) *
                reference_surface_strength(m, 45.0 * kDeg + phi, t, g, ray_width_rad(21, 25.0))});
  }
  return out;  // nearest first: t grows with phi
}

double total(const std::vector<Expected>& e) {
  double s = 0.0;
  for (const Expected& x : e) s += x.strength;
  return s;
}

SonarScene wall_45_scene(const char* material) {
  const Point2 d(std::sqrt(0.5), std::sqrt(0.5));
  return scene_of({{Point2(2.0, 0.0) - 6.0 * d, Point2(2.0, 0.0) + 6.0 * d}}, {},
                  {builtin_index(material)});
}

TEST(SonarMaterial, GlassAt45DegreesHasNoDirectEcho) {
  const SonarModel model(testing::reference_options(), single_transducer_geometry(), 1);
  const SonarScene scene = wall_45_scene("glass");
  const auto got = model.echo_candidates(scene, Pose2{}, 0);
  const auto expect = wall_45(builtin("glass"), 2.0);
  ASSERT_EQ(got.size(), 21u);
  ASSERT_EQ(expect.size(), 21u);
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_FALSE(got[k].multipath);  // the mirrored pulse leaves: no bounce comes back
    EXPECT_NEAR(got[k].range_m, expect[k].range_m, 1e-12) << k;
    // The model drops the mirror lobe beyond 8 sd (80 N(8 sd) dphi < 3e-13): absolute slack.
    EXPECT_NEAR(got[k].strength, expect[k].strength, 1e-9 * expect[k].strength + 3e-13) << k;
    // No backscatter; the lobe (4 deg) is >= 20 deg = 5 sd away: 80 N(20;4) beam(25) dphi.
    EXPECT_LT(got[k].strength, 2e-8) << k;
  }
  EXPECT_LT(model.echo_probability(scene, Pose2{}, 0), 21 * 2e-8);
  EXPECT_FALSE(model.geometric_echo(scene, Pose2{}, 0).echo);
}

TEST(SonarMaterial, PaintedWallAt45DegreesIsHeardByBackscatter) {
  SonarModelOptions o = testing::reference_options();
  o.dropout_probability = 0.0;
  SonarModel model(o, single_transducer_geometry(), 3);
  const SonarScene scene = wall_45_scene("painted_wall");
  const auto got = model.echo_candidates(scene, Pose2{}, 0);
  const auto expect = wall_45(builtin("painted_wall"), 2.0);
  ASSERT_EQ(got.size(), expect.size());
  for (std::size_t k = 0; k < got.size(); ++k) {
    EXPECT_NEAR(got[k].range_m, expect[k].range_m, 1e-12) << k;
    EXPECT_NEAR(got[k].strength / expect[k].strength, 1.0, 1e-9) << k;
  }
  const double p = -std::expm1(-total(expect));  // 1 - prod(1 - p_i) = 1 - exp(-sum s_i)
  EXPECT_NEAR(model.echo_probability(scene, Pose2{}, 0), p, 1e-14);
  EXPECT_GT(p, 0.9);
  // The pings hear it that often: Binomial(4000, p ~ 0.93), tolerance 4 sd.
  constexpr int kPings = 4000;
  int heard = 0;
  for (int i = 0; i < kPings; ++i) heard += model.ping(scene, Pose2{}, 0, 0.0).echo;
  EXPECT_NEAR(heard, kPings * p, 4.0 * std::sqrt(kPings * p * (1.0 - p)));
}

TEST(SonarMaterial, DiffuseExponentsAndReflectivityComeFromTheMaterial) {
  // A custom rough material: no mirror lobe, D = 2, cos^3, with (r / 1 m)^2 range gain.
  const SonarMaterial felt{"felt", 0.0, 6.0, 2.0, 3.0, 0.0};
  SonarModelOptions o = testing::reference_options();
  o.diffuse_range_gain_exponent = 2.0;
  const SonarModel model(o, single_transducer_geometry(), 1);
  const SonarScene scene = scene_of({{Point2(-4.0, 6.0), Point2(8.0, -6.0)}}, {}, {1},
                                    {builtin("painted_wall"), felt});  // on x + y = 2
  const auto got = model.echo_candidates(scene, Pose2{}, 0);
  // Ray phi meets x + y = 2 at t = 2 / (cos + sin), 45 deg - phi off its normal.
  ASSERT_EQ(got.size(), 21u);
  for (std::size_t k = 0; k < got.size(); ++k) {
    const double phi = ray_offset_rad(20 - static_cast<int>(k), 21, 25.0);  // nearest: +25
    const double t = 2.0 / (std::cos(phi) + std::sin(phi));
    const double s = reference_beam(phi, 6.0 * kDeg) * 2.0 *
                     std::pow(std::cos(45 * kDeg - phi), 3) * t * t * ray_width_rad(21, 25.0);
    EXPECT_NEAR(got[k].range_m, t, 1e-12) << k;
    EXPECT_NEAR(got[k].strength / s, 1.0, 1e-9) << k;
    EXPECT_FALSE(got[k].multipath);  // mirror_reflectivity 0: nothing goes on
  }
}

TEST(SonarMaterial, MultipathScalesWithTheFirstSurfacesReflectivity) {
  // A mirror at 45 deg crossing the axis at 2 m, a painted wall 1.5 m to the left (as in
  // sonar_model_test): the bounce echo at 3.5 m carries the first surface's reflectivity.
  const SonarModel model(testing::noiseless_sonar_options(), single_transducer_geometry(), 1);
  auto bounce = [&](double reflectivity) {
    SonarMaterial mirror = builtin("glass");
    mirror.mirror_reflectivity = reflectivity;
    const SonarScene scene =
        scene_of({{Point2(1.0, -1.0), Point2(3.0, 1.0)}, {Point2(0.5, 1.5), Point2(3.0, 1.5)}}, {},
                 {1, 0}, {builtin("painted_wall"), mirror});
    for (const EchoCandidate& c : model.echo_candidates(scene, Pose2{}, 0)) {
      if (c.multipath && std::abs(c.range_m - 3.5) < 1e-9) return c.strength;
    }
    return 0.0;
  };
  const double square =
      reference_surface_strength(builtin("painted_wall"), 0.0, 3.5, 1.0, ray_width_rad(21, 25.0));
  EXPECT_NEAR(bounce(0.95) / (0.95 * square), 1.0, 1e-9);
  EXPECT_NEAR(bounce(0.3) / (0.3 * square), 1.0, 1e-9);
  EXPECT_EQ(bounce(0.0), 0.0);
}

// One straight wall along y = x - 3 (thickness 0.12): its near face lies on y = x - c.
std::string diagonal_world(const std::string& material_line) {
  return "name: diag\n" + material_line +
         "walls:\n"
         "  polylines:\n"
         "    - [[0, -3], [6, 3]]\n"
         "start: {x_m: 0, y_m: 0}\n";
}

TEST(SonarMaterial, WorldMaterialReachesTheSonar) {
  const double c = 3.0 - 0.06 * std::sqrt(2.0);
  const SonarModel model(testing::reference_options(), single_transducer_geometry(), 1);
  const SonarScene glass = surface_segments(
      parse_world(yaml::Node::load_string(diagonal_world("material: glass\n"), "g.yaml")));
  const SonarScene paint =
      surface_segments(parse_world(yaml::Node::load_string(diagonal_world(""), "p.yaml")));
  ASSERT_EQ(glass.surfaces.size(), 4u);  // two faces, two end caps
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(glass.material_of(i).name, "glass");
    EXPECT_EQ(paint.material_of(i).name, "painted_wall");
  }
  // Only the near face is in the fan and in range; its ends and the far face are not.
  EXPECT_NEAR(model.echo_probability(glass, Pose2{}, 0),
              -std::expm1(-total(wall_45(builtin("glass"), c))), 21 * 3e-13);  // lobe cut at 8 sd
  EXPECT_LT(model.echo_probability(glass, Pose2{}, 0), 1e-6);
  const auto painted = wall_45(builtin("painted_wall"), c);
  ASSERT_EQ(painted.size(), 19u);  // the rays at 22.5 and 25 deg meet the face beyond 5 m
  EXPECT_NEAR(model.echo_probability(paint, Pose2{}, 0), -std::expm1(-total(painted)), 1e-14);
  EXPECT_GT(model.echo_probability(paint, Pose2{}, 0), 0.9);
}

// Which material a surface should have, from where its midpoint lies in the world below.
TEST(SonarMaterial, WorldSurfacesCarryTheirMaterial) {
  const WorldSpec w = parse_world(
      yaml::Node::load_string("name: m\n"
                              "material: wood\n"
                              "materials:\n"
                              "  frosted: {like: glass, diffuse_strength: 0.5}\n"
                              "walls:\n"
                              "  polylines:\n"
                              "    - [[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]]\n"
                              "    - {points: [[5, 0], [5, 3]], material: frosted}\n"
                              "obstacles:\n"
                              "  - {box: {center: [2, 4], size: [1, 1]}, material: metal}\n"
                              "  - {circle: {center: [8, 4], radius_m: 0.5}}\n"
                              "start: {x_m: 1, y_m: 1}\n",
                              "m.yaml"));
  ASSERT_EQ(w.materials.size(), 6u);
  EXPECT_EQ(w.materials[5].name, "frosted");
  const WorldSurfaces ws = world_surfaces(w);
  const SonarScene scene = surface_segments(w);
  ASSERT_EQ(ws.surface_material.size(), ws.surfaces.size());
  ASSERT_EQ(scene.surface_material, ws.surface_material);
  ASSERT_EQ(scene.materials.size(), w.materials.size());
  for (std::size_t i = 0; i < w.materials.size(); ++i) {
    EXPECT_EQ(scene.materials[i].name, w.materials[i].name);
  }
  int counts[6] = {0, 0, 0, 0, 0, 0};
  for (std::size_t i = 0; i < ws.surfaces.size(); ++i) {
    const Point2 mid = 0.5 * (ws.surfaces[i].a + ws.surfaces[i].b);
    int expect = 1;  // wood: the room's walls and the circle (the world default)
    if (mid.x() > 1.49 && mid.x() < 2.51 && mid.y() > 3.49 && mid.y() < 4.51) expect = 3;
    if (std::abs(mid.x() - 5.0) < 0.061 && mid.y() > 0.05 && mid.y() < 3.01) expect = 5;
    EXPECT_EQ(ws.surface_material[i], expect) << mid.transpose();
    EXPECT_EQ(scene.material_of(static_cast<int>(i)).name, w.materials[expect].name);
    ++counts[expect];
  }
  EXPECT_EQ(counts[3], 4);  // the box's four sides
  EXPECT_EQ(counts[5], 3);  // the partition's two faces above the wall and its end cap
  // Wood: the room's 8 faces, the inner bottom one cut in two by the partition; 48 circle facets.
  EXPECT_EQ(counts[1], 9 + 48);
  EXPECT_EQ(scene.materials[5].diffuse_strength, 0.5);
  EXPECT_EQ(scene.materials[5].specular_lobe_deg, builtin("glass").specular_lobe_deg);
}

TEST(SonarMaterial, OverridingABuiltinStartsFromIt) {
  // `glass: {mirror_reflectivity: 0.9}` changes one value of glass, not painted_wall's others.
  const WorldSpec w = parse_world(
      yaml::Node::load_string("name: m\nmaterials:\n  glass: {mirror_reflectivity: 0.9}\n"
                              "walls: {polylines: []}\nstart: {x_m: 0, y_m: 0, theta_deg: 0}\n",
                              "m.yaml"));
  const int glass = *find_sonar_material(w.materials, "glass");
  const SonarMaterial& builtin = builtin_sonar_materials()[static_cast<std::size_t>(glass)];
  EXPECT_EQ(w.materials.size(), builtin_sonar_materials().size());
  EXPECT_EQ(w.materials[static_cast<std::size_t>(glass)].mirror_reflectivity, 0.9);
  EXPECT_EQ(w.materials[static_cast<std::size_t>(glass)].diffuse_strength,
            builtin.diffuse_strength);
  EXPECT_EQ(w.materials[static_cast<std::size_t>(glass)].specular_lobe_deg,
            builtin.specular_lobe_deg);
}

}  // namespace
}  // namespace cogmap::sim
