// Parses worlds/*.yaml strictly (docs/formats.md "World"): every key known, every number
// finite, every shape non-degenerate, the start pose clear of everything.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>

#include "cogmap/sim/world_spec.h"
#include "world/polygon_ops.h"

namespace cogmap::sim {

using mapper::Point2;
using mapper::Polyline;

double parse_coordinate(const yaml::Node& node) {
  const double v = node.as<double>();
  if (std::abs(v) > kMaxCoordinateM) {
    std::ostringstream msg;
    msg << "coordinate " << v << " m is beyond the +/-" << kMaxCoordinateM
        << " m the simulator supports (single-precision physics)";
    node.fail(msg.str());
  }
  return v;
}

double parse_angle_deg(const yaml::Node& node) {
  const double v = node.as<double>();
  if (std::abs(v) > kMaxAngleDeg) {
    std::ostringstream msg;
    msg << "angle " << v << " deg is beyond the +/-" << kMaxAngleDeg << " deg a file may give";
    node.fail(msg.str());
  }
  return v * std::numbers::pi / 180.0;
}

namespace {

// Two points closer than this are the same point, metres (a tenth of a millimetre).
constexpr double kSamePointM = 1e-4;
// Polygons with less area than this are degenerate, m² (1 cm²).
constexpr double kMinPolygonAreaM2 = 1e-4;
// Shortest wall segment, polygon edge and box side, and thinnest wall, metres. Box2D welds
// polygon vertices closer than 2.5 mm (b2_linearSlop / 2) and then asserts: a 1-2 mm segment
// passed `world check` and aborted the run. 1 cm keeps a factor 4 from that limit.
constexpr double kMinFeatureM = 0.01;

std::string metres(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

SourceRef source_of(const yaml::Node& node) { return {node.line(), node.key_path()}; }

Point2 parse_point(const yaml::Node& node) {
  if (!node.is_sequence() || node.size() != 2) node.fail("expected a point [x, y] in metres");
  return {parse_coordinate(node.at(0)), parse_coordinate(node.at(1))};
}

double parse_thickness(const yaml::Node& node) {
  const double t = node.as<double>();
  if (t <= 0.0) node.fail("wall thickness must be positive");
  if (t < kMinFeatureM || t > kMaxCoordinateM) {
    node.fail("wall thickness " + metres(t) + " m is outside [" + metres(kMinFeatureM) + ", " +
              metres(kMaxCoordinateM) + "] m");
  }
  return t;
}

// The index of the material a node names, from the world's table.
int parse_material_name(const yaml::Node& node, const std::vector<SonarMaterial>& table) {
  const auto name = node.as<std::string>();
  const auto found = find_sonar_material(table, name);
  if (!found) {
    node.fail("unknown material '" + name + "' (known: " + sonar_material_names(table) + ")");
  }
  return *found;
}

// One entry of `materials:`: a new material, or an override, starting from `like:` (default the
// world's first material) and changing any key.
SonarMaterial parse_material(const std::string& name, const yaml::Node& node,
                             const std::vector<SonarMaterial>& table) {
  node.expect_keys({"like", "specular_strength", "specular_lobe_deg", "diffuse_strength",
                    "diffuse_incidence_exponent", "mirror_reflectivity"});
  // Start from `like:`, else from the material of that name (an override), else painted_wall.
  SonarMaterial m = table.front();
  if (const auto existing = find_sonar_material(table, name)) m = table[*existing];
  if (const auto like = node.child("like")) m = table[parse_material_name(*like, table)];
  m.name = name;
  auto read = [&](const char* key, double& value, double lo, double hi) {
    if (const auto c = node.child(key)) {
      value = c->as<double>();
      if (!(value >= lo && value <= hi)) {
        c->fail("must be in [" + metres(lo) + ", " + metres(hi) + "]");
      }
    }
  };
  read("specular_strength", m.specular_strength, 0.0, 1e6);
  read("specular_lobe_deg", m.specular_lobe_deg, 0.1, 90.0);
  read("diffuse_strength", m.diffuse_strength, 0.0, 1e6);
  read("diffuse_incidence_exponent", m.diffuse_incidence_exponent, 0.0, 100.0);
  read("mirror_reflectivity", m.mirror_reflectivity, 0.0, 1.0);
  return m;
}

void parse_materials(const yaml::Node& node, WorldSpec& world) {
  if (!node.is_map()) node.fail("expected a map of material name -> {like: ..., keys ...}");
  for (const std::string& name : node.keys()) {
    const yaml::Node entry = node[name];
    if (name.empty()) entry.fail("a material needs a non-empty name");
    SonarMaterial m = parse_material(name, entry, world.materials);
    if (const auto existing = find_sonar_material(world.materials, name)) {
      world.materials[static_cast<std::size_t>(*existing)] = m;
    } else {
      world.materials.push_back(m);
    }
  }
}

WallPolyline parse_polyline(const yaml::Node& node, double default_thickness_m,
                            const WorldSpec& world, int default_material) {
  WallPolyline wall;
  wall.thickness_m = default_thickness_m;
  wall.material = default_material;
  wall.source = source_of(node);
  if (node.is_map()) {
    node.expect_keys({"points", "thickness_m", "material"});
    if (const auto t = node.child("thickness_m")) wall.thickness_m = parse_thickness(*t);
    if (const auto m = node.child("material")) {
      wall.material = parse_material_name(*m, world.materials);
    }
  } else if (!node.is_sequence()) {
    node.fail("expected a list of [x, y] points or {points: ..., thickness_m: ...}");
  }
  // Never assign one yaml::Node to another: yaml-cpp's operator= rewrites the document.
  const yaml::Node points = node.is_map() ? node["points"] : node;
  points.expect_sequence();
  if (points.size() < 2) points.fail("a wall polyline needs at least 2 points");
  for (std::size_t i = 0; i < points.size(); ++i) {
    const yaml::Node p = points.at(i);
    wall.points.push_back(parse_point(p));
    if (i == 0) continue;
    const double length_m = (wall.points[i] - wall.points[i - 1]).norm();
    if (length_m < kSamePointM) {
      p.fail("zero-length wall segment (the point repeats the previous one)");
    }
    if (length_m < kMinFeatureM) {
      p.fail("wall segment of " + metres(length_m) + " m is shorter than the " +
             metres(kMinFeatureM) + " m minimum (the physics engine cannot represent it)");
    }
  }
  return wall;
}

void parse_walls(const yaml::Node& node, WorldSpec& world, int default_material) {
  node.expect_keys({"thickness_m", "polylines"});
  double thickness_m = kDefaultWallThicknessM;
  if (const auto t = node.child("thickness_m")) thickness_m = parse_thickness(*t);
  const yaml::Node lines = node["polylines"];
  lines.expect_sequence();
  for (std::size_t i = 0; i < lines.size(); ++i) {
    world.walls.push_back(parse_polyline(lines.at(i), thickness_m, world, default_material));
  }
}

BoxObstacle parse_box(const yaml::Node& node) {
  node.expect_keys({"center", "size", "angle_deg"});
  BoxObstacle box;
  box.center = parse_point(node["center"]);
  const yaml::Node size = node["size"];
  const Point2 s = parse_point(size);
  if (s.x() <= 0.0 || s.y() <= 0.0) size.fail("box size must be positive in both directions");
  if (s.x() < kMinFeatureM || s.y() < kMinFeatureM) {
    size.fail("box sides must be at least " + metres(kMinFeatureM) + " m");
  }
  box.length_m = s.x();
  box.width_m = s.y();
  if (const auto angle = node.child("angle_deg")) box.angle_rad = parse_angle_deg(*angle);
  return box;
}

CircleObstacle parse_circle(const yaml::Node& node) {
  node.expect_keys({"center", "radius_m"});
  CircleObstacle circle;
  circle.center = parse_point(node["center"]);
  const yaml::Node r = node["radius_m"];
  circle.radius_m = r.as<double>();
  if (circle.radius_m <= 0.0) r.fail("circle radius must be positive");
  if (circle.radius_m < kMinFeatureM || circle.radius_m > kMaxCoordinateM) {
    r.fail("circle radius must be in [" + metres(kMinFeatureM) + ", " + metres(kMaxCoordinateM) +
           "] m");
  }
  return circle;
}

PolygonObstacle parse_polygon(const yaml::Node& node) {
  node.expect_sequence();
  PolygonObstacle polygon;
  for (std::size_t i = 0; i < node.size(); ++i) {
    const yaml::Node p = node.at(i);
    const Point2 q = parse_point(p);
    const bool closes = i + 1 == node.size() && !polygon.points.empty() &&
                        (q - polygon.points.front()).norm() < kSamePointM;
    if (closes) break;  // a repeated first vertex just closes the ring
    if (!polygon.points.empty() && (q - polygon.points.back()).norm() < kSamePointM) {
      p.fail("zero-length polygon edge (the vertex repeats the previous one)");
    }
    if (!polygon.points.empty() && (q - polygon.points.back()).norm() < kMinFeatureM) {
      p.fail("polygon edge shorter than the " + metres(kMinFeatureM) + " m minimum");
    }
    polygon.points.push_back(q);
  }
  if (polygon.points.size() < 3) node.fail("a polygon needs at least 3 distinct vertices");
  if ((polygon.points.front() - polygon.points.back()).norm() < kMinFeatureM) {
    node.fail("the closing polygon edge is shorter than the " + metres(kMinFeatureM) +
              " m minimum");
  }
  if (std::abs(geom::signed_area(polygon.points)) < kMinPolygonAreaM2) {
    node.fail("polygon has zero area");
  }
  if (!geom::is_simple_polygon(polygon.points)) node.fail("polygon is self-intersecting");
  return polygon;
}

Obstacle parse_obstacle(const yaml::Node& node, const WorldSpec& world, int default_material) {
  node.expect_keys({"box", "circle", "polygon", "material"});
  const auto material = node.child("material");
  if (node.size() != (material ? 2u : 1u)) {
    node.fail("an obstacle has exactly one of box, circle, polygon");
  }
  Obstacle obstacle;
  obstacle.source = source_of(node);
  obstacle.material = material ? parse_material_name(*material, world.materials) : default_material;
  if (const auto b = node.child("box")) {
    obstacle.shape = parse_box(*b);
  } else if (const auto c = node.child("circle")) {
    obstacle.shape = parse_circle(*c);
  } else {
    obstacle.shape = parse_polygon(node["polygon"]);
  }
  return obstacle;
}

std::string format_xy(const Point2& p) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(2);
  out << '(' << p.x() << ", " << p.y() << ')';
  return out.str();
}

// Distance from p to the surface of an obstacle: negative inside.
double signed_obstacle_distance_m(const Point2& p, const Obstacle& obstacle) {
  if (const auto* c = std::get_if<CircleObstacle>(&obstacle.shape)) {
    return (p - c->center).norm() - c->radius_m;
  }
  const Polyline outline = obstacle_outline(obstacle);
  const double d = geom::distance_to_boundary_m(p, outline);
  return geom::point_in_polygon(p, outline) ? -d : d;
}

// Bounds of one element, lower then upper corner.
using Bounds = std::pair<Point2, Point2>;

// The first element found to meet more than `limit` others: a sweep along x over the bounds
// sorted by their lower x, each pair whose bounds overlap then held to `meet(i, j)`; it stops
// at the first pile found. None when there is no pile.
template <class Meet>
std::optional<std::size_t> first_pile(const std::vector<Bounds>& bounds, std::size_t limit,
                                      const Meet& meet) {
  const std::size_t n = bounds.size();
  if (n <= limit) return std::nullopt;
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return std::pair(bounds[a].first.x(), a) < std::pair(bounds[b].first.x(), b);
  });
  std::vector<std::size_t> overlaps(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = order[k];
    for (std::size_t m = k + 1; m < n && bounds[order[m]].first.x() <= bounds[i].second.x(); ++m) {
      const std::size_t j = order[m];
      if (bounds[j].first.y() > bounds[i].second.y() ||
          bounds[j].second.y() < bounds[i].first.y() || !meet(i, j)) {
        continue;
      }
      for (const std::size_t o : {i, j}) {
        if (++overlaps[o] > limit) return o;
      }
    }
  }
  return std::nullopt;
}

// Refuses an obstacle whose bounds overlap more than kMaxObstaclePile others'.
void check_obstacle_piles(const WorldSpec& world) {
  const std::size_t n = world.obstacles.size();
  if (n <= kMaxObstaclePile) return;
  std::vector<Bounds> bounds(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Polyline outline = obstacle_outline(world.obstacles[i]);
    Point2 lo = outline.front(), hi = outline.front();
    for (const Point2& p : outline) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    bounds[i] = {lo, hi};
  }
  const auto pile =
      first_pile(bounds, kMaxObstaclePile, [](std::size_t, std::size_t) { return true; });
  if (!pile) return;
  const SourceRef& ref = world.obstacles[*pile].source;
  throw yaml::ConfigError(world.file.string(), ref.line, ref.key,
                          "its bounds overlap those of more than " +
                              std::to_string(kMaxObstaclePile) +
                              " other obstacles: a pile that is no building (turning it "
                              "into surfaces would cost the cube of its size)");
}

// Refuses a wall with a piece (one segment, with its thickness) that overlaps or touches more
// than kMaxWallPile other pieces: pieces whose bounds meet are held to their true reach,
// centre lines nearer than their half thicknesses together, so that a long diagonal wall's
// bounds, which meet every partition inside them, count only the walls it touches.
void check_wall_piles(const WorldSpec& world) {
  struct Piece {
    Point2 a, b;
    double half_m = 0.0;
    std::size_t wall = 0;
  };
  std::vector<Piece> pieces;
  std::vector<Bounds> bounds;
  for (std::size_t w = 0; w < world.walls.size(); ++w) {
    const WallPolyline& wall = world.walls[w];
    const double h = 0.5 * wall.thickness_m;
    for (std::size_t k = 0; k + 1 < wall.points.size(); ++k) {
      const Point2 a = wall.points[k], b = wall.points[k + 1];
      pieces.push_back({a, b, h, w});
      bounds.push_back({a.cwiseMin(b) - Point2(h, h), a.cwiseMax(b) + Point2(h, h)});
    }
  }
  const auto touching = [&](std::size_t i, std::size_t j) {
    const Piece& p = pieces[i];
    const Piece& q = pieces[j];
    if (geom::segments_touch(p.a, p.b, q.a, q.b)) return true;
    const mapper::Segment sp{p.a, p.b}, sq{q.a, q.b};
    const double reach = p.half_m + q.half_m;
    return mapper::distance_to_segment_m(p.a, sq) <= reach ||
           mapper::distance_to_segment_m(p.b, sq) <= reach ||
           mapper::distance_to_segment_m(q.a, sp) <= reach ||
           mapper::distance_to_segment_m(q.b, sp) <= reach;
  };
  const auto pile = first_pile(bounds, kMaxWallPile, touching);
  if (!pile) return;
  const SourceRef& ref = world.walls[pieces[*pile].wall].source;
  throw yaml::ConfigError(world.file.string(), ref.line, ref.key,
                          "a piece of this wall overlaps or touches more than " +
                              std::to_string(kMaxWallPile) +
                              " other wall pieces: a pile that is no building (its surfaces "
                              "and sight lines would take hours)");
}

void check_start(const WorldSpec& world, const WorldCheckOptions& options) {
  const Point2 p = world.start.translation();
  auto complain = [&](double d, const std::string& what, const SourceRef& ref) {
    std::ostringstream msg;
    msg.setf(std::ios::fixed);
    msg.precision(3);
    if (d < 0.0) {
      msg << "start " << format_xy(p) << " is inside " << what << " " << ref.key << " (line "
          << ref.line << ")";
    } else {
      msg << "start " << format_xy(p) << " is only " << d << " m from " << what << " " << ref.key
          << " (line " << ref.line << "); the robot needs " << options.start_clearance_m << " m";
    }
    throw yaml::ConfigError(world.file.string(), world.start_source.line, "start", msg.str());
  };
  for (const WallPolyline& wall : world.walls) {
    for (std::size_t i = 0; i + 1 < wall.points.size(); ++i) {
      const double d = mapper::distance_to_segment_m(p, {wall.points[i], wall.points[i + 1]}) -
                       0.5 * wall.thickness_m;
      if (d < options.start_clearance_m) complain(d, "wall", wall.source);
    }
  }
  for (const Obstacle& obstacle : world.obstacles) {
    const double d = signed_obstacle_distance_m(p, obstacle);
    if (d < options.start_clearance_m) complain(d, "obstacle", obstacle.source);
  }
}

}  // namespace

WorldSpec parse_world(const yaml::Node& root, const WorldCheckOptions& options) {
  root.expect_keys({"name", "description", "material", "materials", "walls", "obstacles", "start"});
  WorldSpec world;
  world.file = root.file();
  world.name = root.get<std::string>("name");
  if (world.name.empty()) root["name"].fail("the world needs a non-empty name");
  yaml::expect_one_printable_line(root["name"], world.name);  // `world check` prints it
  world.description = root.get_or<std::string>("description", "");
  if (const auto materials = root.child("materials")) parse_materials(*materials, world);
  int default_material = 0;  // painted_wall, unless the world says otherwise
  if (const auto m = root.child("material")) {
    default_material = parse_material_name(*m, world.materials);
  }
  parse_walls(root["walls"], world, default_material);
  if (const auto obstacles = root.child("obstacles")) {
    obstacles->expect_sequence();
    for (std::size_t i = 0; i < obstacles->size(); ++i) {
      world.obstacles.push_back(parse_obstacle(obstacles->at(i), world, default_material));
    }
  }
  check_obstacle_piles(world);
  check_wall_piles(world);
  const yaml::Node start = root["start"];
  start.expect_keys({"x_m", "y_m", "theta_deg"});
  const auto theta = start.child("theta_deg");
  world.start = {parse_coordinate(start["x_m"]), parse_coordinate(start["y_m"]),
                 theta ? mapper::wrap_angle_rad(parse_angle_deg(*theta)) : 0.0};
  world.start_source = source_of(start);
  check_start(world, options);
  return world;
}

WorldSpec load_world(const std::filesystem::path& path, const WorldCheckOptions& options) {
  return parse_world(yaml::Node::load_file(path), options);
}

bool WallPolyline::closed() const {
  return points.size() > 2 && (points.front() - points.back()).norm() < kSamePointM;
}

Polyline obstacle_outline(const Obstacle& obstacle, int circle_sides) {
  Polyline out;
  if (const auto* b = std::get_if<BoxObstacle>(&obstacle.shape)) {
    const double c = std::cos(b->angle_rad), s = std::sin(b->angle_rad);
    const double hx = 0.5 * b->length_m, hy = 0.5 * b->width_m;
    for (const auto& [u, v] : {std::pair{hx, hy}, {-hx, hy}, {-hx, -hy}, {hx, -hy}}) {
      out.push_back(b->center + Point2{c * u - s * v, s * u + c * v});
    }
  } else if (const auto* ci = std::get_if<CircleObstacle>(&obstacle.shape)) {
    for (int k = 0; k < circle_sides; ++k) {
      const double a = 2.0 * std::numbers::pi * k / circle_sides;
      out.push_back(ci->center + ci->radius_m * Point2{std::cos(a), std::sin(a)});
    }
  } else {
    out = std::get<PolygonObstacle>(obstacle.shape).points;
  }
  return out;
}

std::pair<Point2, Point2> world_bounds(const WorldSpec& world) {
  Point2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Point2 hi = -lo;
  auto grow = [&](const Point2& p, double margin) {
    lo = lo.cwiseMin(p - Point2{margin, margin});
    hi = hi.cwiseMax(p + Point2{margin, margin});
  };
  for (const WallPolyline& wall : world.walls) {
    for (const Point2& p : wall.points) grow(p, 0.5 * wall.thickness_m);
  }
  for (const Obstacle& obstacle : world.obstacles) {
    for (const Point2& p : obstacle_outline(obstacle)) grow(p, 0.0);
  }
  if (world.walls.empty() && world.obstacles.empty()) grow(world.start.translation(), 0.0);
  return {lo, hi};
}

}  // namespace cogmap::sim
