#pragma once
/// The explorer's long-term picture of the building (estimate frame): which cells a sonar
/// beam has swept from close enough for the mapper to see them, and which hold echoes. Unlike
/// the room grid it is never reset at a doorway, so the explorer knows where it has been.

#include <cstdint>
#include <optional>
#include <vector>

#include "cogmap/mapper/nav/controller.h"
#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/robot_geometry.h"
#include "cogmap/mapper/seam/sensor_frame.h"

namespace cogmap::mapper::nav {

/// A growable grid of cells with an occupancy score (0-15) and a seen flag.
class ExploreMap {
 public:
  explicit ExploreMap(const ExploreMapOptions& options = {});

  /// Integrates one frame's sonar at `pose` (estimate frame) and marks the body's cells.
  void add_frame(const SensorFrame& frame, const Pose2& pose, const RobotGeometry& robot);
  /// Marks the cells under a body of `radius_m` at `center` seen and free (the robot is there).
  void mark_body(const Point2& center, double radius_m);
  /// Marks the cell under `center` as one the robot's centre has passed through.
  void mark_traversed(const Point2& center);

  struct Cell {
    int x = 0;
    int y = 0;
  };
  int width() const { return width_; }
  int height() const { return height_; }
  double cell_m() const { return options_.cell_m; }
  bool inside(Cell c) const { return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_; }
  std::size_t index(Cell c) const { return static_cast<std::size_t>(c.y) * width_ + c.x; }
  Cell cell_of(const Point2& p) const;
  Point2 center_of(Cell c) const;
  bool seen(Cell c) const { return inside(c) && seen_[index(c)] != 0; }
  bool occupied(Cell c) const {
    if (!inside(c)) return false;
    const std::size_t i = index(c);
    return hits_[i] >= options_.occupied_min_weight &&
           hits_[i] >= options_.occupied_ratio * misses_[i];
  }
  /// The robot's centre has passed through `c`: the way it came is a way back, whatever
  /// echoes later paint there (a doorway's jambs, heard obliquely, paint it shut again).
  bool traversed(Cell c) const { return inside(c) && traversed_[index(c)] != 0; }
  /// Echo weight, and the weight of beams that swept the cell free.
  float hit_weight(Cell c) const { return inside(c) ? hits_[index(c)] : 0.0f; }
  float miss_weight(Cell c) const { return inside(c) ? misses_[index(c)] : 0.0f; }
  /// Seen, not an obstacle, and next to an unseen cell.
  bool frontier(Cell c) const {
    return seen(c) && !occupied(c) &&
           (!seen({c.x + 1, c.y}) || !seen({c.x - 1, c.y}) || !seen({c.x, c.y + 1}) ||
            !seen({c.x, c.y - 1}));
  }
  /// Forgets the echoes placed in `c` (the explorer's last resort reopens, on a copy, cells
  /// another map shows open).
  void clear_echoes(Cell c) {
    if (inside(c)) hits_[index(c)] = 0.0f;
  }
  /// Cells seen so far (grows as exploration goes on).
  std::size_t seen_count() const { return seen_count_; }
  /// Sonar readings integrated so far (valid ones, echo or not).
  std::size_t readings() const { return readings_; }

 private:
  /// One reading from a transducer at `origin` looking along `axis_rad`, with an echo at
  /// `echo_m` or none: the cone's core before the echo swept free (and seen within
  /// free_sense_m; no_echo_free_m without an echo), the arc at the echo near the axis hit
  /// (and seen within wall_sense_m).
  void sweep(const Point2& origin, double axis_rad, std::optional<double> echo_m,
             const RobotGeometry& robot);
  /// True when an obstacle cell lies between `origin` and `target` (the beam stopped there).
  bool occluded(const Point2& origin, Cell target) const;
  /// Adds evidence seen from `distance_m` to `weights[i]` (hits_ or misses_).
  void add(std::vector<float>& weights, std::size_t i, double distance_m);
  /// Grows the map so that the box [lo, hi] (metres) is inside it; false if it cannot.
  bool cover(const Point2& lo, const Point2& hi);

  ExploreMapOptions options_;
  double origin_x_m_ = 0.0, origin_y_m_ = 0.0;  // world position of cell (0, 0)'s corner
  int width_ = 0, height_ = 0;
  std::vector<float> hits_;    // weight of the echoes placed in the cell
  std::vector<float> misses_;  // weight of the beams that swept it free
  std::vector<std::uint8_t> seen_;
  std::vector<std::uint8_t> traversed_;
  std::size_t seen_count_ = 0;
  std::size_t readings_ = 0;
  std::vector<Cell> swept_, hit_;  // one beam's cells, reused

  void mark_seen(std::size_t i) {
    seen_count_ += seen_[i] == 0 ? 1 : 0;
    seen_[i] = 1;
  }
};

}  // namespace cogmap::mapper::nav
