#include "cogmap/experiments/visible_truth_tracker.h"

#include "cogmap/experiments/segment_index.h"

namespace cogmap::experiments {
namespace {

// Positions handed to the worker at once (every 0.25 m: 16 m of travel). Each batch walks
// every surface sample again, so batches much smaller than this would cost more than they save.
constexpr std::size_t kBatchPositions = 64;

}  // namespace

VisibleTruthTracker::VisibleTruthTracker(std::span<const mapper::Segment> truth,
                                         const MapMetricsOptions& options)
    : truth_(truth),
      options_(options),
      path_(options.trajectory_step_m),
      worker_([this] { work(); }) {}

VisibleTruthTracker::~VisibleTruthTracker() {
  {
    const std::lock_guard lock(mutex_);
    closing_ = true;
    pending_.clear();  // nobody waits for the answer any more
  }
  wake_.notify_one();
  if (worker_.joinable()) worker_.join();
}

void VisibleTruthTracker::add(const mapper::Point2& p) {
  if (path_.add(p)) batch_.push_back(p);
  if (batch_.size() < kBatchPositions) return;
  {
    const std::lock_guard lock(mutex_);
    pending_.insert(pending_.end(), batch_.begin(), batch_.end());
  }
  batch_.clear();
  wake_.notify_one();
}

std::vector<mapper::Point2> VisibleTruthTracker::finish() {
  // The last position counts even when nearer than a step to the last kept one.
  if (const auto tail = path_.unkept_last()) batch_.push_back(*tail);
  {
    const std::lock_guard lock(mutex_);
    pending_.insert(pending_.end(), batch_.begin(), batch_.end());
    closing_ = true;
  }
  batch_.clear();
  wake_.notify_one();
  worker_.join();
  if (failure_) std::rethrow_exception(failure_);
  return marked_samples(truth_, options_.sample_step_m, seen_);
}

void VisibleTruthTracker::work() {
  try {
    const SegmentIndex index(truth_, options_.index_cell_m);
    std::vector<mapper::Point2> poses;
    while (true) {
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [this] { return closing_ || !pending_.empty(); });
        if (pending_.empty()) return;  // closing, nothing left
        poses.swap(pending_);
        pending_.clear();
      }
      mark_visible_samples(truth_, index, poses, options_, seen_, &hidden_by_);
      poses.clear();
    }
  } catch (...) {
    failure_ = std::current_exception();
  }
}

}  // namespace cogmap::experiments
