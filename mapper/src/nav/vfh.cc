#include "cogmap/mapper/nav/vfh.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "cogmap/mapper/grid/grid.h"
#include "nav/nav_constants.h"
#include "nav/turn_backs.h"

namespace cogmap::mapper::nav {
namespace {}  // namespace

Vfh::Vfh(const VfhOptions& options) : options_(options) {
  const double sector_deg = options_.sector_deg > 0.0 ? options_.sector_deg : 5.0;
  const int count = std::max(4, static_cast<int>(std::lround(360.0 / sector_deg)));
  sector_rad_ = 2.0 * kPi / count;
  density_.assign(count, 0.0);
  smoothed_.assign(count, 0.0);
  blocked_.assign(count, 0);
  for (int k = 0; k < count; ++k) {
    const double border = (k - 0.5) * sector_rad_;
    borders_.emplace_back(std::cos(border), std::sin(border));
  }
  borders_.push_back(borders_.front());  // the last sector's upper border
  // Automatic τ_high: a cell of full certainty (15) blocks its sectors once within
  // block_range_m (1.5 m: 2.4 s at 0.5 m/s to steer around it); a lone echo or a barely
  // occupied cell (certainty 8) never blocks on its own, so one spurious sonar reading cannot
  // close a doorway. Farther walls only make the robot prefer other directions.
  const double c = kHistogramMax;
  threshold_ =
      options_.threshold > 0.0 ? options_.threshold : c * c * kappa_at(options_.block_range_m);
}

int Vfh::wrap(int sector) const {
  const int n = sector_count();
  const int s = sector % n;  // in (-n, n): one division, not two
  return s < 0 ? s + n : s;
}

int Vfh::sector_of(double angle_rad) const {
  // Shift by half a sector so sector 0 is centred on 0 rad, then fold into [0, 2π). The
  // angles met here lie within (-2π, 4π) (a direction ± an enlargement): fmod returns those
  // below 2π unchanged and takes 2π off those above, exactly (Sterbenz), so a subtraction
  // gives the same bits without fmod's cost.
  const double two_pi = 2.0 * kPi;
  double a = angle_rad + 0.5 * sector_rad_;
  if (a >= two_pi && a < 2.0 * two_pi) {
    a -= two_pi;
  } else if (!(a > -two_pi && a < two_pi)) {
    a = std::fmod(a, two_pi);
  }
  if (a < 0.0) a += two_pi;
  return wrap(static_cast<int>(std::floor(a / sector_rad_)));
}

int Vfh::sector_of_direction(const Point2& v) const {
  // A rough bearing (within 0.004 rad) names the sector or a neighbour; the cross products
  // with its borders then decide, with a margin of 1e-9 rad far above the rounding of the
  // direction and of sector_of's own arithmetic (~1e-15 rad).
  constexpr double kMargin = 1e-9;
  const double ax = std::abs(v.x()), ay = std::abs(v.y());
  const double big = std::max(ax, ay);
  if (!(big > 0.0)) return -1;
  const double q = std::min(ax, ay) / big;
  double rough = q * (0.25 * kPi + 0.273 * (1.0 - q));  // atan(q), q in [0, 1]
  if (ay > ax) rough = 0.5 * kPi - rough;
  if (v.x() < 0.0) rough = kPi - rough;
  if (v.y() < 0.0) rough = 2.0 * kPi - rough;  // [0, 2π]
  const int n = sector_count();
  int k = static_cast<int>(rough / sector_rad_ + 0.5);  // rough ≥ 0: truncation rounds
  if (k >= n) k -= n;
  const auto above = [&](const Point2& border) { return cross(border, v); };  // v anticlockwise
  const std::size_t i = static_cast<std::size_t>(k);
  const double over_lower = above(borders_[i]), under_upper = -above(borders_[i + 1]);
  if (over_lower > kMargin && under_upper > kMargin) return k;
  // The neighbour on the side the direction lies beyond (borders_ has one entry past the last
  // sector, a copy of the first, so k + 1 needs no wrap).
  const int other = over_lower <= kMargin ? (k == 0 ? n - 1 : k - 1) : (k + 1 == n ? 0 : k + 1);
  const std::size_t j = static_cast<std::size_t>(other);
  if (above(borders_[j]) > kMargin && -above(borders_[j + 1]) > kMargin) return other;
  return -1;
}

double Vfh::sector_center_rad(int sector) const {
  return wrap_angle_rad(wrap(sector) * sector_rad_);
}

double Vfh::kappa_at(double distance_m) const {
  if (distance_m >= options_.window_m || options_.window_m <= 0.0) return 0.0;
  return options_.kappa * (1.0 - distance_m / options_.window_m);
}

void Vfh::build(const std::vector<ObstaclePoint>& obstacles, double range_m) {
  const int n = sector_count();
  std::fill(density_.begin(), density_.end(), 0.0);
  for (const ObstaclePoint& o : obstacles) {
    const double d = o.offset_m.norm();
    const double kappa = kappa_at(d);
    if (kappa <= 0.0 || d <= 0.0 || d > range_m) continue;
    const double c = o.certainty;
    const double m = c * c * kappa;  // Eq. 2.16 with κ(d) scaled by closeness
    // Enlargement: the obstacle blocks every direction whose line passes within r of it.
    // Inside r the whole half plane toward it is blocked.
    const double r = options_.safety_radius_m;
    // The sectors of the enlarged directions β ∓ γ (Eq. 2.15, γ = asin(r/d)): found from the
    // direction turned by ∓γ, without atan2 or asin, unless a direction lies at a sector's
    // border or γ is steep (d within 0.1 % of r); then from the angles, as always.
    int lo = -1, hi = -1;
    const double sin_gamma = d > r ? r / d : 1.0;
    if (sin_gamma <= 0.999 || !(d > r)) {
      const double cos_gamma = d > r ? std::sqrt(1.0 - sin_gamma * sin_gamma) : 0.0;
      const Point2 u = o.offset_m / d;
      lo = sector_of_direction(
          Point2(cos_gamma * u.x() + sin_gamma * u.y(), cos_gamma * u.y() - sin_gamma * u.x()));
      hi = sector_of_direction(
          Point2(cos_gamma * u.x() - sin_gamma * u.y(), cos_gamma * u.y() + sin_gamma * u.x()));
    }
    if (lo < 0 || hi < 0) {
      const double beta = std::atan2(o.offset_m.y(), o.offset_m.x());  // Eq. 2.15
      const double gamma = d > r ? std::asin(r / d) : 0.5 * kPi;
      lo = sector_of(beta - gamma);
      hi = sector_of(beta + gamma);
    }
    const int span = wrap(hi - lo);
    // Eq. 2.17 over sectors lo .. lo + span (lo is in [0, n)), stepping round without a division.
    for (int i = 0, k = lo; i <= span; ++i) {
      density_[k] += m;
      if (++k == n) k = 0;
    }
  }
  // Borenstein's smoothing: triangular weights l+1-|i| over ±l sectors.
  const int l = std::max(0, options_.smoothing_sectors);
  for (int k = 0; k < n; ++k) {
    double sum = 0.0, weights = 0.0;
    for (int i = -l, j = wrap(k - l); i <= l; ++i) {  // j = wrap(k + i)
      const double w = l + 1 - std::abs(i);
      sum += w * density_[j];
      weights += w;
      if (++j == n) j = 0;
    }
    smoothed_[k] = sum / weights;
  }
  // Binary histogram with hysteresis on the enlarged (unsmoothed) density: enlargement already
  // reserves the robot's clearance, and smoothing before the threshold would close the 1-2
  // free sectors a 1 m doorway leaves (docs/algorithms.md).
  const double high = threshold_, low = options_.hysteresis_ratio * threshold_;
  for (int k = 0; k < n; ++k) {
    if (density_[k] > high) {
      blocked_[k] = 1;
    } else if (density_[k] < low) {
      blocked_[k] = 0;
    }
  }
}

double Vfh::side_switch_cost(double direction, double target_rad,
                             std::optional<double> previous_rad) const {
  if (options_.side_switch_rad <= 0.0 || !previous_rad) return 0.0;
  const double prev_off = wrap_angle_rad(*previous_rad - target_rad);
  const double off = wrap_angle_rad(direction - target_rad);
  if (std::abs(prev_off) < options_.detour_rad || std::abs(off) < options_.detour_rad) return 0.0;
  return (prev_off > 0.0) != (off > 0.0) ? options_.side_switch_rad : 0.0;
}

VfhChoice Vfh::select(double target_rad, double heading_rad, std::optional<double> previous_rad,
                      bool hold_way) const {
  const int n = sector_count();
  const int blocked_count = static_cast<int>(std::count(blocked_.begin(), blocked_.end(), 1));
  if (blocked_count == n) return {};
  if (blocked_count == 0) return {true, wrap_angle_rad(target_rad), n};
  // Start scanning just after a blocked sector so every valley is seen whole.
  int start = 0;
  while (!blocked_[start]) ++start;
  VfhChoice best;
  double best_cost = 0.0;
  const auto turn_back_cost = [&](double direction) {
    return hold_way && previous_rad && turns_back(*previous_rad, direction)
               ? options_.turn_back_cost_rad
               : 0.0;
  };
  const auto consider = [&](double direction, int width) {
    const double cost =
        std::abs(wrap_angle_rad(direction - target_rad)) +
        options_.heading_weight * std::abs(wrap_angle_rad(direction - heading_rad)) +
        (previous_rad
             ? options_.previous_weight * std::abs(wrap_angle_rad(direction - *previous_rad))
             : 0.0) +
        side_switch_cost(direction, target_rad, previous_rad) + turn_back_cost(direction);
    if (!best.found || cost < best_cost) {
      best_cost = cost;
      best = {true, wrap_angle_rad(direction), width};
    }
  };
  for (int i = 1; i <= n; ++i) {
    const int first = wrap(start + i);
    if (blocked_[first] || !blocked_[wrap(first - 1)]) continue;
    int width = 0;
    while (!blocked_[wrap(first + width)]) ++width;
    const double first_rad = sector_center_rad(first);
    if (width < options_.wide_valley_sectors) {
      consider(first_rad + 0.5 * (width - 1) * sector_rad_, width);  // narrow: its centre
      continue;
    }
    const int offset = std::clamp(options_.edge_offset_sectors, 0, (width - 1) / 2);
    const double right_rad = first_rad + offset * sector_rad_;
    const double left_rad = first_rad + (width - 1 - offset) * sector_rad_;
    // Where the target lies in the valley, in sectors from the first sector's centre.
    double u = std::fmod(target_rad - first_rad, 2.0 * kPi);
    if (u < 0.0) u += 2.0 * kPi;
    u /= sector_rad_;
    if (u >= offset && u <= width - 1 - offset) consider(target_rad, width);
    consider(right_rad, width);
    consider(left_rad, width);
  }
  return best;
}

int Vfh::freest_sector(double prefer_rad) const {
  int best = 0;
  for (int k = 1; k < sector_count(); ++k) {
    if (smoothed_[k] < smoothed_[best]) {
      best = k;
    } else if (smoothed_[k] == smoothed_[best] &&
               std::abs(wrap_angle_rad(sector_center_rad(k) - prefer_rad)) <
                   std::abs(wrap_angle_rad(sector_center_rad(best) - prefer_rad))) {
      best = k;
    }
  }
  return best;
}

}  // namespace cogmap::mapper::nav
