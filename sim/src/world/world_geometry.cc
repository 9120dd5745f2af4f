// Thick walls become mitred quads; every quad and obstacle outline contributes its edges as
// candidate surfaces, and the parts of a candidate buried inside another piece are cut away.
#include "cogmap/sim/world_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "world/polygon_ops.h"

namespace cogmap::sim {

using mapper::Point2;
using mapper::Polyline;
using mapper::Segment;

namespace {

// Joints sharper than this turn (radians) are not mitred: the mitre would spike far out.
constexpr double kMaxMitreTurnRad = 150.0 * 3.14159265358979323846 / 180.0;
// Endpoints closer than this are the same vertex when surfaces are chained, metres.
constexpr double kJoinEpsM = 1e-6;
// A chained vertex is a convex corner when the surfaces turn right by more than this (sine).
constexpr double kCornerMinSine = 1e-3;
// Candidate pieces shorter than this after clipping are numerical dust, metres.
constexpr double kMinSurfaceM = 1e-6;

Point2 left_normal(const Point2& d) { return {-d.y(), d.x()}; }

struct Candidate {
  Segment segment;
  std::size_t owner;  // index of the piece it bounds: never clipped against itself
  int material = 0;   // index into WorldSpec::materials
};

struct Box {
  Point2 lo, hi;
  bool overlaps(const Box& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y();
  }
};

Box bounds_of(const Polyline& pts) {
  Box b{pts.front(), pts.front()};
  for (const Point2& p : pts) {
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
  }
  return b;
}

// Mitre offset at a joint between unit directions d0 then d1, or nullopt when not mitred.
std::optional<Point2> mitre_offset(const Point2& d0, const Point2& d1, double half_m) {
  const double turn = std::atan2(geom::cross(d0, d1), d0.dot(d1));
  if (std::abs(turn) > kMaxMitreTurnRad) return std::nullopt;
  const Point2 n0 = left_normal(d0), n1 = left_normal(d1);
  return half_m * (n0 + n1) / (1.0 + n0.dot(n1));
}

// Adds one wall's quads to `pieces` and their exposed edges to `candidates`.
void add_wall(const WallPolyline& wall, std::vector<SolidPiece>& pieces,
              std::vector<Candidate>& candidates) {
  const double h = 0.5 * wall.thickness_m;
  const bool closed = wall.closed();
  const std::size_t n_seg = wall.points.size() - 1;
  std::vector<Point2> dir(n_seg);
  for (std::size_t k = 0; k < n_seg; ++k) {
    dir[k] = (wall.points[k + 1] - wall.points[k]).normalized();
  }
  // Offset of the left face at the start and end of every segment; the right face mirrors it.
  std::vector<Point2> start_off(n_seg), end_off(n_seg);
  std::vector<bool> start_cap(n_seg, true), end_cap(n_seg, true);
  for (std::size_t k = 0; k < n_seg; ++k) {
    start_off[k] = h * left_normal(dir[k]);
    end_off[k] = start_off[k];
  }
  for (std::size_t k = 0; k < n_seg; ++k) {
    const bool has_next = k + 1 < n_seg || closed;
    if (!has_next) continue;
    const std::size_t next = (k + 1) % n_seg;
    if (const auto off = mitre_offset(dir[k], dir[next], h)) {
      end_off[k] = *off;
      start_off[next] = *off;
      end_cap[k] = false;
      start_cap[next] = false;
    }
  }
  for (std::size_t k = 0; k < n_seg; ++k) {
    const Point2& a = wall.points[k];
    const Point2& b = wall.points[k + 1];
    const Point2 ls = a + start_off[k], le = b + end_off[k];
    const Point2 re = b - end_off[k], rs = a - start_off[k];
    const std::size_t owner = pieces.size();
    SolidPiece piece;
    piece.outline = {ls, le, re, rs};  // clockwise: the solid is right of each edge
    pieces.push_back(piece);
    candidates.push_back({{ls, le}, owner, wall.material});
    candidates.push_back({{re, rs}, owner, wall.material});
    if (end_cap[k]) candidates.push_back({{le, re}, owner, wall.material});
    if (start_cap[k]) candidates.push_back({{rs, ls}, owner, wall.material});
  }
}

void add_obstacle(const Obstacle& obstacle, std::vector<SolidPiece>& pieces,
                  std::vector<Candidate>& candidates) {
  SolidPiece piece;
  piece.outline = obstacle_outline(obstacle, kCircleSides);
  if (geom::signed_area(piece.outline) > 0.0) {
    std::reverse(piece.outline.begin(), piece.outline.end());
  }
  if (const auto* c = std::get_if<CircleObstacle>(&obstacle.shape)) {
    piece.circle = true;
    piece.circle_center = c->center;
    piece.circle_radius_m = c->radius_m;
  }
  if (std::holds_alternative<PolygonObstacle>(obstacle.shape)) {
    const Polyline& o = piece.outline;
    for (std::size_t i = 0; i < o.size() && piece.convex; ++i) {
      const Point2& p0 = o[i];
      const Point2& p1 = o[(i + 1) % o.size()];
      const Point2& p2 = o[(i + 2) % o.size()];
      piece.convex = geom::cross(p1 - p0, p2 - p1) <= 0.0;  // clockwise: right turns only
    }
  }
  const std::size_t owner = pieces.size();
  for (std::size_t i = 0; i < piece.outline.size(); ++i) {
    candidates.push_back({{piece.outline[i], piece.outline[(i + 1) % piece.outline.size()]},
                          owner,
                          obstacle.material});
  }
  pieces.push_back(std::move(piece));
}

void build(const WorldSpec& world, std::vector<SolidPiece>& pieces,
           std::vector<Candidate>& candidates) {
  for (const WallPolyline& wall : world.walls) add_wall(wall, pieces, candidates);
  for (const Obstacle& obstacle : world.obstacles) add_obstacle(obstacle, pieces, candidates);
}

// A point this near a piece's boundary is on it, not inside (metres).
constexpr double kInsideEpsM = 1e-9;

// True when p is inside the piece and not on its boundary.
bool strictly_inside(const Point2& p, const Polyline& outline) {
  return geom::point_in_polygon(p, outline) &&
         geom::distance_to_boundary_m(p, outline) > kInsideEpsM;
}

// True when the clockwise outline turns right (or goes straight) at every vertex and once round
// in all: convex and simple, so that the inside is where every edge has the point on its right.
bool convex_clockwise(const Polyline& outline) {
  const std::size_t n = outline.size();
  if (n < 3) return false;
  double turned = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2 e0 = outline[(i + 1) % n] - outline[i];
    const Point2 e1 = outline[(i + 2) % n] - outline[(i + 1) % n];
    const double cross = geom::cross(e0, e1);
    if (cross > 0.0) return false;
    turned += std::atan2(cross, e0.dot(e1));
  }
  return std::abs(turned + 2.0 * std::numbers::pi) < 1e-6;
}

// The parameters t in which a + t·d lies inside a convex clockwise outline by more than
// kInsideEpsM from every edge's line: one open interval (lo, hi), or none. For a convex piece
// that is exactly where strictly_inside holds (its distance to the boundary is the least of its
// distances to the edges' lines), found by one pass over the edges instead of a test per point.
std::optional<std::pair<double, double>> inside_interval(const Point2& a, const Point2& d,
                                                         const Polyline& outline) {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Point2& p0 = outline[i];
    const Point2 e = outline[(i + 1) % outline.size()] - p0;
    const double len = e.norm();
    if (len == 0.0) continue;
    // Distance to the right of the edge (into the solid): s0 + t·s1.
    const double s0 = geom::cross(a - p0, e) / len, s1 = geom::cross(d, e) / len;
    if (s1 == 0.0) {
      if (!(s0 > kInsideEpsM)) return std::nullopt;
      continue;
    }
    const double t = (kInsideEpsM - s0) / s1;
    if (s1 > 0.0) {
      lo = std::max(lo, t);
    } else {
      hi = std::min(hi, t);
    }
  }
  if (!(lo < hi)) return std::nullopt;
  return std::pair(lo, hi);
}

// Open intervals merged into disjoint ones, sorted; `covers` asks whether t lies in one.
class Coverage {
 public:
  explicit Coverage(std::vector<std::pair<double, double>> intervals) {
    std::sort(intervals.begin(), intervals.end());
    for (const auto& [lo, hi] : intervals) {
      if (!merged_.empty() && lo < merged_.back().second) {
        merged_.back().second = std::max(merged_.back().second, hi);
      } else {
        merged_.push_back({lo, hi});
      }
    }
  }
  bool covers(double t) const {
    // The last interval starting before t is the only one that may hold it.
    auto it = std::lower_bound(merged_.begin(), merged_.end(), t,
                               [](const auto& interval, double v) { return interval.first < v; });
    if (it == merged_.begin()) return false;
    --it;
    return t < it->second;
  }

 private:
  std::vector<std::pair<double, double>> merged_;
};

// The pieces' boxes sorted along the axis they spread most on, so that the pieces a box may
// overlap are found by binary searches instead of a pass over every piece: a world of n pieces
// is clipped in ~n log n, not n² (a 60 000-point wall took minutes). Boxes are grouped by their
// length along that axis in powers of two, each group sorted on its own: a search looks back
// only as far as its group's longest box, so one long outer wall does not make every search
// scan every piece before it (a 38 000-point zig-zag inside a 41 m wall took 14 s).
class PieceIndex {
 public:
  explicit PieceIndex(const std::vector<Box>& boxes) : boxes_(boxes) {
    Box all{{0.0, 0.0}, {0.0, 0.0}};
    if (!boxes.empty()) all = boxes.front();
    for (const Box& b : boxes) all = {all.lo.cwiseMin(b.lo), all.hi.cwiseMax(b.hi)};
    axis_ = (all.hi - all.lo).x() >= (all.hi - all.lo).y() ? 0 : 1;
    std::map<int, Group> groups;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const double length = boxes[i].hi[axis_] - boxes[i].lo[axis_];
      // ilogb: the power of two at or below the length; points (and NaN) share one group.
      const int key = length > 0.0 ? std::ilogb(length) : std::numeric_limits<int>::min();
      Group& g = groups[key];
      g.order.push_back(i);
      g.longest = std::max(g.longest, length);
    }
    for (auto& [key, g] : groups) {
      std::sort(g.order.begin(), g.order.end(), [&](std::size_t a, std::size_t b) {
        return std::pair(boxes[a].lo[axis_], a) < std::pair(boxes[b].lo[axis_], b);
      });
      groups_.push_back(std::move(g));
    }
  }

  /// Indices (ascending) of the pieces whose box overlaps `box`.
  std::vector<std::size_t> overlapping(const Box& box) const {
    std::vector<std::size_t> out;
    for (const Group& g : groups_) {
      // A box overlapping `box` starts at or before its end and no earlier than its start
      // minus the group's longest box.
      const double from = box.lo[axis_] - g.longest, to = box.hi[axis_];
      auto first =
          std::lower_bound(g.order.begin(), g.order.end(), from,
                           [&](std::size_t i, double v) { return boxes_[i].lo[axis_] < v; });
      for (auto it = first; it != g.order.end() && boxes_[*it].lo[axis_] <= to; ++it) {
        if (boxes_[*it].overlaps(box)) out.push_back(*it);
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  struct Group {
    std::vector<std::size_t> order;  // by the boxes' start along the axis
    double longest = 0.0;
  };
  const std::vector<Box>& boxes_;
  int axis_ = 0;
  std::vector<Group> groups_;
};

// The parts of a candidate outside every other piece, in order along the candidate. A convex
// piece buries one interval of the candidate, found once; only a concave one is asked point by
// point: a pile of k pieces on one spot then costs k log k a candidate, not k² (1 500 walls
// laid 1 mm apart along one line took 226 s to load).
void clip(const Candidate& c, const std::vector<SolidPiece>& pieces,
          const std::vector<char>& convex, const PieceIndex& index, std::vector<Segment>& out,
          std::vector<int>& out_material) {
  const Box own{c.segment.a.cwiseMin(c.segment.b), c.segment.a.cwiseMax(c.segment.b)};
  const Point2 d = c.segment.b - c.segment.a;
  std::vector<std::size_t> concave;
  std::vector<std::pair<double, double>> inside;
  std::vector<double> cuts{0.0, 1.0};
  for (const std::size_t i : index.overlapping(own)) {
    if (i == c.owner) continue;
    if (convex[i]) {
      if (const auto r = inside_interval(c.segment.a, d, pieces[i].outline)) inside.push_back(*r);
    } else {
      concave.push_back(i);
    }
    const auto t = geom::crossings(c.segment.a, c.segment.b, pieces[i].outline);
    cuts.insert(cuts.end(), t.begin(), t.end());
  }
  std::sort(cuts.begin(), cuts.end());
  const Coverage covered(std::move(inside));
  double open = -1.0;  // start parameter of the kept run being built; negative: none open
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double t0 = cuts[k], t1 = cuts[k + 1];
    if (t1 - t0 <= 0.0) continue;
    const double t_mid = 0.5 * (t0 + t1);
    const Point2 mid = c.segment.a + t_mid * d;
    const bool buried =
        covered.covers(t_mid) || std::any_of(concave.begin(), concave.end(), [&](std::size_t i) {
          return strictly_inside(mid, pieces[i].outline);
        });
    if (!buried && open < 0.0) open = t0;
    if (buried && open >= 0.0) {
      out.push_back({c.segment.a + open * d, c.segment.a + t0 * d});
      out_material.push_back(c.material);
      open = -1.0;
    }
  }
  if (open >= 0.0) {
    out.push_back({c.segment.a + open * d, c.segment.b});
    out_material.push_back(c.material);
  }
}

// Points bucketed by cells of kJoinEpsM, so that the points within kJoinEpsM of a query are
// found among its cell's 3 × 3 neighbourhood (in insertion order) instead of by a pass over all.
class JoinBuckets {
 public:
  void add(const Point2& p, std::size_t id) {
    cells_[key(cell(p.x()), cell(p.y()))].push_back({p, id});
  }

  /// Ids (ascending) of the points within kJoinEpsM of `p`.
  std::vector<std::size_t> near(const Point2& p) const {
    std::vector<std::size_t> out;
    const long long cx = cell(p.x()), cy = cell(p.y());
    for (long long dy = -1; dy <= 1; ++dy) {
      for (long long dx = -1; dx <= 1; ++dx) {
        const auto it = cells_.find(key(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        for (const auto& [q, id] : it->second) {
          if ((q - p).norm() <= kJoinEpsM) out.push_back(id);
        }
      }
    }
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  static long long cell(double v) { return static_cast<long long>(std::floor(v / kJoinEpsM)); }
  static std::pair<long long, long long> key(long long x, long long y) { return {x, y}; }
  std::map<std::pair<long long, long long>, std::vector<std::pair<Point2, std::size_t>>> cells_;
};

std::vector<Point2> convex_corners(const std::vector<Segment>& surfaces) {
  JoinBuckets starts;
  for (std::size_t i = 0; i < surfaces.size(); ++i) starts.add(surfaces[i].a, i);
  JoinBuckets found;
  std::vector<Point2> corners;
  for (const Segment& s : surfaces) {
    const Point2 d0 = (s.b - s.a).normalized();
    for (const std::size_t j : starts.near(s.b)) {
      const Segment& t = surfaces[j];
      const Point2 d1 = (t.b - t.a).normalized();
      if (geom::cross(d0, d1) < -kCornerMinSine && found.near(s.b).empty()) {
        found.add(s.b, corners.size());
        corners.push_back(s.b);
      }
    }
  }
  return corners;
}

}  // namespace

std::vector<SolidPiece> solid_pieces(const WorldSpec& world) {
  std::vector<SolidPiece> pieces;
  std::vector<Candidate> unused;
  build(world, pieces, unused);
  return pieces;
}

WorldSurfaces world_surfaces(const WorldSpec& world) {
  std::vector<SolidPiece> pieces;
  std::vector<Candidate> candidates;
  build(world, pieces, candidates);
  std::vector<Box> boxes;
  boxes.reserve(pieces.size());
  for (const SolidPiece& p : pieces) boxes.push_back(bounds_of(p.outline));
  const PieceIndex index(boxes);
  std::vector<char> convex;
  convex.reserve(pieces.size());
  for (const SolidPiece& p : pieces) convex.push_back(convex_clockwise(p.outline) ? 1 : 0);
  WorldSurfaces out;
  for (const Candidate& c : candidates) {
    clip(c, pieces, convex, index, out.surfaces, out.surface_material);
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < out.surfaces.size(); ++i) {
    if (out.surfaces[i].length_m() < kMinSurfaceM) continue;
    out.surfaces[kept] = out.surfaces[i];
    out.surface_material[kept] = out.surface_material[i];
    ++kept;
  }
  out.surfaces.resize(kept);
  out.surface_material.resize(kept);
  out.corners = convex_corners(out.surfaces);
  return out;
}

SonarScene surface_segments(const WorldSpec& world) {
  WorldSurfaces s = world_surfaces(world);
  return {std::move(s.surfaces), std::move(s.corners), std::move(s.surface_material),
          world.materials};
}

std::vector<Segment> true_surfaces(const WorldSpec& world) {
  return world_surfaces(world).surfaces;
}

}  // namespace cogmap::sim
