#include "cogmap/experiments/trajectory_rows.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace cogmap::experiments {
namespace {

// Rows go to the spill file as their own bytes and come back the same way.
static_assert(std::is_trivially_copyable_v<TrajectoryRow>);
constexpr std::size_t kChunkBytes = TrajectoryLog::kRowsPerChunk * sizeof(TrajectoryRow);

}  // namespace

TrajectoryView::Iterator::Iterator(const TrajectoryView* view, std::size_t piece)
    : view_(view), piece_(piece) {
  load();
}

TrajectoryView::Iterator& TrajectoryView::Iterator::operator++() {
  if (++row_ == rows_.size()) {  // pieces are never empty
    ++piece_;
    row_ = 0;
    load();
  }
  return *this;
}

void TrajectoryView::Iterator::load() {
  buffer_.reset();
  rows_ = {};
  if (view_ == nullptr || piece_ >= view_->pieces_.size()) return;
  const Piece& p = view_->pieces_[piece_];
  if (p.file_offset < 0) {
    rows_ = p.rows;
    return;
  }
  // A new buffer for every piece: a copy of this iterator may still be reading the last one.
  auto rows = std::make_shared<std::vector<TrajectoryRow>>(p.count);
  auto* bytes = reinterpret_cast<char*>(rows->data());
  const std::size_t want = p.count * sizeof(TrajectoryRow);
  std::size_t got = 0;
  while (got < want) {
    const ssize_t n = ::pread(view_->fd_, bytes + got, want - got,
                              static_cast<off_t>(p.file_offset + static_cast<std::int64_t>(got)));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      throw std::runtime_error("trajectory spill file: reading back rows at byte " +
                               std::to_string(p.file_offset + static_cast<std::int64_t>(got)) +
                               ": " + (n < 0 ? std::strerror(errno) : "file ends early"));
    }
    got += static_cast<std::size_t>(n);
  }
  rows_ = *rows;
  buffer_ = std::move(rows);
}

TrajectoryLog::TrajectoryLog(bool spill) {
  if (spill) file_.reset(std::tmpfile());
  spilling_ = file_ != nullptr;
  current_.reserve(kRowsPerChunk);
}

void TrajectoryLog::push_back(const TrajectoryRow& row) {
  current_.push_back(row);
  ++size_;
  if (current_.size() == kRowsPerChunk) spill_current();
}

void TrajectoryLog::spill_current() {
  if (spilling_) {
    // Written and flushed whole, so pread sees every byte of it; a short write (a full disk)
    // keeps this chunk and every later one in memory instead: the file's chunks stay the first
    // spilled_chunks_ of the run, each complete.
    std::FILE* f = file_.get();
    const bool written =
        std::fseek(f, static_cast<long>(spilled_chunks_ * kChunkBytes), SEEK_SET) == 0 &&
        std::fwrite(current_.data(), sizeof(TrajectoryRow), current_.size(), f) ==
            current_.size() &&
        std::fflush(f) == 0;
    if (written) {
      ++spilled_chunks_;
      current_.clear();
      return;
    }
    spilling_ = false;
  }
  kept_.push_back(std::move(current_));
  current_ = {};
  current_.reserve(kRowsPerChunk);
}

TrajectoryView TrajectoryLog::view() const {
  TrajectoryView v;
  if (file_) v.fd_ = ::fileno(file_.get());
  for (std::size_t k = 0; k < spilled_chunks_; ++k) {
    v.pieces_.push_back({{}, static_cast<std::int64_t>(k * kChunkBytes), kRowsPerChunk});
    v.size_ += kRowsPerChunk;
  }
  for (const std::vector<TrajectoryRow>& chunk : kept_) v.add_memory(chunk);
  v.add_memory(current_);
  return v;
}

}  // namespace cogmap::experiments
