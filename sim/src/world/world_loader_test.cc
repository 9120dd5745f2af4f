#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cogmap/sim/world_spec.h"
#include "world/world_test_support.h"

namespace cogmap::sim {
namespace {

using testing::parse;

// Parses `text`, expects a ConfigError, returns it for inspection.
yaml::ConfigError config_error_of_world(const std::string& text) {
  try {
    parse(text);
  } catch (const yaml::ConfigError& e) {
    return e;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return yaml::ConfigError("", 0, "", "");
}

const std::string kHeader =
    "name: t\n"                                            // line 1
    "walls:\n"                                             // line 2
    "  polylines:\n"                                       // line 3
    "    - [[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]]\n";  // line 4

TEST(WorldLoader, ParsesEveryElement) {
  const WorldSpec w = parse(
      "name: two\n"
      "description: d\n"
      "walls:\n"
      "  thickness_m: 0.2\n"
      "  polylines:\n"
      "    - [[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]]\n"
      "    - {points: [[7, 6], [7, 4]], thickness_m: 0.05}\n"
      "obstacles:\n"
      "  - {box: {center: [2.0, 4.5], size: [1.2, 0.6], angle_deg: 90}}\n"
      "  - {circle: {center: [8.0, 1.5], radius_m: 0.25}}\n"
      "  - {polygon: [[3, 1], [3.5, 1], [3.2, 1.6]]}\n"
      "start: {x_m: 1.0, y_m: 1.0, theta_deg: 90}\n");
  EXPECT_EQ(w.name, "two");
  EXPECT_EQ(w.description, "d");
  ASSERT_EQ(w.walls.size(), 2u);
  EXPECT_DOUBLE_EQ(w.walls[0].thickness_m, 0.2);
  EXPECT_TRUE(w.walls[0].closed());
  EXPECT_DOUBLE_EQ(w.walls[1].thickness_m, 0.05);
  EXPECT_FALSE(w.walls[1].closed());
  EXPECT_EQ(w.walls[1].source.line, 7);
  ASSERT_EQ(w.obstacles.size(), 3u);
  const auto& box = std::get<BoxObstacle>(w.obstacles[0].shape);
  EXPECT_DOUBLE_EQ(box.length_m, 1.2);
  EXPECT_DOUBLE_EQ(box.angle_rad, std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(std::get<CircleObstacle>(w.obstacles[1].shape).radius_m, 0.25);
  EXPECT_EQ(std::get<PolygonObstacle>(w.obstacles[2].shape).points.size(), 3u);
  EXPECT_EQ(w.obstacles[2].source.key, "obstacles[2]");
  EXPECT_DOUBLE_EQ(w.start.x_m, 1.0);
  EXPECT_DOUBLE_EQ(w.start.theta_rad, std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(w.walls[0].thickness_m, 0.2);
}

TEST(WorldLoader, DefaultThicknessApplies) {
  const WorldSpec w = parse(kHeader + "start: {x_m: 1, y_m: 1}\n");
  EXPECT_DOUBLE_EQ(w.walls[0].thickness_m, kDefaultWallThicknessM);
  EXPECT_DOUBLE_EQ(w.start.theta_rad, 0.0);
}

TEST(WorldLoader, UnknownKeyNamesFileLineAndKey) {
  const auto e = config_error_of_world(kHeader + "start: {x_m: 1, y_m: 1, theta: 0}\n");
  EXPECT_EQ(e.line(), 5);
  EXPECT_EQ(e.key(), "start.theta");
  EXPECT_NE(std::string(e.what()).find("w.yaml:5: start.theta: unknown key"), std::string::npos)
      << e.what();
  const auto top = config_error_of_world(kHeader + "strat: {x_m: 1, y_m: 1}\n");
  EXPECT_EQ(top.key(), "strat");
  EXPECT_EQ(top.line(), 5);
}

TEST(WorldLoader, WrongTypeNamesKey) {
  const auto e = config_error_of_world(kHeader + "start: {x_m: one, y_m: 1}\n");
  EXPECT_EQ(e.key(), "start.x_m");
  EXPECT_EQ(e.line(), 5);
  EXPECT_NE(std::string(e.what()).find("expected a finite number"), std::string::npos);
  const auto p = config_error_of_world(
      "name: t\nwalls:\n  polylines:\n    - [[0, 0], [1]]\nstart: {x_m: 5, y_m: 5}\n");
  EXPECT_EQ(p.key(), "walls.polylines[0][1]");
  EXPECT_EQ(p.line(), 4);
  EXPECT_NE(std::string(p.what()).find("expected a point [x, y]"), std::string::npos);
}

// A pile of obstacles at one spot (found by fuzzing: 3 000 boxes there did not load in 30 s)
// is refused at the obstacle that tips it over; as many side by side load.
TEST(WorldLoader, APileOfObstaclesIsRefusedAtItsLine) {
  const auto world = [](bool piled) {
    std::string text = kHeader + "obstacles:\n";              // line 5
    for (std::size_t i = 0; i < kMaxObstaclePile + 2; ++i) {  // each overlaps all the others
      const double x = piled ? 5.0 : 0.5 + 0.14 * static_cast<double>(i);
      text += "  - {box: {center: [" + std::to_string(x) + ", 3], size: [0.1, 0.1]}}\n";
    }
    return text + "start: {x_m: 5, y_m: 1}\n";
  };
  EXPECT_EQ(parse(world(false)).obstacles.size(), kMaxObstaclePile + 2);
  const auto e = config_error_of_world(world(true));
  // The first obstacle meets its 65th overlap with the last one: it is named.
  EXPECT_EQ(e.key(), "obstacles[0]");
  EXPECT_EQ(e.line(), 6);
  EXPECT_NE(std::string(e.what()).find("overlap those of more than 64 other obstacles"),
            std::string::npos)
      << e.what();
}

// Walls laid over one another by the thousand (1 500 along one line took 226 s to load, since
// 10.7 s; tens of thousands would not finish) are refused at the first wall whose piece touches
// more than kMaxWallPile others; as many short walls apart load.
TEST(WorldLoader, APileOfWallsIsRefusedAtItsLine) {
  const auto world = [](bool piled) {
    std::string text = kHeader;                           // walls[0] on line 4
    for (std::size_t i = 0; i < kMaxWallPile + 2; ++i) {  // each touches all the others
      const double d = static_cast<double>(i);
      if (piled) {
        text += "    - [[" + std::to_string(1 + 0.001 * d) + ", 3], [" +
                std::to_string(6 + 0.001 * d) + ", 3]]\n";
      } else {  // 0.1 m walls on a 0.3 m grid, clear of one another and of the room's walls
        const double x = 0.3 + 0.3 * static_cast<double>(i % 32), y = 0.3 + 0.3 * (i / 32);
        text += "    - [[" + std::to_string(x) + ", " + std::to_string(y) + "], [" +
                std::to_string(x + 0.1) + ", " + std::to_string(y) + "]]\n";
      }
    }
    return text + "start: {x_m: 9.5, y_m: 5.6}\n";
  };
  EXPECT_EQ(parse(world(false)).walls.size(), kMaxWallPile + 3);
  const auto e = config_error_of_world(world(true));
  // The first piled wall meets its 513th neighbour last: it is named.
  EXPECT_EQ(e.line(), 5);
  EXPECT_NE(std::string(e.what()).find("touches more than 512 other wall pieces"),
            std::string::npos)
      << e.what();
}

TEST(WorldLoader, MissingKeyIsAnError) {
  const auto e = config_error_of_world(kHeader);
  EXPECT_NE(std::string(e.what()).find("missing required key 'start'"), std::string::npos);
}

TEST(WorldLoader, DegenerateWallsAreErrors) {
  const auto one = config_error_of_world(
      "name: t\nwalls:\n  polylines:\n    - [[0, 0]]\nstart: {x_m: 5, y_m: 5}\n");
  EXPECT_EQ(one.key(), "walls.polylines[0]");
  EXPECT_EQ(one.line(), 4);
  EXPECT_NE(std::string(one.what()).find("at least 2 points"), std::string::npos);

  const auto zero = config_error_of_world(
      "name: t\nwalls:\n  polylines:\n    - [[0, 0], [1, 0],\n       [1, 0]]\n"
      "start: {x_m: 5, y_m: 5}\n");
  EXPECT_EQ(zero.key(), "walls.polylines[0][2]");
  EXPECT_EQ(zero.line(), 5);
  EXPECT_NE(std::string(zero.what()).find("zero-length wall segment"), std::string::npos);

  const auto thin = config_error_of_world(
      "name: t\nwalls:\n  thickness_m: 0\n  polylines: []\nstart: {x_m: 5, y_m: 5}\n");
  EXPECT_EQ(thin.key(), "walls.thickness_m");
  EXPECT_EQ(thin.line(), 3);
}

TEST(WorldLoader, DegenerateObstaclesAreErrors) {
  const std::string head = kHeader + "obstacles:\n";  // obstacles start on line 6
  const std::string start = "start: {x_m: 1, y_m: 1}\n";
  const auto box =
      config_error_of_world(head + "  - {box: {center: [5, 3], size: [1, -0.5]}}\n" + start);
  EXPECT_EQ(box.key(), "obstacles[0].box.size");
  EXPECT_EQ(box.line(), 6);
  EXPECT_NE(std::string(box.what()).find("box size must be positive"), std::string::npos);

  const auto circle =
      config_error_of_world(head + "  - {circle: {center: [5, 3], radius_m: 0}}\n" + start);
  EXPECT_EQ(circle.key(), "obstacles[0].circle.radius_m");
  EXPECT_NE(std::string(circle.what()).find("radius must be positive"), std::string::npos);

  const auto two = config_error_of_world(head + "  - {polygon: [[5, 3], [6, 3]]}\n" + start);
  EXPECT_EQ(two.key(), "obstacles[0].polygon");
  EXPECT_NE(std::string(two.what()).find("at least 3"), std::string::npos);

  const auto flat =
      config_error_of_world(head + "  - {polygon: [[5, 3], [6, 3], [7, 3]]}\n" + start);
  EXPECT_NE(std::string(flat.what()).find("zero area"), std::string::npos);

  // A lopsided bow tie (non-zero area): edges (5,3)-(7,4) and (7,3)-(5,5) cross.
  const auto bow =
      config_error_of_world(head + "  - {polygon: [[5, 3], [7, 4], [7, 3], [5, 5]]}\n" + start);
  EXPECT_EQ(bow.line(), 6);
  EXPECT_NE(std::string(bow.what()).find("self-intersecting"), std::string::npos);

  const auto both =
      config_error_of_world(head +
                            "  - {box: {center: [5, 3], size: [1, 1]}, circle: {center: [5, 3], "
                            "radius_m: 1}}\n" +
                            start);
  EXPECT_NE(std::string(both.what()).find("exactly one of"), std::string::npos);
}

TEST(WorldLoader, StartInsideObstacleIsAnError) {
  const auto e = config_error_of_world(kHeader +
                                       "obstacles:\n"
                                       "  - {box: {center: [2, 2], size: [2, 2]}}\n"  // line 6
                                       "start: {x_m: 2.0, y_m: 2.5}\n");              // line 7
  EXPECT_EQ(e.line(), 7);
  EXPECT_EQ(e.key(), "start");
  EXPECT_NE(std::string(e.what()).find("w.yaml:7: start: start (2.00, 2.50) is inside obstacle "
                                       "obstacles[0] (line 6)"),
            std::string::npos)
      << e.what();
}

TEST(WorldLoader, StartTooCloseToWallIsAnError) {
  // The wall's inner face is at y = 0.06; 0.2 m from it is less than half the robot's width.
  const auto e = config_error_of_world(kHeader + "start: {x_m: 5, y_m: 0.26}\n");
  EXPECT_EQ(e.line(), 5);
  EXPECT_NE(std::string(e.what()).find("is only 0.200 m from wall walls.polylines[0] (line 4)"),
            std::string::npos)
      << e.what();
  EXPECT_NO_THROW(parse(kHeader + "start: {x_m: 5, y_m: 0.32}\n"));
  const auto inside = config_error_of_world(kHeader + "start: {x_m: 5, y_m: 0.0}\n");
  EXPECT_NE(std::string(inside.what()).find("is inside wall"), std::string::npos);
}

TEST(WorldLoader, StartNearCircleUsesTrueRadius) {
  const std::string w = kHeader + "obstacles:\n  - {circle: {center: [5, 3], radius_m: 0.5}}\n";
  EXPECT_THROW(parse(w + "start: {x_m: 5.7, y_m: 3}\n"), yaml::ConfigError);
  EXPECT_NO_THROW(parse(w + "start: {x_m: 5.8, y_m: 3}\n"));
}

TEST(WorldLoader, LoadFileNamesThePath) {
  try {
    load_world("/nonexistent/world.yaml");
    FAIL();
  } catch (const yaml::ConfigError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/world.yaml");
  }
}

TEST(WorldLoader, ObstacleOutlines) {
  Obstacle box{BoxObstacle{{1.0, 2.0}, 2.0, 1.0, 0.0}, 0, {}};
  const mapper::Polyline o = obstacle_outline(box);
  ASSERT_EQ(o.size(), 4u);
  EXPECT_DOUBLE_EQ(o[0].x(), 2.0);
  EXPECT_DOUBLE_EQ(o[0].y(), 2.5);
  EXPECT_DOUBLE_EQ(o[2].x(), 0.0);
  EXPECT_DOUBLE_EQ(o[2].y(), 1.5);
  Obstacle circle{CircleObstacle{{0.0, 0.0}, 1.0}, 0, {}};
  const mapper::Polyline c = obstacle_outline(circle, 48);
  ASSERT_EQ(c.size(), 48u);
  for (const auto& p : c) EXPECT_NEAR(p.norm(), 1.0, 1e-12);
}

// Sonar materials (docs/sonar-model.md "Materials"): the world default, per polyline, per
// obstacle, and the world's own `materials:` table.
TEST(WorldLoader, MaterialsDefaultToPaintedWall) {
  const WorldSpec w = parse(kHeader +
                            "obstacles:\n  - {circle: {center: [5, 3], radius_m: 0.5}}\n"
                            "start: {x_m: 1, y_m: 1}\n");
  const auto& builtins = builtin_sonar_materials();
  ASSERT_EQ(w.materials.size(), builtins.size());
  for (std::size_t i = 0; i < builtins.size(); ++i)
    EXPECT_EQ(w.materials[i].name, builtins[i].name);
  EXPECT_EQ(w.materials[0].name, "painted_wall");
  EXPECT_EQ(w.walls[0].material, 0);
  EXPECT_EQ(w.obstacles[0].material, 0);
}

TEST(WorldLoader, WorldPolylineAndObstacleMaterials) {
  const WorldSpec w = parse(
      "name: m\n"
      "material: wood\n"
      "walls:\n"
      "  polylines:\n"
      "    - [[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]]\n"
      "    - {points: [[5, 0], [5, 3]], material: glass}\n"
      "    - {points: [[7, 6], [7, 5]], material: painted_wall, thickness_m: 0.05}\n"
      "obstacles:\n"
      "  - {box: {center: [2, 4], size: [1, 1]}, material: metal}\n"
      "  - {circle: {center: [8, 3], radius_m: 0.5}}\n"
      "  - {material: fabric, polygon: [[7, 1], [8, 1], [7.5, 2]]}\n"
      "start: {x_m: 1, y_m: 1}\n");
  // Indices into the built-in table: painted_wall 0, wood 1, glass 2, metal 3, fabric 4.
  ASSERT_EQ(w.walls.size(), 3u);
  EXPECT_EQ(w.walls[0].material, 1);  // the world default
  EXPECT_EQ(w.walls[1].material, 2);
  EXPECT_EQ(w.walls[2].material, 0);
  EXPECT_DOUBLE_EQ(w.walls[2].thickness_m, 0.05);
  ASSERT_EQ(w.obstacles.size(), 3u);
  EXPECT_EQ(w.obstacles[0].material, 3);
  EXPECT_EQ(w.obstacles[1].material, 1);
  EXPECT_EQ(w.obstacles[2].material, 4);
  EXPECT_TRUE(std::holds_alternative<PolygonObstacle>(w.obstacles[2].shape));
  const auto alone = config_error_of_world(
      kHeader + "obstacles:\n  - {material: glass}\nstart: {x_m: 1, y_m: 1}\n");
  EXPECT_NE(std::string(alone.what()).find("exactly one of box, circle, polygon"),
            std::string::npos)
      << alone.what();
}

TEST(WorldLoader, MaterialsTableDefinesAndOverrides) {
  const WorldSpec w = parse(
      "name: m\n"
      "materials:\n"
      "  frosted: {like: glass, diffuse_strength: 0.5, mirror_reflectivity: 0.7}\n"
      "  drywall: {specular_lobe_deg: 9}\n"
      "  metal: {like: metal, specular_strength: 150}\n"
      "  frosted2: {like: frosted}\n"
      "material: drywall\n"
      "walls:\n"
      "  polylines:\n"
      "    - {points: [[0, 0], [10, 0], [10, 6], [0, 6], [0, 0]], material: frosted}\n"
      "    - [[5, 0], [5, 3]]\n"
      "obstacles:\n"
      "  - {box: {center: [2, 4], size: [1, 1]}, material: metal}\n"
      "start: {x_m: 1, y_m: 1}\n");
  const auto& b = builtin_sonar_materials();
  ASSERT_EQ(w.materials.size(), 8u);  // five built-ins (metal replaced in place), three new
  const SonarMaterial& frosted = w.materials[5];
  EXPECT_EQ(frosted.name, "frosted");
  EXPECT_EQ(frosted.specular_strength, b[2].specular_strength);  // like: glass
  EXPECT_EQ(frosted.specular_lobe_deg, b[2].specular_lobe_deg);
  EXPECT_EQ(frosted.diffuse_incidence_exponent, b[2].diffuse_incidence_exponent);
  EXPECT_EQ(frosted.diffuse_strength, 0.5);
  EXPECT_EQ(frosted.mirror_reflectivity, 0.7);
  const SonarMaterial& drywall = w.materials[6];  // no like: starts from painted_wall
  EXPECT_EQ(drywall.name, "drywall");
  EXPECT_EQ(drywall.specular_lobe_deg, 9.0);
  EXPECT_EQ(drywall.specular_strength, b[0].specular_strength);
  EXPECT_EQ(drywall.diffuse_strength, b[0].diffuse_strength);
  EXPECT_EQ(drywall.mirror_reflectivity, b[0].mirror_reflectivity);
  EXPECT_EQ(w.materials[3].name, "metal");
  EXPECT_EQ(w.materials[3].specular_strength, 150.0);
  EXPECT_EQ(w.materials[3].specular_lobe_deg, b[3].specular_lobe_deg);
  const SonarMaterial& frosted2 = w.materials[7];  // like: an earlier entry of the table
  EXPECT_EQ(frosted2.name, "frosted2");
  EXPECT_EQ(frosted2.diffuse_strength, 0.5);
  EXPECT_EQ(frosted2.mirror_reflectivity, 0.7);
  EXPECT_EQ(w.walls[0].material, 5);
  EXPECT_EQ(w.walls[1].material, 6);  // the world default names a material of its own
  EXPECT_EQ(w.obstacles[0].material, 3);
}

TEST(WorldLoader, BadMaterialsNameFileLineKeyAndTheKnownNames) {
  const std::string known = "(known: painted_wall, wood, glass, metal, fabric)";
  const std::string start = "start: {x_m: 5, y_m: 3}\n";
  const auto wall = config_error_of_world(
      "name: t\nwalls:\n  polylines:\n    - {points: [[0, 0], [10, 0]], material: glas}\n" + start);
  EXPECT_EQ(wall.line(), 4);
  EXPECT_EQ(wall.key(), "walls.polylines[0].material");
  EXPECT_NE(std::string(wall.what())
                .find("w.yaml:4: walls.polylines[0].material: unknown material 'glas' " + known),
            std::string::npos)
      << wall.what();
  const auto obstacle = config_error_of_world(
      kHeader + "obstacles:\n  - {box: {center: [5, 3], size: [1, 1]}, material: steel}\n" +
      "start: {x_m: 1, y_m: 1}\n");
  EXPECT_EQ(obstacle.line(), 6);
  EXPECT_EQ(obstacle.key(), "obstacles[0].material");
  EXPECT_NE(std::string(obstacle.what()).find("unknown material 'steel' " + known),
            std::string::npos);
  const auto world =
      config_error_of_world("name: t\nmaterial: plaster\n" + kHeader.substr(8) + start);
  EXPECT_EQ(world.line(), 2);
  EXPECT_EQ(world.key(), "material");
  EXPECT_NE(std::string(world.what()).find("unknown material 'plaster' " + known),
            std::string::npos);
  const auto like = config_error_of_world("name: t\nmaterials:\n  frosted: {like: frost}\n" +
                                          kHeader.substr(8) + start);
  EXPECT_EQ(like.line(), 3);
  EXPECT_EQ(like.key(), "materials.frosted.like");
  // The list names the world's own materials too.
  const auto own = config_error_of_world(
      "name: t\nmaterials:\n  felt: {diffuse_strength: 1}\n"
      "walls:\n  polylines:\n    - {points: [[0, 0], [10, 0]], "
      "material: felted}\n" +
      start);
  EXPECT_EQ(own.line(), 6);
  EXPECT_NE(std::string(own.what())
                .find("unknown material 'felted' (known: painted_wall, wood, glass, metal, "
                      "fabric, felt)"),
            std::string::npos)
      << own.what();
  const auto key = config_error_of_world("name: t\nmaterials:\n  felt: {roughness: 1}\n" +
                                         kHeader.substr(8) + start);
  EXPECT_EQ(key.key(), "materials.felt.roughness");
  EXPECT_NE(std::string(key.what()).find("unknown key"), std::string::npos);
  const auto range = config_error_of_world(
      "name: t\nmaterials:\n  felt: {mirror_reflectivity: 1.5}\n" + kHeader.substr(8) + start);
  EXPECT_EQ(range.line(), 3);
  EXPECT_EQ(range.key(), "materials.felt.mirror_reflectivity");
  EXPECT_NE(std::string(range.what()).find("must be in [0, 1]"), std::string::npos);
  const auto list =
      config_error_of_world("name: t\nmaterials: [glass]\n" + kHeader.substr(8) + start);
  EXPECT_EQ(list.key(), "materials");
  EXPECT_NE(std::string(list.what()).find("expected a map"), std::string::npos);
}

}  // namespace
}  // namespace cogmap::sim
