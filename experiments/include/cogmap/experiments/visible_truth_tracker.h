#pragma once
/// The coverage's denominator (visible_truth_samples) worked out while the run goes. The frame
/// loop runs on one core; the test of which true surfaces the robot could have sensed depends
/// only on the truth and the true path, so a worker thread does it on the other core as the
/// true positions come in, and the end of the run waits only for the last stretch.

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <mutex>
#include <span>
#include <thread>
#include <vector>

#include "cogmap/experiments/metrics.h"
#include "cogmap/mapper/seam/geometry.h"

namespace cogmap::experiments {

class VisibleTruthTracker {
 public:
  /// Starts the worker. `truth` must outlive the tracker.
  VisibleTruthTracker(std::span<const mapper::Segment> truth, const MapMetricsOptions& options);
  /// Stops the worker (its result unused) if finish() was not called.
  ~VisibleTruthTracker();
  VisibleTruthTracker(const VisibleTruthTracker&) = delete;
  VisibleTruthTracker& operator=(const VisibleTruthTracker&) = delete;

  /// The next true position of the robot (every frame; subsampled here as
  /// visible_truth_samples subsamples the path).
  void add(const mapper::Point2& true_position);
  /// Waits for the worker and returns exactly what visible_truth_samples(truth, path, options)
  /// returns for the positions added; rethrows what the worker threw. Call once.
  std::vector<mapper::Point2> finish();

 private:
  void work();

  std::span<const mapper::Segment> truth_;
  MapMetricsOptions options_;
  PathSubsampler path_;                   // main thread: which positions count...
  std::vector<mapper::Point2> batch_;     // ...kept, not yet handed over
  std::vector<mapper::Point2> pending_;   // handed over, not yet tested (under mutex_)
  bool closing_ = false;                  // no more positions will come (under mutex_)
  std::vector<std::uint8_t> seen_;        // worker: per sample, seen from some position
  std::vector<std::uint32_t> hidden_by_;  // worker: per sample, the surface that last hid it
  std::exception_ptr failure_;            // worker: what it threw
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread worker_;
};

}  // namespace cogmap::experiments
