#pragma once
/// The frames of a run as the metrics read them: one row per frame, appended while the run goes
/// (TrajectoryLog) and read afterwards as one sequence (TrajectoryView).
///
/// Why not one vector: a run's rows grow with its length, not with its rooms (88 bytes a frame,
/// 0.9 MB for a 1 000 s drive, 3 MB an hour), and a doubling vector holds up to twice that. The
/// log keeps only the chunk being filled in memory and writes every full one to an unnamed
/// temporary file, from which the view reads it back a chunk at a time, so the peak memory of a
/// run does not grow with its length (docs/performance.md, "Growth").

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <memory>
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

/// Read-only rows in frame order, made of pieces held in memory or in a TrajectoryLog's spill
/// file. It does not own the rows: what it was made from must outlive it and not grow
/// meanwhile. A row read through an iterator stays valid only until that iterator advances
/// (a spilled piece is read into a buffer of the iterator's): copy what must outlive the step.
/// Several iterators may read at once, from several threads.
class TrajectoryView {
  struct Piece {
    std::span<const TrajectoryRow> rows;  ///< in memory; empty when spilled
    std::int64_t file_offset = -1;        ///< spilled: where its rows start in the file
    std::size_t count = 0;                ///< its number of rows (never 0)
  };

 public:
  class Iterator {
   public:
    using iterator_category = std::input_iterator_tag;
    using value_type = TrajectoryRow;
    using difference_type = std::ptrdiff_t;
    using pointer = const TrajectoryRow*;
    using reference = const TrajectoryRow&;

    Iterator() = default;
    reference operator*() const { return rows_[row_]; }
    pointer operator->() const { return &rows_[row_]; }
    Iterator& operator++();
    Iterator operator++(int) {
      Iterator before = *this;
      ++*this;
      return before;
    }
    bool operator==(const Iterator& other) const {
      return piece_ == other.piece_ && row_ == other.row_;
    }

   private:
    friend class TrajectoryView;
    Iterator(const TrajectoryView* view, std::size_t piece);
    void load();  // rows_ for piece_ (read back from the file when spilled)

    const TrajectoryView* view_ = nullptr;
    std::size_t piece_ = 0;
    std::size_t row_ = 0;
    std::span<const TrajectoryRow> rows_;
    std::shared_ptr<const std::vector<TrajectoryRow>> buffer_;  // a spilled piece, read back
  };

  TrajectoryView() = default;
  /// One piece in memory (implicit, so a vector of rows reads as a view).
  TrajectoryView(std::span<const TrajectoryRow> rows) {  // NOLINT(google-explicit-constructor)
    add_memory(rows);
  }
  TrajectoryView(const std::vector<TrajectoryRow>& rows)  // NOLINT(google-explicit-constructor)
      : TrajectoryView(std::span<const TrajectoryRow>(rows)) {}
  /// Pieces in memory, in order; empty ones are skipped.
  explicit TrajectoryView(std::span<const std::span<const TrajectoryRow>> pieces) {
    for (const auto& piece : pieces) add_memory(piece);
  }

  Iterator begin() const { return Iterator(this, 0); }
  Iterator end() const { return Iterator(this, pieces_.size()); }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

 private:
  friend class TrajectoryLog;
  void add_memory(std::span<const TrajectoryRow> piece) {
    if (piece.empty()) return;
    pieces_.push_back({piece, -1, piece.size()});
    size_ += piece.size();
  }

  int fd_ = -1;  // the spill file (pread: safe from several threads at once)
  std::vector<Piece> pieces_;
  std::size_t size_ = 0;
};

/// The rows of a run as it goes, appended one frame at a time.
class TrajectoryLog {
 public:
  /// 1024 rows (90 kB) a chunk: one write per ~100 s of a run at 10 Hz.
  static constexpr std::size_t kRowsPerChunk = 1024;

  /// `spill`: full chunks go to an unnamed temporary file (std::tmpfile, gone when the log is);
  /// when none can be made, or a write fails, the chunks stay in memory instead.
  explicit TrajectoryLog(bool spill = true);
  TrajectoryLog(const TrajectoryLog&) = delete;
  TrajectoryLog& operator=(const TrajectoryLog&) = delete;
  TrajectoryLog(TrajectoryLog&&) noexcept = default;
  TrajectoryLog& operator=(TrajectoryLog&&) noexcept = default;
  ~TrajectoryLog() = default;

  void push_back(const TrajectoryRow& row);
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  /// How many rows are in the spill file (the rest are in memory).
  std::size_t spilled_rows() const { return spilled_chunks_ * kRowsPerChunk; }
  /// Valid until the next push_back.
  TrajectoryView view() const;

 private:
  struct CloseFile {
    void operator()(std::FILE* f) const { std::fclose(f); }
  };
  void spill_current();

  std::unique_ptr<std::FILE, CloseFile> file_;    // null: everything stays in memory
  bool spilling_ = false;                         // ...and false too once a write has failed
  std::size_t spilled_chunks_ = 0;                // the file's chunks: the run's first ones
  std::vector<std::vector<TrajectoryRow>> kept_;  // full chunks in memory (after the file's)
  std::vector<TrajectoryRow> current_;            // the chunk being filled
  std::size_t size_ = 0;
};

}  // namespace cogmap::experiments
