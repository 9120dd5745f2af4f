// Dempster-Shafer (§2.2.2): Table 2.3 masses and Dempster's rule (Eqs. 2.11-2.13).

#include <gtest/gtest.h>

#include <random>

#include "cogmap/mapper/grid/grid_updater.h"
#include "grid/grid_test_support.h"
#include "grid/sensor_models.h"

namespace cogmap::mapper {
namespace {

using testing::echo;
using testing::single_forward_sonar;

using testing::kRobot;

TEST(DempsterShaferModel, TableMasses) {
  const DsMass one = ds_region_one(0.9, 0.98);
  EXPECT_FLOAT_EQ(one.occupied, 0.882f);
  EXPECT_FLOAT_EQ(one.empty, 0.0f);
  EXPECT_FLOAT_EQ(one.unknown, 0.118f);
  const DsMass two = ds_region_two(0.95);
  EXPECT_FLOAT_EQ(two.occupied, 0.0f);
  EXPECT_FLOAT_EQ(two.empty, 0.95f);
  EXPECT_FLOAT_EQ(two.unknown, 0.05f);
}

TEST(DempsterShaferModel, ConflictNormalisationByHand) {
  // a = (0.6, 0.3, 0.1), b = (0.5, 0.2, 0.3):
  // K = 0.6·0.2 + 0.3·0.5 = 0.27; O = 0.30 + 0.18 + 0.05 = 0.53; E = 0.06 + 0.09 + 0.02 = 0.17;
  // Θ = 0.03; each divided by 1 - K = 0.73.
  const DsCombination c = dempster_combine({0.6f, 0.3f, 0.1f}, {0.5f, 0.2f, 0.3f});
  EXPECT_NEAR(c.conflict, 0.27, 1e-7);
  EXPECT_NEAR(c.mass.occupied, 0.53 / 0.73, 1e-6);
  EXPECT_NEAR(c.mass.empty, 0.17 / 0.73, 1e-6);
  EXPECT_NEAR(c.mass.unknown, 0.03 / 0.73, 1e-6);
  EXPECT_NEAR(c.mass.occupied + c.mass.empty + c.mass.unknown, 1.0, 1e-6);
}

TEST(DempsterShaferModel, VacuousEvidenceIsNeutralAndTotalConflictIsRefused) {
  const DsMass m{0.2f, 0.5f, 0.3f};
  const DsCombination v = dempster_combine(m, DsMass{});
  EXPECT_FLOAT_EQ(v.mass.occupied, 0.2f);
  EXPECT_FLOAT_EQ(v.mass.empty, 0.5f);
  EXPECT_FLOAT_EQ(v.mass.unknown, 0.3f);
  EXPECT_EQ(v.conflict, 0.0);
  const DsCombination t = dempster_combine({1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
  EXPECT_EQ(t.conflict, 1.0);
  EXPECT_FLOAT_EQ(t.mass.occupied, 1.0f);
}

TEST(DempsterShaferModel, KeepOpenAndHistogramScale) {
  const DsMass k = keep_open({0.9995f, 0.0f, 0.0005f}, 0.001);
  EXPECT_FLOAT_EQ(k.unknown, 0.001f);
  EXPECT_FLOAT_EQ(k.occupied, 0.999f);
  EXPECT_FLOAT_EQ(ds_to_histogram(DsMass{}), 0.0f);
  EXPECT_FLOAT_EQ(ds_to_histogram({1.0f, 0.0f, 0.0f}), 15.0f);
  EXPECT_FLOAT_EQ(ds_to_histogram({0.0f, 1.0f, 0.0f}), -3.0f);
  EXPECT_FLOAT_EQ(ds_to_histogram({0.5f, 0.25f, 0.25f}), 6.75f);
}

TEST(DempsterShaferUpdater, OneReadingByHand) {
  auto u = make_grid_updater(GridKind::kDempsterShafer, {}, single_forward_sonar());
  u->reset({0.0, 0.0});
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));
  EXPECT_NEAR(u->histogram_at({70, 60}), 15.0 * 0.882, 1e-4);  // region I on the axis
  EXPECT_NEAR(u->histogram_at({65, 60}), -3.0 * 0.95, 1e-4);   // region II at 0.5 m
  EXPECT_FLOAT_EQ(u->histogram_at({72, 60}), 0.0f);
  // Second reading: m(O) = 1 - 0.118² (no conflict: region I carries no m(E)).
  ASSERT_TRUE(u->integrate(kRobot, echo(0, 1.0)));
  EXPECT_NEAR(u->histogram_at({70, 60}), 15.0 * (1.0 - 0.118 * 0.118), 1e-4);
}

TEST(DempsterShaferUpdater, HistogramStaysInScaleAfterManyReadings) {
  auto u = make_grid_updater(GridKind::kDempsterShafer, {}, p2at_geometry());
  u->reset({0.0, 0.0});
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> range(0.3, 5.0), pos(-1.0, 1.0), turn(-3.1, 3.1);
  std::uniform_int_distribution<int> sonar(0, 15);
  for (int i = 0; i < 400; ++i) {
    const Pose2 pose{pos(rng), pos(rng), turn(rng)};
    ASSERT_TRUE(u->integrate(pose, {sonar(rng), range(rng), i % 7 != 0, 0.0}));
  }
  // The masses are private (their normalisation is checked on the model below); every cell's
  // HIMM-scale value must stay within [-3, 15], which fails if any mass leaves [0, 1].
  const HistogramGrid h = u->histogram();
  int occupied = 0, empty = 0;
  for (std::size_t i = 0; i < h.geometry().cell_count(); ++i) {
    ASSERT_GE(h.data()[i], -3.0f);
    ASSERT_LE(h.data()[i], 15.0f);
    occupied += h.data()[i] > 7.0f;
    empty += h.data()[i] < 0.0f;
  }
  EXPECT_GT(occupied, 0);
  EXPECT_GT(empty, 0);
}

TEST(DempsterShaferModel, RandomCombinationsStayNormalised) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u01(0.0, 1.0);
  DsMass m;
  for (int i = 0; i < 10000; ++i) {
    const double w = u01(rng);
    const DsMass e = u01(rng) < 0.5 ? ds_region_one(w, 0.98) : ds_region_two(w);
    m = keep_open(dempster_combine(m, e).mass, 0.001);
    ASSERT_NEAR(m.occupied + m.empty + m.unknown, 1.0, 1e-5) << i;
    ASSERT_GE(m.unknown, 0.001f * (1 - 1e-6));
    ASSERT_GE(m.occupied, 0.0f);
    ASSERT_GE(m.empty, 0.0f);
  }
}

}  // namespace
}  // namespace cogmap::mapper
