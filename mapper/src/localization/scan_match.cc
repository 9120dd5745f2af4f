// Echoes of the last minute matched against the newest ones; see the header.

#include "cogmap/mapper/localization/scan_match.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "cogmap/mapper/grid/bresenham.h"
#include "cogmap/mapper/grid/grid_geometry.h"

namespace cogmap::mapper {
namespace {

constexpr double kHitValue = 3.0;     // HIMM: +3 on the cell an echo lands in (thesis §2.2.3)
constexpr double kPassValue = -1.0;   // ... −1 on each cell its beam crossed before it
constexpr double kFloorValue = -3.0;  // MHIMM's floor and cap (thesis §3.1.4)
constexpr double kCapValue = 15.0;
constexpr double kMaxBoxM = 40.0;  // the largest box matched (16 000 cells of 10 cm a side)

/// The memory's walls as a log-likelihood field over a box: per cell,
/// log(1 + exp(−d²/2σ²) / outlier), d the distance to the nearest wall cell (0 beyond 3σ), and
/// whether d < 2σ (the echo counts as matched).
struct LikelihoodField {
  GridGeometry geometry;
  std::vector<float> score;
  std::vector<char> near;

  /// Bilinear between cell centres; 0 outside.
  double at(const Point2& p) const {
    const double cell = geometry.cell_size_m();
    const double fx = (p.x() - geometry.origin_x_m()) / cell - 0.5;
    const double fy = (p.y() - geometry.origin_y_m()) / cell - 0.5;
    const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
    if (x0 < 0 || y0 < 0 || x0 + 1 >= geometry.width() || y0 + 1 >= geometry.height()) return 0.0;
    const double ax = fx - x0, ay = fy - y0;
    const std::size_t i = static_cast<std::size_t>(y0) * geometry.width() + x0;
    const std::size_t w = geometry.width();
    return (1.0 - ay) * ((1.0 - ax) * score[i] + ax * score[i + 1]) +
           ay * ((1.0 - ax) * score[i + w] + ax * score[i + w + 1]);
  }
  bool is_near(const Point2& p) const {
    const CellIndex c = geometry.cell_of(p);
    return geometry.contains(c) && near[geometry.linear(c)] != 0;
  }
};

}  // namespace

Pose2 ScanMatchFix::transform() const {
  return Pose2{shift_m.x(), shift_m.y(), 0.0}.compose(rotation_about(pivot, rotation_rad));
}

ScanMatcher::ScanMatcher(const ScanMatchOptions& options, const RobotGeometry& robot)
    : options_(options) {
  for (const SonarMount& m : robot.sonars) mounts_.push_back({m.x_m, m.y_m, m.heading_rad});
}

void ScanMatcher::add(const Pose2& pose, const SonarReading& reading, int room_id) {
  if (!reading.echo || !std::isfinite(reading.range_m) || reading.range_m <= 0.0 ||
      reading.range_m > options_.max_range_m || reading.index < 0 ||
      reading.index >= static_cast<int>(mounts_.size())) {
    return;
  }
  const Pose2 sensor = pose.compose(mounts_[reading.index]);
  const Point2 point = sensor.transform({reading.range_m, 0.0});
  if (!point.allFinite() || !sensor.translation().allFinite()) return;  // a broken estimate
  window_.push_back({sensor.translation(), point, room_id});
}

bool ScanMatcher::visit(const Pose2& pose, double turned_rad) {
  const Point2 p = pose.translation();
  if (has_position_) travelled_m_ += (p - last_position_).norm();
  has_position_ = true;
  last_position_ = p;
  turned_rad_ += std::abs(turned_rad);
  return (travelled_m_ >= options_.interval_m || turned_rad_ >= options_.interval_rad) &&
         window_.size() >= options_.min_window_echoes;
}

void ScanMatcher::move_room(int room_id, const Pose2& move) {
  const auto follow = [&](Echo& e) {
    if (e.room_id != room_id) return;
    e.origin = move.transform(e.origin);
    e.point = move.transform(e.point);
  };
  std::for_each(memory_.begin(), memory_.end(), follow);
  std::for_each(window_.begin(), window_.end(), follow);
}

void ScanMatcher::shift_all(const Point2& shift) {
  const auto follow = [&](Echo& e) {
    e.origin += shift;
    e.point += shift;
  };
  std::for_each(memory_.begin(), memory_.end(), follow);
  std::for_each(window_.begin(), window_.end(), follow);
}

ScanMatchFix ScanMatcher::match(const Pose2& pose, double rotation_prior_var_rad2,
                                double shift_prior_var_m2) {
  ScanMatchFix fix;
  fix.pivot = pose.translation();
  fix.rotation_var_rad2 = rotation_prior_var_rad2;
  fix.shift_var_m2 = shift_prior_var_m2;
  fix.window_echoes = window_.size();
  travelled_m_ = 0.0;
  turned_rad_ = 0.0;

  const double sigma_r = std::sqrt(std::max(rotation_prior_var_rad2, 1e-12));
  const double sigma_t = std::sqrt(std::max(shift_prior_var_m2, 1e-12));
  const double half_r =
      std::clamp(4.0 * sigma_r, options_.rotation_step_rad, options_.max_rotation_rad);
  const double half_t = std::clamp(4.0 * sigma_t, options_.shift_step_m, options_.max_shift_m);

  // The box the window's echoes can move within.
  Point2 lo{0.0, 0.0}, hi{0.0, 0.0};
  if (!window_.empty()) {
    lo = hi = window_.front().point;
    for (const Echo& e : window_) {
      lo = lo.cwiseMin(e.point);
      hi = hi.cwiseMax(e.point);
    }
    const double reach =
        half_t + half_r * options_.max_range_m * 2.0 + 3.0 * options_.sigma_m + options_.cell_m;
    lo -= Point2{reach, reach};
    hi += Point2{reach, reach};
  }
  // A window spread wider than kMaxBoxM (a long drive with few echoes, an odometry jump) is not
  // matched: its grids would grow with the square of the distance.
  if (!window_.empty() && !memory_.empty() && fix.pivot.allFinite() && std::isfinite(half_r) &&
      std::isfinite(half_t) && (hi - lo).maxCoeff() <= kMaxBoxM) {
    // The memory drawn as HIMM draws it, oldest first, on cells of a fixed lattice; each wall
    // cell stands for the mean of the echoes that landed in it (a cell centre would pull the
    // window up to half a cell toward it).
    const double cell = options_.cell_m;
    const auto lattice = [](double v, double step) { return std::floor(v / step) * step; };
    const GridGeometry geometry(lattice(lo.x(), cell), lattice(lo.y(), cell), cell * 1000.0,
                                static_cast<int>(std::ceil((hi.x() - lo.x()) / cell)) + 2,
                                static_cast<int>(std::ceil((hi.y() - lo.y()) / cell)) + 2);
    std::vector<float> value(geometry.cell_count(), 0.0f);
    std::vector<Point2> hit_sum(geometry.cell_count(), Point2::Zero());
    std::vector<int> hits(geometry.cell_count(), 0);
    for (const Echo& e : memory_) {
      // A beam wholly outside the box touches none of its cells.
      if (std::max(e.origin.x(), e.point.x()) < lo.x() ||
          std::min(e.origin.x(), e.point.x()) > hi.x() ||
          std::max(e.origin.y(), e.point.y()) < lo.y() ||
          std::min(e.origin.y(), e.point.y()) > hi.y()) {
        continue;
      }
      const CellIndex end = geometry.cell_of(e.point);
      for_each_line_cell(geometry.cell_of(e.origin), end, [&](CellIndex c) {
        if (!geometry.contains(c)) return true;
        const std::size_t i = geometry.linear(c);
        if (c == end) {
          value[i] = std::min<float>(value[i] + kHitValue, kCapValue);
          hit_sum[i] += e.point;
          ++hits[i];
        } else {
          value[i] = std::max<float>(value[i] + kPassValue, kFloorValue);
        }
        return true;
      });
    }
    // The likelihood field on half cells: distance to the nearest wall point, out to 3σ.
    const double fine = 0.5 * cell;
    const GridGeometry fine_geometry(geometry.origin_x_m(), geometry.origin_y_m(), fine * 1000.0,
                                     2 * geometry.width(), 2 * geometry.height());
    const int radius = static_cast<int>(std::ceil(3.0 * options_.sigma_m / fine));
    std::vector<float> distance(fine_geometry.cell_count(), std::numeric_limits<float>::infinity());
    for (std::size_t i = 0; i < value.size(); ++i) {
      if (value[i] < options_.occupied_value || hits[i] == 0) continue;
      const Point2 wall = hit_sum[i] / hits[i];
      const CellIndex centre = fine_geometry.cell_of(wall);
      for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
          const CellIndex c{centre.x + dx, centre.y + dy};
          if (!fine_geometry.contains(c)) continue;
          float& d = distance[fine_geometry.linear(c)];
          d = std::min<float>(d, static_cast<float>((fine_geometry.center_of(c) - wall).norm()));
        }
      }
    }
    LikelihoodField field{fine_geometry, std::vector<float>(fine_geometry.cell_count(), 0.0f),
                          std::vector<char>(fine_geometry.cell_count(), 0)};
    const double two_var = 2.0 * options_.sigma_m * options_.sigma_m;
    for (std::size_t i = 0; i < distance.size(); ++i) {
      if (!std::isfinite(distance[i])) continue;
      const double d = distance[i];
      field.score[i] =
          static_cast<float>(std::log1p(std::exp(-d * d / two_var) / options_.outlier_weight));
      field.near[i] = d < 2.0 * options_.sigma_m ? 1 : 0;
    }
    // Echoes where no memory beam ever reached, and no memory wall is near, are left out:
    // there the memory cannot say whether a wall stands, and every move that carried them back
    // onto the memory's walls would score (down a corridor, the window was pulled back by ~2 %
    // of the distance driven). What is left of that pull along a corridor, from the echoes near
    // the end of the memory's walls, the degenerate-direction rule below takes out.
    std::vector<Point2> used;
    used.reserve(window_.size());
    for (const Echo& e : window_) {
      const CellIndex c = geometry.cell_of(e.point);
      const bool known = geometry.contains(c) &&
                         (value[geometry.linear(c)] != 0.0f || hits[geometry.linear(c)] > 0);
      if (!known && !field.is_near(e.point)) continue;
      used.push_back(e.point);
      fix.matched_echoes += field.is_near(e.point) ? 1 : 0;
    }

    if (fix.matched_echoes >= options_.min_matched) {
      // The posterior over a grid of rigid moves: likelihood of the moved window (each echo
      // counted 1/correlated_echoes) times odometry's prior.
      const int n_r =
          options_.rotation ? static_cast<int>(std::round(half_r / options_.rotation_step_rad)) : 0;
      const int n_t =
          options_.shift ? static_cast<int>(std::round(half_t / options_.shift_step_m)) : 0;
      const double per_echo = 1.0 / options_.correlated_echoes;
      struct Cell {
        double rotation, tx, ty, log_post;
      };
      std::vector<Cell> cells;
      cells.reserve(static_cast<std::size_t>(2 * n_r + 1) * (2 * n_t + 1) * (2 * n_t + 1));
      std::vector<Point2> moved(used.size());
      double best = -std::numeric_limits<double>::infinity();
      for (int ir = -n_r; ir <= n_r; ++ir) {
        const double r = ir * options_.rotation_step_rad;
        const Pose2 turn = rotation_about(fix.pivot, r);
        for (std::size_t i = 0; i < used.size(); ++i) moved[i] = turn.transform(used[i]);
        for (int ix = -n_t; ix <= n_t; ++ix) {
          for (int iy = -n_t; iy <= n_t; ++iy) {
            const Point2 t{ix * options_.shift_step_m, iy * options_.shift_step_m};
            double sum = 0.0;
            for (const Point2& p : moved) sum += field.at(p + t);
            const double log_post = per_echo * sum - r * r / (2.0 * rotation_prior_var_rad2) -
                                    t.squaredNorm() / (2.0 * shift_prior_var_m2);
            best = std::max(best, log_post);
            cells.push_back({r, t.x(), t.y(), log_post});
          }
        }
      }
      double total = 0.0, mr = 0.0, mx = 0.0, my = 0.0;
      for (const Cell& c : cells) {
        const double w = std::exp(c.log_post - best);
        total += w;
        mr += w * c.rotation;
        mx += w * c.tx;
        my += w * c.ty;
      }
      mr /= total;
      mx /= total;
      my /= total;
      double vr = 0.0;
      Eigen::Matrix2d shift_cov = Eigen::Matrix2d::Zero();
      for (const Cell& c : cells) {
        const double w = std::exp(c.log_post - best) / total;
        vr += w * (c.rotation - mr) * (c.rotation - mr);
        const Eigen::Vector2d d{c.tx - mx, c.ty - my};
        shift_cov += w * d * d.transpose();
      }
      // A grid step is the finest the search resolves.
      const double step_r2 = options_.rotation_step_rad * options_.rotation_step_rad / 12.0;
      const double step_t2 = options_.shift_step_m * options_.shift_step_m / 12.0;
      // Along a direction the echoes do not constrain (down a corridor) the posterior keeps the
      // prior's width, and any slight pull of the likelihood (the window's far end, phantoms
      // of oblique beams) would move the estimate by a share of the prior every match: that
      // share of the shift is left out, and the direction keeps its prior variance.
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> axes(shift_cov);
      Eigen::Vector2d shift{mx, my}, kept = Eigen::Vector2d::Zero();
      double shift_var = 0.0;
      for (int k = 0; k < 2; ++k) {
        const Eigen::Vector2d axis = axes.eigenvectors().col(k);
        const double var = std::max(axes.eigenvalues()(k), step_t2);
        if (var > options_.degenerate_ratio * shift_prior_var_m2) {
          shift_var += 0.5 * shift_prior_var_m2;
          ++fix.degenerate_axes;
          continue;
        }
        kept += axis * axis.dot(shift);
        shift_var += 0.5 * var;
      }
      fix.measured = true;
      fix.rotation_rad = mr;
      fix.shift_m = {kept.x(), kept.y()};
      fix.rotation_var_rad2 = options_.rotation
                                  ? std::min(rotation_prior_var_rad2, std::max(vr, step_r2))
                                  : rotation_prior_var_rad2;
      fix.shift_var_m2 =
          options_.shift ? std::min(shift_prior_var_m2, shift_var) : shift_prior_var_m2;
    }
  }

  // The window joins the memory where the fix puts it.
  const Pose2 move = fix.transform();
  for (Echo& e : window_) {
    if (fix.measured) {
      e.origin = move.transform(e.origin);
      e.point = move.transform(e.point);
    }
    memory_.push_back(e);
  }
  window_.clear();
  while (memory_.size() > options_.memory_readings) memory_.pop_front();
  return fix;
}

}  // namespace cogmap::mapper
