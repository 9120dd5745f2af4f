#pragma once
/// A simulated world as written in worlds/*.yaml (docs/formats.md, docs/worlds.md): walls as
/// thick polylines, obstacles as boxes, circles and polygons, and the robot's start pose.
/// Loading is strict: every mistake is a cogmap::yaml::ConfigError naming file, line and key.

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/pose2.h"
#include "cogmap/sim/sonar_material.h"
#include "cogmap/sim/yaml_strict.h"

namespace cogmap::sim {

/// Default wall thickness when `walls.thickness_m` is absent, metres (a plaster wall).
inline constexpr double kDefaultWallThicknessM = 0.12;

/// Largest |x| or |y| of any point of a world and of an experiment's start and waypoints,
/// metres. Box2D computes in float: at 3e6 m one float step is 0.25 m and a 12 cm wall collapses
/// (assertion); at 1 km a step is 0.06 mm. The thesis worlds span under 100 m.
inline constexpr double kMaxCoordinateM = 1000.0;

/// A coordinate in metres: a finite number within +/-kMaxCoordinateM. Throws
/// yaml::ConfigError at `node` otherwise.
double parse_coordinate(const yaml::Node& node);

/// Largest |angle| of a world's box `angle_deg` and start `theta_deg` and of an experiment's
/// start `theta_deg`, degrees. Any turn a file means is far inside it (generated buildings add
/// a rotation of up to 360 degrees to their own); 1e308 overflowed to an infinite angle in
/// radians, a NaN start heading that Box2D aborted on.
inline constexpr double kMaxAngleDeg = 1e6;
/// Most obstacles whose bounds may overlap any one obstacle's. Furniture touches a few
/// neighbours; a pile of thousands at one spot is no building, and turning it into surfaces
/// costs about the cube of the pile (3 000 boxes at one spot did not load in 30 s; 1 000 took
/// 5.7 s; 64 take milliseconds).
inline constexpr std::size_t kMaxObstaclePile = 64;
/// Most wall pieces (one segment of a polyline, with its thickness) that any one piece may
/// overlap or touch. A corridor's face meets one partition every few metres, so 512 is a
/// corridor of a kilometre; walls laid over one another by the thousand load in about the
/// square of their number and are then seen through the same cells by every sight line (1 500
/// along one line 10.7 s, 3 000 58 s, tens of thousands would not finish).
inline constexpr std::size_t kMaxWallPile = 512;

/// An angle in degrees: a finite number within +/-kMaxAngleDeg, returned in radians (not
/// wrapped). Throws yaml::ConfigError at `node` otherwise.
double parse_angle_deg(const yaml::Node& node);

/// Where a YAML element came from, so later checks (start clearance) can still name it.
struct SourceRef {
  int line = 0;     ///< 1-based line in the world file, 0 when unknown
  std::string key;  ///< key path, e.g. "obstacles[2].box"
};

/// One wall: a polyline whose surfaces lie thickness_m / 2 either side of the line.
struct WallPolyline {
  mapper::Polyline points;  ///< world frame, metres; at least 2, no zero-length segment
  double thickness_m = kDefaultWallThicknessM;
  int material = 0;  ///< index into WorldSpec::materials (the sonar's view of its faces)
  SourceRef source;

  /// True when the first and last points coincide (the wall closes on itself: no end caps).
  bool closed() const;
};

/// A rectangle of furniture, centred at `center`, rotated by angle_rad (CCW).
struct BoxObstacle {
  mapper::Point2 center{0.0, 0.0};  ///< metres
  double length_m = 0.0;            ///< along the box's own x (before rotation), > 0
  double width_m = 0.0;             ///< along the box's own y, > 0
  double angle_rad = 0.0;           ///< CCW rotation (the file says angle_deg)
};

/// A round obstacle (chair, bin, pillar).
struct CircleObstacle {
  mapper::Point2 center{0.0, 0.0};  ///< metres
  double radius_m = 0.0;            ///< > 0
};

/// A simple (non self-intersecting) polygon with non-zero area; either winding.
struct PolygonObstacle {
  mapper::Polyline points;  ///< at least 3 vertices, not repeated at the end
};

/// One obstacle of the world.
struct Obstacle {
  std::variant<BoxObstacle, CircleObstacle, PolygonObstacle> shape;
  int material = 0;  ///< index into WorldSpec::materials
  SourceRef source;
};

/// The whole world file, parsed and checked.
struct WorldSpec {
  std::string name;
  std::string description;
  std::vector<WallPolyline> walls;
  std::vector<Obstacle> obstacles;
  /// Sonar materials: the built-ins, then the world's own `materials:` (docs/sonar-model.md).
  std::vector<SonarMaterial> materials = builtin_sonar_materials();
  mapper::Pose2 start;         ///< the robot's true start pose, world frame
  SourceRef start_source;      ///< where `start` was written
  std::filesystem::path file;  ///< the file it came from (empty for text)
};

/// Options of the checks that need the robot (start clearance).
struct WorldCheckOptions {
  /// Clearance the start pose needs from every surface, metres; default half the P2-AT's
  /// 0.505 m width (docs/p2at.md), so the robot can at least turn on the spot's centre line.
  double start_clearance_m = 0.2525;
};

/// Loads and validates a world file. Throws yaml::ConfigError ("file:line: key: message").
WorldSpec load_world(const std::filesystem::path& path, const WorldCheckOptions& options = {});

/// Parses and validates an already loaded document (tests, embedded worlds).
WorldSpec parse_world(const yaml::Node& root, const WorldCheckOptions& options = {});

/// The outline of an obstacle as a closed polygon (last vertex not repeated), world frame;
/// circles become regular `circle_sides`-gons with vertices on the circle.
mapper::Polyline obstacle_outline(const Obstacle& obstacle, int circle_sides = 48);

/// Axis-aligned bounds of every wall and obstacle, metres: {min corner, max corner}.
std::pair<mapper::Point2, mapper::Point2> world_bounds(const WorldSpec& world);

}  // namespace cogmap::sim
