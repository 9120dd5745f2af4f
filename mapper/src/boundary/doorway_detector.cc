// The doorway state machine of thesis Fig. 3.4 (§3.1.2). The figure is not in the text we have;
// docs/algorithms.md reconstructs it from the prose: two states (in a room, at an
// access point) and the events L/¬L, R/¬R from the side sonars.

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "cogmap/mapper/boundary/asr_boundary_detector.h"

namespace cogmap::mapper {
namespace {

enum class Side { kLeft, kRight };

/// The latest reading of one side transducer, kept because sonars fire sparsely.
struct HeldReading {
  bool valid = false;
  double time_s = 0.0;
  double range_m = 0.0;
  bool echo = false;
};

/// What one side says right now: unknown (no fresh reading), close or not close.
struct SideState {
  bool known = false;
  bool close = false;
  double lateral_m = 0.0;  ///< signed y (robot frame) of the nearest obstacle when close
  double forward_m = 0.0;  ///< x (robot frame) of that obstacle
};

class DoorwayDetector final : public AsrBoundaryDetector {
 public:
  DoorwayDetector(const DoorwayOptions& options, const RobotGeometry& robot)
      : options_(options), mounts_(robot.sonars), held_(robot.sonars.size()) {
    for (std::size_t i = 0; i < mounts_.size(); ++i) {
      const double h = wrap_angle_rad(mounts_[i].heading_rad);
      if (std::abs(h - std::numbers::pi / 2) <= options_.side_heading_tolerance_rad) {
        left_.push_back(i);
      } else if (std::abs(h + std::numbers::pi / 2) <= options_.side_heading_tolerance_rad) {
        right_.push_back(i);
      }
    }
  }

  std::optional<BoundaryEvent> update(const SensorFrame& frame, const Pose2& pose) override {
    for (const SonarReading& r : frame.sonar) {
      if (r.index < 0 || static_cast<std::size_t>(r.index) >= held_.size()) continue;
      held_[r.index] = {true, r.time_s, r.range_m, r.echo};
    }
    if (last_pose_) {
      travel_m_ += (pose.translation() - last_pose_->translation()).norm();
    }
    last_pose_ = pose;

    const SideState left = side_state(left_, frame.time_s);
    const SideState right = side_state(right_, frame.time_s);
    if (state_ == State::kInRoom) {
      // In a room: L ∧ R (held for confirm_frames) means we are passing an access point.
      streak_ = (left.known && right.known && left.close && right.close) ? streak_ + 1 : 0;
      if (streak_ >= options_.confirm_frames) {
        state_ = State::kAtAccess;
        streak_ = 0;
        best_width_m_ = std::numeric_limits<double>::infinity();
        remember_gap(left, right, pose);
      }
      return std::nullopt;
    }
    // At an access point: keep the narrowest gap seen (the door frame itself), and leave when
    // both sides are confirmed free. Unknown sides do not count as free: no evidence.
    if (left.known && right.known && left.close && right.close) remember_gap(left, right, pose);
    streak_ = (left.known && right.known && !left.close && !right.close) ? streak_ + 1 : 0;
    if (streak_ < options_.confirm_frames) return std::nullopt;
    state_ = State::kInRoom;
    streak_ = 0;
    // A corridor start, or a gap inside a room the robot has barely entered, is no new room.
    if (travel_m_ < options_.min_room_travel_m) return std::nullopt;
    // Only a robot that went through is in the next room: it must be past the gap centre along
    // the direction it was heading at the narrowest point.
    const Point2 crossing(std::cos(gap_heading_rad_), std::sin(gap_heading_rad_));
    if ((pose.translation() - gap_center_).dot(crossing) < options_.min_exit_advance_m) {
      return std::nullopt;
    }
    travel_m_ = 0.0;
    return BoundaryEvent{frame.time_s, gap_center_, best_width_m_, gap_heading_rad_};
  }

  void reset() override {
    held_.assign(held_.size(), HeldReading{});
    state_ = State::kInRoom;
    streak_ = 0;
    travel_m_ = 0.0;
    last_pose_.reset();
  }

 private:
  enum class State { kInRoom, kAtAccess };

  SideState side_state(const std::vector<std::size_t>& sonars, double now_s) const {
    SideState out;
    double nearest_m = std::numeric_limits<double>::infinity();
    for (const std::size_t i : sonars) {
      const HeldReading& h = held_[i];
      if (!h.valid || now_s - h.time_s > options_.max_reading_age_s) continue;  // stale
      out.known = true;
      if (!h.echo || h.range_m >= options_.close_side_m || h.range_m >= nearest_m) continue;
      nearest_m = h.range_m;
      out.close = true;
      const SonarMount& m = mounts_[i];
      out.lateral_m = m.y_m + h.range_m * std::sin(m.heading_rad);
      out.forward_m = m.x_m + h.range_m * std::cos(m.heading_rad);
    }
    return out;
  }

  void remember_gap(const SideState& left, const SideState& right, const Pose2& pose) {
    // The width is measured between the two echo points (transducer offsets included), which is
    // the gap the body passes through.
    const double width_m = left.lateral_m - right.lateral_m;
    if (width_m >= best_width_m_) return;
    best_width_m_ = width_m;
    const Point2 centre_robot{(left.forward_m + right.forward_m) / 2.0,
                              (left.lateral_m + right.lateral_m) / 2.0};
    gap_center_ = pose.transform(centre_robot);
    gap_heading_rad_ = pose.theta_rad;
  }

  DoorwayOptions options_;
  std::vector<SonarMount> mounts_;
  std::vector<std::size_t> left_, right_;
  std::vector<HeldReading> held_;
  State state_ = State::kInRoom;
  int streak_ = 0;
  double travel_m_ = 0.0;
  std::optional<Pose2> last_pose_;
  double best_width_m_ = std::numeric_limits<double>::infinity();
  Point2 gap_center_{0.0, 0.0};
  double gap_heading_rad_ = 0.0;
};

}  // namespace

std::unique_ptr<AsrBoundaryDetector> make_doorway_detector(const DoorwayOptions& options,
                                                           const RobotGeometry& robot) {
  return std::make_unique<DoorwayDetector>(options, robot);
}

}  // namespace cogmap::mapper
