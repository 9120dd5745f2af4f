#pragma once
/// The frames of a run as the metrics read them: one row per frame, kept in fixed-size chunks
/// while the run grows (TrajectoryLog) and read as one sequence (TrajectoryView).
///
/// Why chunks: a vector doubling its capacity holds up to twice the rows it needs and, while it
/// moves them, three times; for a 36-room block (9,700 frames of 88 bytes) that slack was the
/// largest piece of the peak memory that grows with the run (docs/performance.md, "Growth").

#include <cstddef>
#include <iterator>
#include <optional>
#include <span>
#include <vector>

#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::experiments {

/// One frame of the run, world frame.
struct TrajectoryRow {
  double t_s = 0.0;
  std::optional<mapper::Pose2> truth;  ///< empty on a real robot
  mapper::Pose2 odometry;              ///< odometry composed with the known start pose
  mapper::Pose2 estimate;              ///< the mapper's corrected estimate
};

/// Read-only rows in frame order, made of one or more contiguous pieces. It does not own the
/// rows: the log or vector it was made from must outlive it and not grow meanwhile.
class TrajectoryView {
 public:
  class Iterator {
   public:
    using iterator_category = std::forward_iterator_tag;
    using value_type = TrajectoryRow;
    using difference_type = std::ptrdiff_t;
    using pointer = const TrajectoryRow*;
    using reference = const TrajectoryRow&;

    Iterator() = default;
    reference operator*() const { return (*piece_)[row_]; }
    pointer operator->() const { return &(*piece_)[row_]; }
    Iterator& operator++() {
      if (++row_ == piece_->size()) {  // pieces are never empty
        ++piece_;
        row_ = 0;
      }
      return *this;
    }
    Iterator operator++(int) {
      Iterator before = *this;
      ++*this;
      return before;
    }
    bool operator==(const Iterator& other) const = default;

   private:
    friend class TrajectoryView;
    Iterator(const std::span<const TrajectoryRow>* piece, std::size_t row)
        : piece_(piece), row_(row) {}
    const std::span<const TrajectoryRow>* piece_ = nullptr;
    std::size_t row_ = 0;
  };

  TrajectoryView() = default;
  /// One contiguous piece (implicit, so a vector of rows reads as a view).
  TrajectoryView(std::span<const TrajectoryRow> rows) {  // NOLINT(google-explicit-constructor)
    add(rows);
  }
  TrajectoryView(const std::vector<TrajectoryRow>& rows)  // NOLINT(google-explicit-constructor)
      : TrajectoryView(std::span<const TrajectoryRow>(rows)) {}
  /// The pieces in order; empty ones are skipped.
  explicit TrajectoryView(std::span<const std::span<const TrajectoryRow>> pieces) {
    for (const auto& piece : pieces) add(piece);
  }

  Iterator begin() const { return {pieces_.data(), 0}; }
  Iterator end() const { return {pieces_.data() + pieces_.size(), 0}; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

 private:
  void add(std::span<const TrajectoryRow> piece) {
    if (piece.empty()) return;
    pieces_.push_back(piece);
    size_ += piece.size();
  }

  std::vector<std::span<const TrajectoryRow>> pieces_;
  std::size_t size_ = 0;
};

/// The rows of a run as it goes, appended one frame at a time; rows never move once added.
class TrajectoryLog {
 public:
  /// 1024 rows (90 kB) a chunk: below glibc's mmap threshold, and a 10,000-frame run needs ten.
  static constexpr std::size_t kRowsPerChunk = 1024;

  void push_back(const TrajectoryRow& row) {
    if (chunks_.empty() || chunks_.back().size() == kRowsPerChunk) {
      chunks_.emplace_back().reserve(kRowsPerChunk);
    }
    chunks_.back().push_back(row);
    ++size_;
  }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  /// Valid until the next push_back.
  TrajectoryView view() const {
    std::vector<std::span<const TrajectoryRow>> pieces(chunks_.begin(), chunks_.end());
    return TrajectoryView(pieces);
  }

 private:
  std::vector<std::vector<TrajectoryRow>> chunks_;  // each reserved to kRowsPerChunk
  std::size_t size_ = 0;
};

}  // namespace cogmap::experiments
