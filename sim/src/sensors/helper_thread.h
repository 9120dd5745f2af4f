#pragma once
/// A second thread that shares short lists of independent jobs with the thread that owns it
/// (internal to the sonar model: a frame's pings, docs/performance.md "Pings on two threads").

#include <atomic>
#include <cstdint>
#include <exception>
#include <thread>
#include <type_traits>

namespace cogmap::sim::sonar_detail {

/// run(n, job) calls job(i) exactly once for each i in [0, n), some on the calling thread and
/// some on the helper, and returns when every call has returned. Jobs are taken one at a time
/// from a shared counter, so the caller never waits for a helper that has not started yet (a
/// helper the operating system has not scheduled only means the caller does every job itself);
/// it waits only for a job the helper has already taken. Between lists the helper spins for a
/// millisecond, yielding now and then (in the frame loop a list comes every ~40 µs), then sleeps
/// until the next list. One owner thread calls run(); jobs must not call run() themselves. A job
/// that throws (on either thread) stops the list: jobs not yet taken do not run, those taken
/// finish, and run() rethrows the first exception.
class HelperThread {
 public:
  HelperThread();
  ~HelperThread();
  HelperThread(const HelperThread&) = delete;
  HelperThread& operator=(const HelperThread&) = delete;

  template <class Job>
  void run(int n, Job&& job) {
    run_erased(n, &job, [](void* context, int i) {
      (*static_cast<std::remove_reference_t<Job>*>(context))(i);
    });
  }

 private:
  using Call = void (*)(void* context, int i);
  void run_erased(int n, void* context, Call call);
  /// Jobs taken from a list: the first one's index and how many (0: none).
  struct Taken {
    int first = 0;
    int count = 0;
  };
  /// Takes up to `most` jobs of list `generation` that nobody has taken yet (none when that
  /// list is done or no longer the current one). One job to run it; all that are left to close
  /// the list after a failure, unrun.
  Taken take(std::uint32_t generation, std::uint64_t most);
  void serve();

  // One word so that a job is taken only from the list it belongs to: generation (high 32
  // bits) | job count (16 bits) | next job (low 16 bits).
  std::atomic<std::uint64_t> list_{0};
  std::atomic<int> helper_done_{0};     // jobs of the current list the helper has finished
  std::atomic<std::uint32_t> wake_{0};  // bumped for every list; the sleeping helper waits on it
  std::atomic<bool> sleeping_{false};
  std::atomic<bool> stop_{false};
  // A job's exception on the helper: written before helper_done_ counts that job (release), read
  // by the owner after it has seen the count (acquire).
  std::exception_ptr helper_failure_;
  std::uint32_t generation_ = 0;  // the owner's: the current list
  // The current list's job, and the index of its first job when a long list goes in pieces:
  // written before list_ is published, read after a job is taken.
  void* context_ = nullptr;
  Call call_ = nullptr;
  int first_ = 0;
  std::thread thread_;
};

}  // namespace cogmap::sim::sonar_detail
