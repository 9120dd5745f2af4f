#include "helper_thread.h"

#include <algorithm>
#include <exception>
#include <utility>

namespace cogmap::sim::sonar_detail {
namespace {

constexpr std::uint64_t kMaxJobsPerList = 0xFFFF;
// About a millisecond of spinning between lists before the helper sleeps (a pause is ~40 ns on
// the Xeon host, ~10 ns on older cores): a frame's pings come every 30-40 µs of wall time while
// a run goes, and waking a sleeping thread takes longer than that.
constexpr int kSpinsBeforeSleep = 20000;
// Every ~3 µs of spinning the helper yields: a thread of this process (the metrics) or of
// another run sharing the cores then gets the core while the helper has nothing to do. Every
// 16, 64 or 256 pauses measured alike on one run; without yields two runs at once on two
// cores took 10-15 % longer than with one thread each (docs/performance.md).
constexpr int kSpinsPerYield = 64;

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

}  // namespace

HelperThread::HelperThread() : thread_([this] { serve(); }) {}

HelperThread::~HelperThread() {
  stop_.store(true, std::memory_order_seq_cst);
  wake_.fetch_add(1, std::memory_order_seq_cst);
  wake_.notify_one();
  thread_.join();
}

HelperThread::Taken HelperThread::take(std::uint32_t generation, std::uint64_t most) {
  std::uint64_t list = list_.load(std::memory_order_acquire);
  for (;;) {
    if (static_cast<std::uint32_t>(list >> 32) != generation) return {};
    const std::uint64_t count = (list >> 16) & kMaxJobsPerList;
    const std::uint64_t next = list & kMaxJobsPerList;
    if (next >= count) return {};
    const std::uint64_t taken = std::min(most, count - next);
    if (list_.compare_exchange_weak(list, list + taken, std::memory_order_acq_rel,
                                    std::memory_order_acquire)) {
      return {static_cast<int>(next), static_cast<int>(taken)};
    }
  }
}

void HelperThread::run_erased(int n, void* context, Call call) {
  // Longer lists go in pieces (the counter has 16 bits); the sonar's never need it.
  for (int first = 0; first < n;) {
    const int count = static_cast<int>(std::min<std::uint64_t>(kMaxJobsPerList, n - first));
    context_ = context;
    call_ = call;
    first_ = first;
    helper_done_.store(0, std::memory_order_relaxed);
    ++generation_;
    list_.store(static_cast<std::uint64_t>(generation_) << 32 | static_cast<std::uint64_t>(count)
                                                                    << 16,
                std::memory_order_release);
    wake_.fetch_add(1, std::memory_order_seq_cst);
    if (sleeping_.load(std::memory_order_seq_cst)) wake_.notify_one();
    int mine = 0;  // jobs this thread took, or closed unrun after a failure
    std::exception_ptr failure;
    for (Taken job; (job = take(generation_, 1)).count > 0;) {
      ++mine;
      try {
        call(context, first + job.first);
      } catch (...) {
        // Run no more of this list, but let the helper finish what it took: it still uses the
        // job's context and what the jobs write, which leave scope when this throws.
        failure = std::current_exception();
        mine += take(generation_, kMaxJobsPerList).count;
        break;
      }
    }
    // Only jobs the helper has already taken are left: wait for them.
    for (int spins = 0; helper_done_.load(std::memory_order_acquire) != count - mine; ++spins) {
      if (spins < 1000) {
        cpu_relax();
      } else {
        std::this_thread::yield();  // the helper was descheduled inside a job
      }
    }
    // A job that threw on the helper is rethrown here, as it would have been on one thread.
    std::exception_ptr helper_failure = std::exchange(helper_failure_, nullptr);
    if (!failure) failure = std::move(helper_failure);
    if (failure) std::rethrow_exception(failure);
    first += count;
  }
}

void HelperThread::serve() {
  std::uint32_t seen = 0;
  for (;;) {
    int spins = 0;
    for (;;) {
      if (stop_.load(std::memory_order_acquire)) return;
      const auto generation =
          static_cast<std::uint32_t>(list_.load(std::memory_order_acquire) >> 32);
      if (generation != seen) {
        seen = generation;
        break;
      }
      if (++spins < kSpinsBeforeSleep) {
        // Give the core away now and then, so that other threads run while this one has
        // nothing to do rather than preempt it inside a job.
        if (spins % kSpinsPerYield == 0) {
          std::this_thread::yield();
        } else {
          cpu_relax();
        }
        continue;
      }
      // Sleep until the owner publishes a list (or stops). The owner bumps wake_ after
      // publishing and then looks at sleeping_; either it sees the flag and wakes us, or we see
      // its new wake_ value here (both sides sequentially consistent) and do not sleep.
      const std::uint32_t ticket = wake_.load(std::memory_order_seq_cst);
      sleeping_.store(true, std::memory_order_seq_cst);
      if (static_cast<std::uint32_t>(list_.load(std::memory_order_seq_cst) >> 32) == seen &&
          !stop_.load(std::memory_order_seq_cst)) {
        wake_.wait(ticket, std::memory_order_seq_cst);
      }
      sleeping_.store(false, std::memory_order_relaxed);
      spins = 0;
    }
    for (Taken job; (job = take(seen, 1)).count > 0;) {
      int finished = 1;
      try {
        call_(context_, first_ + job.first);
      } catch (...) {
        // Kept for the owner, who rethrows it once the list is done; the rest of the list is
        // closed (counted as this thread's, unrun).
        helper_failure_ = std::current_exception();
        finished += take(seen, kMaxJobsPerList).count;
      }
      helper_done_.fetch_add(finished, std::memory_order_release);
    }
  }
}

}  // namespace cogmap::sim::sonar_detail
