#pragma once
/// Rooms of the true world and how many of them the true trajectory entered (metrics.json
/// `nav.rooms_total_true` / `nav.rooms_visited_true`, docs/metrics.md). Worlds carry no room
/// annotations, so rooms are found from the true surfaces alone: rasterise the walls, erode the
/// free space until doorways close, and take the enclosed connected components that the robot
/// can reach from the run's start (an enclosed block with no door, or the inside of a solid
/// obstacle, is no room).

#include <cstddef>
#include <span>

#include "cogmap/experiments/metrics.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::experiments {

/// Knobs of count_true_rooms. General, not tuned to any world.
struct TrueRoomsOptions {
  /// Raster cell: well below the narrowest opening that matters (doors, 0.9-1.2 m).
  double resolution_m = 0.05;
  /// Coarser than this (max_cells forced it) and a 0.9 m door between walls thickened by
  /// 0.75 cell each side keeps under 5 cells: the result is flagged not measurable.
  double max_measurable_resolution_m = 0.1;
  /// Free border around the surfaces' bounding box, wider than door_close_radius_m, so the
  /// outside of the building stays one component that touches the raster border.
  double margin_m = 1.0;
  /// A cell is wall when its centre is this close to a surface: walls are 0.12 m thick. Never
  /// less than half a cell diagonal is used, so a rasterised wall has no diagonal leak.
  double wall_half_thickness_m = 0.06;
  /// Free cells this close to a wall cell are not room core: closes openings up to 2 × 0.65 =
  /// 1.3 m wide between wall cells (doors are 0.9-1.2 m), while 5 × 5 m rooms and corridors
  /// 1.8-3 m wide stay open. True surfaces are wall faces, so between surfaces the limit is
  /// 1.3 m + 2 × wall_half_thickness_m, about 1.42 m.
  double door_close_radius_m = 0.65;
  /// Smaller core components are slivers between furniture and walls, not rooms.
  double min_room_area_m2 = 1.0;
  /// Memory bound (about 8 bytes a cell): a larger raster is coarsened until it fits.
  std::size_t max_cells = 20'000'000;
};

/// Rooms found in the true surfaces, and those the true trajectory entered.
struct TrueRooms {
  std::size_t total = 0;  ///< reachable enclosed room-core components of at least min_room_area_m2
  std::size_t visited = 0;  ///< rooms with some row's true position in their core
  /// False when the raster had to be coarsened past max_measurable_resolution_m (a world so
  /// large that a 0.9 m door may close in it): the counts are then not to be trusted.
  bool measurable = true;
};

/// Counts the rooms of `surfaces` (world frame, walls and obstacle outlines) and the rooms a
/// true pose of `rows` falls in (rows without truth are ignored). Only rooms reachable from the
/// run's start count: the first row with a finite true position seeds a flood fill of the
/// un-eroded free space (not wall cells, doors open), and a room none of whose core cells it
/// reaches is dropped. Connectivity only: whether the robot's body fits through an opening is not
/// checked (doors are 0.9 m or more). Without a finite true position in `rows` (or with no free
/// cell near it) every enclosed component counts, reachable or not. Never throws: no (finite)
/// surface gives {0, 0}.
TrueRooms count_true_rooms(std::span<const mapper::Segment> surfaces, TrajectoryView rows,
                           const TrueRoomsOptions& options = {});

}  // namespace cogmap::experiments
