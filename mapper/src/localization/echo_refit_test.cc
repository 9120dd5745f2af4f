// Wall directions refitted to echo end points (echo_refit.h) on exact synthetic echoes: a
// segment fitted 1° off the wall its echoes lie on takes the wall's direction, centred on the
// echoes; echoes off the band or past the ends do not count; too few echoes or too large a turn
// leave the segment as fitted.
#include "cogmap/mapper/localization/echo_refit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cogmap/test_support/angles.h"

namespace cogmap::mapper {
namespace {

/// 39 echoes at x = 0.1 ... 3.9 on the line through (2, 0.01) at `angle_rad` to the x axis.
std::vector<Point2> wall_echoes(double angle_rad) {
  std::vector<Point2> echoes;
  for (int i = 1; i <= 39; ++i) {
    const double x = 0.1 * i;
    echoes.emplace_back(x, 0.01 + (x - 2.0) * std::tan(angle_rad));
  }
  return echoes;
}

EchoRefitOptions options(double band_m, int min_echoes, double max_turn_deg) {
  EchoRefitOptions o;
  o.band_m = band_m;
  o.min_echoes = min_echoes;
  o.max_turn_rad = max_turn_deg * kDeg;
  return o;
}

double direction_rad(const Polyline& segment) {
  const Point2 d = segment[1] - segment[0];
  return std::atan2(d.y(), d.x());
}

TEST(EchoRefit, TakesTheDirectionOfTheEchoesCentredOnThem) {
  const std::vector<Polyline> walls{{{0.0, 0.0}, {4.0, 0.0}}};  // fitted along x
  const std::vector<Polyline> out =
      refit_wall_directions(walls, wall_echoes(1.0 * kDeg), options(0.1, 20, 5.0));
  ASSERT_EQ(out.size(), 1u);
  ASSERT_EQ(out[0].size(), 2u);
  EXPECT_NEAR(direction_rad(out[0]), 1.0 * kDeg, 1e-12);
  EXPECT_NEAR((out[0][1] - out[0][0]).norm(), 4.0, 1e-12);  // as long as the fitted segment
  // Centred on the echoes' mean: x symmetric about 2, so (2, 0.01).
  const Point2 centre = 0.5 * (out[0][0] + out[0][1]);
  EXPECT_NEAR(centre.x(), 2.0, 1e-12);
  EXPECT_NEAR(centre.y(), 0.01, 1e-12);
}

TEST(EchoRefit, EchoesOffTheBandOrPastTheEndsDoNotCount) {
  const std::vector<Polyline> walls{{{0.0, 0.0}, {4.0, 0.0}}};
  std::vector<Point2> echoes = wall_echoes(1.0 * kDeg);
  echoes.emplace_back(2.0, 0.5);   // a desk 0.5 m in front: beyond the 0.1 m band
  echoes.emplace_back(3.5, -0.2);  // behind the wall, beyond the band
  echoes.emplace_back(-0.5, 0.0);  // before the segment's start
  echoes.emplace_back(4.6, 0.05);  // past its end
  const std::vector<Polyline> out = refit_wall_directions(walls, echoes, options(0.1, 20, 5.0));
  ASSERT_EQ(out.size(), 1u);
  EXPECT_NEAR(direction_rad(out[0]), 1.0 * kDeg, 1e-12);
  // A band wide enough to take the echo 0.2 m behind turns the answer: the band is what counts.
  const std::vector<Polyline> wide = refit_wall_directions(walls, echoes, options(0.3, 20, 5.0));
  EXPECT_GT(std::abs(direction_rad(wide[0]) - 1.0 * kDeg), 1e-4);
}

TEST(EchoRefit, TooFewEchoesOrTooLargeATurnLeaveTheSegment) {
  const std::vector<Polyline> walls{{{0.0, 0.0}, {4.0, 0.0}}};
  const Polyline fitted{{0.0, 0.0}, {4.0, 0.0}};
  // 39 echoes, 40 needed.
  EXPECT_EQ(refit_wall_directions(walls, wall_echoes(1.0 * kDeg), options(0.1, 40, 5.0)),
            std::vector<Polyline>{fitted});
  // 39 needed: refitted.
  EXPECT_NE(refit_wall_directions(walls, wall_echoes(1.0 * kDeg), options(0.1, 39, 5.0)),
            std::vector<Polyline>{fitted});
  // The echoes turn it by 3°, 2° allowed; 4° allowed refits it.
  EXPECT_EQ(refit_wall_directions(walls, wall_echoes(3.0 * kDeg), options(0.2, 20, 2.0)),
            std::vector<Polyline>{fitted});
  EXPECT_NEAR(direction_rad(
                  refit_wall_directions(walls, wall_echoes(3.0 * kDeg), options(0.2, 20, 4.0))[0]),
              3.0 * kDeg, 1e-12);
}

TEST(EchoRefit, EverySegmentOnItsOwnKeepingItsWay) {
  // An L drawn right to left and then up: (4, 0) -> (0, 0) -> (0, 3), and a zero-length piece.
  const std::vector<Polyline> walls{{{4.0, 0.0}, {0.0, 0.0}, {0.0, 3.0}, {0.0, 3.0}}};
  const std::vector<Polyline> out =
      refit_wall_directions(walls, wall_echoes(1.0 * kDeg), options(0.1, 20, 5.0));
  ASSERT_EQ(out.size(), 2u);  // the zero-length piece is dropped
  // The first points the way it was drawn (−x), turned by the echoes' 1°.
  EXPECT_NEAR(direction_rad(out[0]), -kPi + 1.0 * kDeg, 1e-12);
  // The second has no echoes: as fitted.
  EXPECT_EQ(out[1], (Polyline{{0.0, 0.0}, {0.0, 3.0}}));
}

}  // namespace
}  // namespace cogmap::mapper
