#include "facade/room_recorder.h"

namespace cogmap::mapper::internal {

void RoomRecorder::start(int id, double time_s, const Pose2& pose, const Exit& entry,
                         std::optional<int> parent) {
  id_ = id;
  start_time_s_ = time_s;
  entry_ = entry;
  parent_ = parent;
  path_.clear();
  travelled_m_ = 0.0;
  echoes_.clear();
  grid_->reset(pose.translation());
  visit(pose);
}

void RoomRecorder::visit(const Pose2& pose) {
  grid_->mark_robot(pose);
  const Point2 p = pose.translation();
  if (path_.empty()) {
    path_.push_back(p);
    return;
  }
  const double step_m = (p - path_.back()).norm();
  // The path feeds the clean-map rays and the figures; a vertex per half cell is enough.
  if (step_m >= path_spacing_m_) {
    travelled_m_ += step_m;
    path_.push_back(p);
  }
}

}  // namespace cogmap::mapper::internal
