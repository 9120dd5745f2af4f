// usable_cores follows the affinity mask, not the machine's core count.
#include "cogmap/experiments/usable_cores.h"

#include <gtest/gtest.h>

#if defined(__linux__)
#include <sched.h>
#endif

namespace cogmap::experiments {
namespace {

#if defined(__linux__)
TEST(UsableCores, FollowsTheAffinityMask) {
  cpu_set_t before;
  CPU_ZERO(&before);
  ASSERT_EQ(sched_getaffinity(0, sizeof(before), &before), 0);
  EXPECT_EQ(usable_cores(), static_cast<unsigned>(CPU_COUNT(&before)));
  // Pinned to one of its CPUs (this thread only: pid 0 is the caller), one core is usable.
  int first = 0;
  while (!CPU_ISSET(first, &before)) ++first;
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(first, &one);
  ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);
  const unsigned pinned = usable_cores();
  ASSERT_EQ(sched_setaffinity(0, sizeof(before), &before), 0);
  EXPECT_EQ(pinned, 1u);
}
#endif

TEST(UsableCores, AtLeastOne) { EXPECT_GE(usable_cores(), 1u); }

TEST(UsableCores, ACpuQuotaAllowsItsQuotientRoundedUp) {
  EXPECT_EQ(cores_of_cpu_quota("150000", "100000"), 2u);  // docker --cpus=1.5
  EXPECT_EQ(cores_of_cpu_quota("100000", "100000"), 1u);  // --cpus=1
  EXPECT_EQ(cores_of_cpu_quota("50000", "100000"), 1u);   // half a core: still one
  EXPECT_EQ(cores_of_cpu_quota("400000\n", " 100000"), 4u);
  // No quota, or nothing readable: no limit (0).
  EXPECT_EQ(cores_of_cpu_quota("max", "100000"), 0u);  // cgroup v2
  EXPECT_EQ(cores_of_cpu_quota("-1", "100000"), 0u);   // cgroup v1
  EXPECT_EQ(cores_of_cpu_quota("", ""), 0u);
  EXPECT_EQ(cores_of_cpu_quota("100000", "0"), 0u);
  EXPECT_EQ(cores_of_cpu_quota("1e5", "100000"), 0u);
  EXPECT_EQ(cores_of_cpu_quota("99999999999999999999", "1"), 0u);  // does not fit: ignored
}

}  // namespace
}  // namespace cogmap::experiments
