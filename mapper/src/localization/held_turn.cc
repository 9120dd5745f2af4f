#include "cogmap/mapper/localization/held_turn.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace cogmap::mapper {

void HeldTurnFilter::compare(const SonarReading& r, const Point2& at) {
  // A transducer number a P2OS packet cannot carry (one byte) is nobody's: the mapper rejects
  // such readings anyway, and a hostile one must not grow the table.
  if (r.index < 0 || r.index > 255) return;
  const auto i = static_cast<std::size_t>(r.index);
  if (i >= last_reading_.size()) last_reading_.resize(i + 1);
  const bool near =
      r.echo && std::isfinite(r.range_m) && r.range_m > 0.0 && r.range_m <= options_.max_range_m;
  std::optional<Reading>& last = last_reading_[i];
  const bool turned_since = last && std::abs(turn_rad_ - last->turn_rad) >=
                                        options_.min_turn_deg * std::numbers::pi / 180.0;
  if (near && last && r.time_s - last->time_s <= options_.window_s &&
      (at - last->at).norm() <= options_.max_shift_m && turned_since) {
    comparisons_.push_back(
        {r.time_s, std::abs(r.range_m - last->range_m) <= options_.same_m, last->turn_rad});
  }
  // The reading a later one is held against: the one before the turn, kept while the robot
  // has not turned min_turn_deg since (a newer one would shorten the turn being judged).
  if (!near) {
    last.reset();
  } else if (!last || (at - last->at).norm() > options_.max_shift_m ||
             r.time_s - last->time_s > options_.window_s || turned_since) {
    last = Reading{r.range_m, turn_rad_, at, r.time_s};
  }
}

Pose2 HeldTurnFilter::update(const Pose2& odometry, const SensorFrame& frame) {
  if (!options_.enabled) return odometry;
  const double step_rad = last_in_ ? wrap_angle_rad(odometry.theta_rad - last_in_->theta_rad) : 0.0;
  if (std::isfinite(step_rad)) turn_rad_ += step_rad;  // a broken frame must not end the judging
  last_in_ = odometry;
  const Point2 at = odometry.translation();
  for (const SonarReading& r : frame.sonar) compare(r, at);
  // Judged on the latest comparisons only (those made while the body was still turning, before
  // it got wedged, say nothing about now), and only on recent ones.
  const auto n = static_cast<std::size_t>(std::max(options_.recent_comparisons, 1));
  while (comparisons_.size() > n ||
         (!comparisons_.empty() &&
          !(frame.time_s - comparisons_.front().time_s <= options_.window_s))) {
    comparisons_.pop_front();
  }
  std::size_t same = 0;
  for (const Comparison& c : comparisons_) same += c.same ? 1 : 0;
  const bool held_now = comparisons_.size() >= n &&
                        same >= static_cast<std::size_t>(std::max(options_.recent_same, 1));
  double remove_rad = 0.0;
  if (held_now && !held_) {
    // Detected: the body has not turned since the earliest of those unchanged readings was
    // taken, so the whole turn counted since then goes (this frame's included).
    double largest = 0.0;
    for (const Comparison& c : comparisons_) {
      if (c.same && std::abs(turn_rad_ - c.since_turn_rad) > std::abs(largest)) {
        largest = turn_rad_ - c.since_turn_rad;
      }
    }
    remove_rad = largest;
    ++detections_;
  } else if (held_now) {
    remove_rad = step_rad;  // still held: this frame's turn did not happen either
  }
  if (!held_now && held_) comparisons_.clear();  // a new picture: judge afresh
  held_ = held_now;
  if (remove_rad != 0.0) {
    // Turn the output back by remove_rad about where the robot stands in it: offset ←
    // R(−remove, about p) ∘ offset.
    const Point2 p = offset_.compose(odometry).translation();
    const double c = std::cos(-remove_rad), s = std::sin(-remove_rad);
    const Pose2 about{p.x() - (c * p.x() - s * p.y()), p.y() - (s * p.x() + c * p.y()),
                      -remove_rad};
    offset_ = about.compose(offset_);
    has_offset_ = true;
    removed_abs_rad_ += std::abs(remove_rad);
  }
  // Until a held turn is found the odometry passes through bit for bit.
  return has_offset_ ? offset_.compose(odometry) : odometry;
}

}  // namespace cogmap::mapper
