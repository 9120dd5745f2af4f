#include "cogmap/mapper/mapper.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "facade/mapper_impl.h"

namespace cogmap::mapper {

Mapper::Mapper(const MapperOptions& options, const RobotGeometry& robot, AsrStore& store,
               const Pose2& start_pose)
    : impl_(std::make_unique<Impl>(options, robot, store, start_pose)) {}

Mapper::~Mapper() = default;

void Mapper::set_room_listener(RoomListener listener) { impl_->listener = std::move(listener); }

std::optional<int> Mapper::process(const SensorFrame& frame) {
  Impl& m = *impl_;
  ++m.stats.frames;
  // Everything below sees the odometry re-integrated for the base's arcs (as reported when
  // options.odometry_calibration.curvature_gain is 0).
  // ...and with the turns made while the body was held taken out.
  const Pose2 odometry = m.held_turn.update(m.recalibrator.update(frame.odometry), frame);
  m.stats.held_turns = m.held_turn.detections();
  m.stats.held_turn_removed_abs_rad = m.held_turn.removed_abs_rad();
  const double turned_rad =
      m.previous_odometry ? wrap_angle_rad(odometry.theta_rad - m.previous_odometry->theta_rad)
                          : 0.0;
  m.previous_odometry = odometry;
  Pose2 pose = m.estimate(odometry);
  if (!m.started) {
    // Room 0 is entered at the known start pose.
    m.room.start(m.next_id++, frame.time_s, pose, Exit{pose.translation(), 0.0, pose.theta_rad, {}},
                 std::nullopt);
    m.restart_room_path(pose.translation());
    m.started = true;
    if (m.options.glimpse.enabled) m.glimpse.begin(pose);
  }
  // The extent limit bounds every room grid whatever the input: a pose that would stretch the
  // room past it (a log's time gap admits an odometry jump of kilometres, which grew one grid
  // to gigabytes) starts the next room before anything of the frame is drawn, whatever
  // min_room_duration_s says, and the frame's readings are not spread along the jump.
  std::optional<int> finished;
  const Point2 here = pose.translation();
  if ((m.room_hi.cwiseMax(here) - m.room_lo.cwiseMin(here)).maxCoeff() >
      m.options.max_room_extent_m) {
    const double heading = m.last_estimate ? m.last_estimate->theta_rad : pose.theta_rad;
    finished = m.next_room(m.last_time_s, frame.time_s, odometry,
                           BoundaryEvent{m.last_time_s, m.room_last_point, 0.0, heading}, pose);
    m.last_estimate.reset();
  }
  m.room.visit(pose);
  m.integrate(frame, pose);
  if (m.options.scan_match.enabled && m.scan_match.visit(pose, turned_rad)) {
    m.finish_scan_match(pose);
    pose = m.estimate(odometry);
  }
  if (m.options.glimpse.enabled && m.glimpse.visit(pose, turned_rad)) {
    m.finish_glimpse(pose);
    pose = m.estimate(odometry);
    m.glimpse.begin(pose);
  }
  m.room_lo = m.room_lo.cwiseMin(pose.translation());
  m.room_hi = m.room_hi.cwiseMax(pose.translation());
  const double step_m = (pose.translation() - m.room_last_point).norm();
  m.room_travel_m += step_m;
  m.travel_m += step_m;
  m.room_last_point = pose.translation();

  std::optional<BoundaryEvent> event = m.boundary->update(frame, pose);
  const double travel_limit_m = applied_max_room_travel_m(m.options);
  const bool too_long = travel_limit_m > 0.0 && m.room_travel_m >= travel_limit_m;
  if (!event && (too_long || (m.room_hi - m.room_lo).maxCoeff() > m.options.max_room_extent_m)) {
    event = BoundaryEvent{frame.time_s, pose.translation(), 0.0, pose.theta_rad};
  }
  if (!finished && event && frame.time_s - m.room.start_time_s() >= m.options.min_room_duration_s) {
    finished = m.next_room(frame.time_s, frame.time_s, odometry, *event, pose);
  }
  m.last_estimate = pose;
  m.last_time_s = frame.time_s;
  return finished;
}

std::optional<int> Mapper::finish() {
  Impl& m = *impl_;
  if (!m.started) return std::nullopt;
  m.started = false;
  const std::optional<int> id = m.finish_room(m.last_time_s, std::nullopt);
  if (m.relaxation.rooms() > 1) {
    const auto relax_start = std::chrono::steady_clock::now();
    m.room_moves = m.relaxation.relax(m.store, m.graph, m.stats);
    m.stats.localization_time_s += facade_detail::seconds_since(relax_start);
  }
  // The last room's correction turns the robot's estimate too, as every room's does when the
  // robot leaves it: pose_estimate() is the end of the run as the whole map sees it.
  if (m.previous_odometry) m.last_estimate = m.estimate(*m.previous_odometry);
  return id;
}

Pose2 Mapper::odometry_pose() const {
  return impl_->correction.inverse().compose(impl_->last_estimate.value_or(impl_->start_pose));
}

Pose2 Mapper::pose_estimate() const { return impl_->last_estimate.value_or(impl_->start_pose); }

const GridUpdater& Mapper::grid() const { return impl_->room.grid(); }
const AsrGraph& Mapper::graph() const { return impl_->graph; }
const AsrStore& Mapper::store() const { return impl_->store; }
const MapperStats& Mapper::stats() const { return impl_->stats; }
const std::vector<std::pair<int, Pose2>>& Mapper::room_moves() const { return impl_->room_moves; }

void Mapper::append_room_segments(const Asr& asr, bool corrected, std::vector<MapSegment>& map) {
  for (const Segment& s : asr.world_segments(corrected)) map.push_back({asr.id, s});
}

std::vector<Mapper::MapSegment> Mapper::master_map(bool corrected) const {
  std::vector<MapSegment> out;
  for (int id : impl_->store.ids()) append_room_segments(impl_->store.load(id), corrected, out);
  return out;
}

}  // namespace cogmap::mapper
