// Line fitting, thesis §3.1.8, Eqs. 3.8-3.10.
//
// Eq. 3.8's y = b0 + b1 x cannot represent a vertical wall (b1 infinite), and Eq. 3.10's ρ is
// undefined for an exactly horizontal or vertical wall (no spread in y or x) and near zero for
// a noisy one, so a straight wall would be rejected or accepted depending on which way it runs.
// fit_line() therefore fits by orthogonal least squares (the principal axis of the covariance)
// and reports |ρ| as Eq. 3.10 evaluated in the frame where the fitted line runs at 45°. With
// covariance eigenvalues λ1 >= λ2 that frame has var x = var y = (λ1 + λ2)/2 and
// cov(x, y) = (λ1 − λ2)/2, hence |ρ| = (λ1 − λ2)/(λ1 + λ2): rotation invariant, and equal to the
// thesis's value for a line that already runs at 45°.

#include <cmath>

#include "cogmap/mapper/asr/stages.h"

namespace cogmap::mapper {

LineFit fit_line(std::span<const Point2> points) {
  LineFit fit;
  if (points.size() < 2) return fit;
  const double n = static_cast<double>(points.size());
  Point2 mean(0.0, 0.0);
  for (const Point2& p : points) mean += p;
  mean /= n;
  // Centred sums (two passes) keep the covariance accurate far from the origin.
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (const Point2& p : points) {
    const Point2 d = p - mean;
    sxx += d.x() * d.x();
    syy += d.y() * d.y();
    sxy += d.x() * d.y();
  }
  const double trace = sxx + syy;
  if (!(trace > 0.0)) return fit;                              // all points identical
  const double half_gap = std::hypot(0.5 * (sxx - syy), sxy);  // (λ1 − λ2)/2
  const double angle = 0.5 * std::atan2(2.0 * sxy, sxx - syy);
  fit.point = mean;
  fit.direction = Point2(std::cos(angle), std::sin(angle));
  fit.correlation = 2.0 * half_gap / trace;
  fit.valid = true;
  return fit;
}

RegressionFit regress_y_on_x(std::span<const Point2> points) {
  RegressionFit fit;
  const double n = static_cast<double>(points.size());
  double sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (const Point2& p : points) {
    sx += p.x();
    sy += p.y();
    sxx += p.x() * p.x();
    syy += p.y() * p.y();
    sxy += p.x() * p.y();
  }
  const double denom_x = n * sxx - sx * sx;
  const double denom_y = n * syy - sy * sy;
  if (points.size() < 2 || !(denom_x > 0.0) || !(denom_y > 0.0)) return fit;
  fit.b1 = (n * sxy - sx * sy) / denom_x;                                // Eq. 3.8
  fit.b0 = sy / n - fit.b1 * sx / n;                                     // Eq. 3.9
  fit.correlation = (n * sxy - sx * sy) / std::sqrt(denom_x * denom_y);  // Eq. 3.10
  fit.valid = true;
  return fit;
}

}  // namespace cogmap::mapper
