#pragma once
/// The state of the room being mapped: its grid, the robot path through it and its entry.

#include <memory>
#include <optional>
#include <vector>

#include "cogmap/mapper/asr/asr.h"
#include "cogmap/mapper/grid/grid_updater.h"

namespace cogmap::mapper::internal {

class RoomRecorder {
 public:
  RoomRecorder(std::unique_ptr<GridUpdater> grid, double path_spacing_m)
      : grid_(std::move(grid)), path_spacing_m_(path_spacing_m) {}

  /// Starts a new room at `pose` entered through `entry` (estimate frame).
  void start(int id, double time_s, const Pose2& pose, const Exit& entry,
             std::optional<int> parent);

  /// Marks the robot's centre and appends it to the path when it moved far enough.
  void visit(const Pose2& pose);

  GridUpdater& grid() { return *grid_; }
  const GridUpdater& grid() const { return *grid_; }
  int id() const { return id_; }
  double start_time_s() const { return start_time_s_; }
  const Exit& entry() const { return entry_; }
  std::optional<int> parent() const { return parent_; }
  const std::vector<Point2>& path() const { return path_; }
  /// Distance the robot's centre travelled in this room, metres.
  double travelled_m() const { return travelled_m_; }
  /// The end point of an echo heard in this room (estimate frame), kept for EM's wall
  /// directions (LocalizerOptions::echo_refit); forgotten when the next room starts.
  void add_echo(const Point2& end_point) { echoes_.push_back(end_point); }
  const std::vector<Point2>& echoes() const { return echoes_; }

 private:
  std::unique_ptr<GridUpdater> grid_;
  double path_spacing_m_;
  int id_ = -1;
  double start_time_s_ = 0.0;
  Exit entry_;
  std::optional<int> parent_;
  std::vector<Point2> path_;
  double travelled_m_ = 0.0;
  std::vector<Point2> echoes_;
};

}  // namespace cogmap::mapper::internal
