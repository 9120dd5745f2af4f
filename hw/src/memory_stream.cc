// In-memory stream pair: two byte queues guarded by one mutex, for codec and robot tests.
#include <algorithm>
#include <condition_variable>
#include <deque>
#include <mutex>

#include "cogmap/hw/byte_stream.h"

namespace cogmap::hw {
namespace {

struct Shared {
  std::mutex mutex;
  std::condition_variable cv;
  std::deque<std::uint8_t> queue[2];  // queue[i] is read by end i
  bool closed[2] = {false, false};    // end i was destroyed
};

class MemoryEnd final : public ByteStream {
 public:
  MemoryEnd(std::shared_ptr<Shared> shared, int side) : shared_(std::move(shared)), side_(side) {}
  ~MemoryEnd() override {
    std::lock_guard lock(shared_->mutex);
    shared_->closed[side_] = true;
    shared_->cv.notify_all();
  }

  void write(std::span<const std::uint8_t> bytes) override {
    std::lock_guard lock(shared_->mutex);
    if (shared_->closed[1 - side_]) throw StreamClosed(name() + ": peer closed");
    auto& q = shared_->queue[1 - side_];
    q.insert(q.end(), bytes.begin(), bytes.end());
    shared_->cv.notify_all();
  }

  std::size_t read(std::span<std::uint8_t> buffer, std::chrono::milliseconds timeout) override {
    std::unique_lock lock(shared_->mutex);
    auto& q = shared_->queue[side_];
    shared_->cv.wait_for(lock, timeout, [&] { return !q.empty() || shared_->closed[1 - side_]; });
    if (q.empty()) {
      if (shared_->closed[1 - side_]) throw StreamClosed(name() + ": peer closed");
      return 0;
    }
    const std::size_t n = std::min(buffer.size(), q.size());
    std::copy_n(q.begin(), n, buffer.begin());
    q.erase(q.begin(), q.begin() + static_cast<std::ptrdiff_t>(n));
    return n;
  }

  std::string name() const override { return side_ == 0 ? "memory:a" : "memory:b"; }

 private:
  std::shared_ptr<Shared> shared_;
  int side_;
};

}  // namespace

std::pair<std::unique_ptr<ByteStream>, std::unique_ptr<ByteStream>> make_memory_pair() {
  auto shared = std::make_shared<Shared>();
  return {std::make_unique<MemoryEnd>(shared, 0), std::make_unique<MemoryEnd>(shared, 1)};
}

}  // namespace cogmap::hw
