// HelperThread: every job of every list runs exactly once, whichever thread takes it, also
// across lists published faster than the helper wakes and after the helper has gone to sleep.
#include "helper_thread.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

namespace cogmap::sim::sonar_detail {
namespace {

// Runs one list of n jobs; each job counts its own calls and records the thread it ran on.
struct ListResult {
  std::vector<int> calls;
  int on_owner = 0, on_helper = 0;
};

ListResult run_list(HelperThread& helper, int n) {
  ListResult r;
  r.calls.assign(static_cast<std::size_t>(n), 0);
  std::vector<std::thread::id> ran_on(static_cast<std::size_t>(n));
  helper.run(n, [&](int i) {
    ++r.calls[static_cast<std::size_t>(i)];  // each slot is written by one call only
    ran_on[static_cast<std::size_t>(i)] = std::this_thread::get_id();
  });
  for (const std::thread::id id : ran_on) {
    (id == std::this_thread::get_id() ? r.on_owner : r.on_helper) += 1;
  }
  return r;
}

TEST(HelperThread, EveryJobOfEveryListRunsExactlyOnce) {
  HelperThread helper;
  for (int list = 0; list < 20000; ++list) {
    const int n = list % 9;  // 0-8 jobs: a frame's pings, and the empty and single lists
    const ListResult r = run_list(helper, n);
    for (int i = 0; i < n; ++i)
      ASSERT_EQ(r.calls[static_cast<std::size_t>(i)], 1) << list << " " << i;
    ASSERT_EQ(r.on_owner + r.on_helper, n);
  }
}

TEST(HelperThread, TheHelperTakesAJobWhileTheOwnerIsBusy) {
  // Two jobs, each holding on until both have started: they can only both start if the helper
  // took one, so the owner cannot finish the list alone (no timing claim: the helper is
  // scheduled eventually; the 10 s bound only keeps a broken helper from hanging the test).
  HelperThread helper;
  for (int round = 0; round < 20; ++round) {
    std::atomic<int> started{0};
    std::vector<std::thread::id> ran_on(2);
    helper.run(2, [&](int i) {
      ran_on[static_cast<std::size_t>(i)] = std::this_thread::get_id();
      ++started;
      const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
      while (started.load() < 2 && std::chrono::steady_clock::now() < give_up) {
        std::this_thread::yield();
      }
    });
    ASSERT_EQ(started.load(), 2);
    EXPECT_NE(ran_on[0], ran_on[1]) << round;
  }
}

TEST(HelperThread, ListsLongerThanTheCounterGoInPieces) {
  HelperThread helper;
  const ListResult r = run_list(helper, 200000);  // the shared counter holds 16 bits
  for (std::size_t i = 0; i < r.calls.size(); ++i) ASSERT_EQ(r.calls[i], 1) << i;
}

TEST(HelperThread, WorksAgainAfterTheHelperHasGoneToSleep) {
  HelperThread helper;
  for (int round = 0; round < 3; ++round) {
    // Long enough for the helper to stop spinning and wait for the next list.
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
    std::atomic<long> sum{0};
    helper.run(1000, [&](int i) { sum += i; });
    EXPECT_EQ(sum.load(), 999L * 1000 / 2);
  }
}

TEST(HelperThread, SharedResultsMatchASingleThread) {
  // Jobs of uneven cost writing their own slots: the result does not depend on who ran what.
  auto work = [](int i) {
    double x = i;
    for (int k = 0; k < (i % 7) * 500; ++k) x = x * 0.999 + 1.0;
    return x;
  };
  std::vector<double> alone(64), shared(64);
  for (int i = 0; i < 64; ++i) alone[static_cast<std::size_t>(i)] = work(i);
  HelperThread helper;
  for (int round = 0; round < 200; ++round) {
    helper.run(64, [&](int i) { shared[static_cast<std::size_t>(i)] = work(i); });
    ASSERT_EQ(shared, alone) << round;
  }
}

// Two jobs that hold on until both have started, so each thread has one (see above); the
// job on `thrower` throws. Returns once run() has thrown (or not).
struct TwoJobs {
  std::atomic<int> started{0};
  std::vector<std::thread::id> ran_on = std::vector<std::thread::id>(2);
  std::vector<int> finished = std::vector<int>(2, 0);
};

void hold_until_both_started(TwoJobs& jobs) {
  ++jobs.started;
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (jobs.started.load() < 2 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::yield();
  }
}

TEST(HelperThread, AJobThrownOnTheHelperIsRethrownByRun) {
  HelperThread helper;
  const std::thread::id owner = std::this_thread::get_id();
  for (int round = 0; round < 10; ++round) {
    TwoJobs jobs;
    EXPECT_THROW(helper.run(2,
                            [&](int i) {
                              jobs.ran_on[static_cast<std::size_t>(i)] = std::this_thread::get_id();
                              hold_until_both_started(jobs);
                              if (std::this_thread::get_id() != owner) {
                                throw std::runtime_error("helper job failed");
                              }
                              jobs.finished[static_cast<std::size_t>(i)] = 1;
                            }),
                 std::runtime_error);
    EXPECT_EQ(jobs.started.load(), 2);
    // The owner's job still finished.
    EXPECT_EQ(jobs.finished[0] + jobs.finished[1], 1);
  }
  // And the helper serves the next list as before.
  const ListResult r = run_list(helper, 8);
  for (const int c : r.calls) EXPECT_EQ(c, 1);
}

TEST(HelperThread, AJobThrownOnTheOwnerWaitsForTheHelpersJobThenStopsTheList) {
  HelperThread helper;
  const std::thread::id owner = std::this_thread::get_id();
  for (int round = 0; round < 10; ++round) {
    TwoJobs jobs;
    std::atomic<int> later_jobs{0};
    EXPECT_THROW(helper.run(50,
                            [&](int i) {
                              if (i >= 2) {
                                ++later_jobs;
                                return;
                              }
                              hold_until_both_started(jobs);
                              if (std::this_thread::get_id() == owner) {
                                throw std::logic_error("owner job failed");
                              }
                              // The helper's job is still running when the owner throws: run()
                              // must not return before it has finished writing.
                              std::this_thread::sleep_for(std::chrono::milliseconds(20));
                              jobs.finished[static_cast<std::size_t>(i)] = 1;
                            }),
                 std::logic_error);
    EXPECT_EQ(jobs.finished[0] + jobs.finished[1], 1);
    // Each thread held one of the first two jobs until the owner threw and closed the list:
    // none of the 48 later ones ran.
    EXPECT_EQ(later_jobs.load(), 0);
  }
  const ListResult r = run_list(helper, 8);
  for (const int c : r.calls) EXPECT_EQ(c, 1);
}

TEST(HelperThread, StopsWhileSpinningAndWhileAsleep) {
  { HelperThread spinning; }  // destroyed at once, still spinning
  {
    HelperThread sleeping;
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
  }
  SUCCEED();  // neither destructor hangs (ctest's timeout would catch one that did)
}

}  // namespace
}  // namespace cogmap::sim::sonar_detail
