// The fixed-distance cut of thesis §3.1.2: "a new ASR is created every 4.5 meters" of travel.

#include "cogmap/mapper/boundary/asr_boundary_detector.h"

namespace cogmap::mapper {
namespace {

class DistanceDetector final : public AsrBoundaryDetector {
 public:
  explicit DistanceDetector(const DistanceOptions& options) : options_(options) {}

  std::optional<BoundaryEvent> update(const SensorFrame& frame, const Pose2& pose) override {
    if (last_pose_) travel_m_ += (pose.translation() - last_pose_->translation()).norm();
    last_pose_ = pose;
    if (options_.asr_distance_m <= 0.0 || travel_m_ < options_.asr_distance_m) return std::nullopt;
    // Keep the remainder so cuts fall at multiples of the distance, not drifting by a frame each.
    travel_m_ -= options_.asr_distance_m;
    return BoundaryEvent{frame.time_s, pose.translation(), 0.0, pose.theta_rad};
  }

  void reset() override {
    travel_m_ = 0.0;
    last_pose_.reset();
  }

 private:
  DistanceOptions options_;
  double travel_m_ = 0.0;
  std::optional<Pose2> last_pose_;
};

}  // namespace

std::unique_ptr<AsrBoundaryDetector> make_distance_detector(const DistanceOptions& options) {
  return std::make_unique<DistanceDetector>(options);
}

}  // namespace cogmap::mapper
