#pragma once
/// Writers of a run directory's text products (docs/formats.md "A run's output directory"):
/// trajectory.csv, map_segments*.csv and map.svg. Every file is written atomically.

#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cogmap/experiments/metrics.h"
#include "cogmap/mapper/mapper.h"

namespace cogmap::experiments {

/// trajectory.csv: `t_s,true_x_m,true_y_m,true_theta_rad,odom_x_m,odom_y_m,odom_theta_rad,
/// est_x_m,est_y_m,est_theta_rad`, one row a frame; true columns empty without ground truth.
std::string trajectory_csv(TrajectoryView rows);
/// The same text in pieces of `rows_per_chunk` rows (the header goes with the first), handed
/// to `emit` as they are made: a long run's file is written without holding it whole.
void trajectory_csv_chunks(TrajectoryView rows, const std::function<void(std::string_view)>& emit,
                           std::size_t rows_per_chunk = 1024);

/// One control cycle of the controller's own account (nav_trace.csv, `output.nav_trace`).
struct NavTraceRow {
  double t_s = 0.0;
  const char* mode = "idle";  ///< to_string(NavMode): a static string
  std::size_t waypoint_index = 0;
  double target_rad = 0.0;
  double direction_rad = 0.0;
  bool has_direction = false;
  double front_clearance_m = 0.0;
  bool door_active = false;
  mapper::Point2 door_center_m{0.0, 0.0};
  double door_normal_rad = 0.0;
  double door_width_m = 0.0;
  double v_mps = 0.0;  ///< the command sent
  double w_radps = 0.0;
};

/// nav_trace.csv: `t_s,mode,waypoint_index,target_rad,direction_rad,has_direction,
/// front_clearance_m,door_active,door_x_m,door_y_m,door_normal_rad,door_width_m,v_mps,w_radps`,
/// one row a cycle; door columns empty while no door is held, direction empty without one,
/// clearance empty when nothing is ahead. In pieces of `rows_per_chunk` rows, like the trajectory.
void nav_trace_csv_chunks(std::span<const NavTraceRow> rows,
                          const std::function<void(std::string_view)>& emit,
                          std::size_t rows_per_chunk = 1024);

/// Rooms re-placed after the room listener drew them (Mapper::room_moves, the end-of-run
/// relaxation): each room's segments in `map` and its label in `labels` take its move.
void move_rooms(std::span<const std::pair<int, mapper::Pose2>> moves,
                std::vector<mapper::Mapper::MapSegment>& map,
                std::vector<std::pair<int, mapper::Point2>>& labels);

/// map_segments.csv / map_segments_odom.csv: `asr_id,x1_m,y1_m,x2_m,y2_m`, world frame.
std::string segments_csv(std::span<const mapper::Mapper::MapSegment> segments);

/// What map.svg shows.
struct SvgMap {
  std::vector<mapper::Mapper::MapSegment> map;  ///< the merged corrected map (black)
  std::vector<mapper::Segment> truth;           ///< true surfaces (light grey, underneath)
  std::vector<mapper::Point2> path;             ///< the estimated robot path (blue), optional
  std::vector<std::pair<int, mapper::Point2>> labels;  ///< room id at its reference point
};

/// The merged polyline map as SVG: world metres (y flipped so north is up), a scale bar.
std::string map_svg(const SvgMap& map);

/// Just the segments of a master map.
std::vector<mapper::Segment> segments_of(std::span<const mapper::Mapper::MapSegment> map);

}  // namespace cogmap::experiments
