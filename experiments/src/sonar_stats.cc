#include "cogmap/experiments/sonar_stats.h"

#include "cogmap/experiments/metrics.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <ostream>

namespace cogmap::experiments {

namespace {

double degrees(double rad) { return rad * 180.0 / std::numbers::pi; }

// metrics.h's quantile, 0 for no values (a transducer that never answered).
double quantile_or_zero(std::vector<double>& values, double q) {
  return values.empty() ? 0.0 : quantile(values, q);
}

}  // namespace

SonarStatsCollector::SonarStatsCollector(const mapper::RobotGeometry& geometry,
                                         SonarStatsOptions options)
    : geometry_(geometry),
      options_(options),
      firings_(geometry.sonars.size(), 0),
      echoes_(geometry.sonars.size(), 0),
      ranges_(geometry.sonars.size()) {}

void SonarStatsCollector::add(const mapper::SensorFrame& frame) {
  if (!have_previous_) {
    previous_ = frame;
    have_previous_ = true;
    return;
  }
  const double dt_s = frame.time_s - previous_.time_s;
  const double moved_m = (frame.odometry.translation() - previous_.odometry.translation()).norm();
  previous_ = frame;
  if (!(dt_s > 0.0)) return;
  const double speed = moved_m / dt_s;
  if (speed < options_.min_speed_mps) return;
  moving_time_s_ += dt_s;
  ++moving_frames_;
  speeds_.push_back(speed);
  for (const mapper::SonarReading& r : frame.sonar) {
    if (r.index < 0 || r.index >= static_cast<int>(firings_.size())) continue;
    const auto i = static_cast<std::size_t>(r.index);
    ++firings_[i];
    ++moving_readings_;
    if (r.echo && r.range_m < options_.max_echo_range_m) {
      ++echoes_[i];
      ranges_[i].push_back(r.range_m);
    }
  }
}

SonarStats SonarStatsCollector::result() const {
  SonarStats s;
  s.moving_time_s = moving_time_s_;
  s.moving_frames = moving_frames_;
  s.readings_per_frame =
      moving_frames_ > 0 ? static_cast<double>(moving_readings_) / moving_frames_ : 0.0;
  std::vector<double> speeds = speeds_;
  s.median_speed_mps = quantile_or_zero(speeds, 0.5);
  for (std::size_t i = 0; i < geometry_.sonars.size(); ++i) {
    TransducerStats t;
    t.index = static_cast<int>(i);
    t.bearing_deg = degrees(geometry_.sonars[i].heading_rad);
    t.firings = firings_[i];
    t.echoes = echoes_[i];
    t.echo_fraction = t.firings > 0 ? static_cast<double>(t.echoes) / t.firings : 0.0;
    std::vector<double> r = ranges_[i];
    t.p10_m = quantile_or_zero(r, 0.1);
    t.p50_m = quantile_or_zero(r, 0.5);
    t.p90_m = quantile_or_zero(r, 0.9);
    t.firings_per_100ms = moving_time_s_ > 0.0 ? t.firings / (moving_time_s_ / 0.1) : 0.0;
    s.transducers.push_back(t);
  }
  return s;
}

SonarStats collect_sonar_stats(mapper::Robot& robot, const SonarStatsOptions& options) {
  SonarStatsCollector collector(robot.geometry(), options);
  while (const auto frame = robot.next_frame()) collector.add(*frame);
  return collector.result();
}

void write_sonar_stats_text(std::ostream& out, const SonarStats& stats) {
  out << std::fixed;
  out << "moving " << std::setprecision(1) << stats.moving_time_s << " s in " << stats.moving_frames
      << " frames, median speed " << std::setprecision(2) << stats.median_speed_mps << " m/s, "
      << stats.readings_per_frame << " new readings per frame\n";
  out << "  #  bearing  firings  echo/firing   p10_m   p50_m   p90_m  firings/100ms\n";
  for (const TransducerStats& t : stats.transducers) {
    out << std::setw(3) << t.index << std::setw(8) << std::setprecision(0) << t.bearing_deg << "°"
        << std::setw(9) << t.firings << std::setw(13) << std::setprecision(2) << t.echo_fraction
        << std::setw(8) << t.p10_m << std::setw(8) << t.p50_m << std::setw(8) << t.p90_m
        << std::setw(15) << std::setprecision(3) << t.firings_per_100ms << "\n";
  }
}

void write_sonar_stats_csv(std::ostream& out, const SonarStats& stats) {
  out << "index,bearing_deg,firings,echoes,echo_fraction,p10_m,p50_m,p90_m,firings_per_100ms\n";
  out << std::setprecision(6);
  for (const TransducerStats& t : stats.transducers) {
    out << t.index << ',' << t.bearing_deg << ',' << t.firings << ',' << t.echoes << ','
        << t.echo_fraction << ',' << t.p10_m << ',' << t.p50_m << ',' << t.p90_m << ','
        << t.firings_per_100ms << "\n";
  }
}

void write_sonar_stats_comparison(std::ostream& out, const SonarStats& a, const SonarStats& b,
                                  const std::string& name_a, const std::string& name_b) {
  out << std::fixed << "first: " << name_a << "\nsecond: " << name_b << "\n";
  out << "bearing   echo 1st  echo 2nd  diff     p50 1st  p50 2nd  ratio   /100ms 1st  2nd\n";
  for (const TransducerStats& ta : a.transducers) {
    const auto match = std::find_if(b.transducers.begin(), b.transducers.end(), [&](const auto& t) {
      return std::abs(t.bearing_deg - ta.bearing_deg) < 0.5;
    });
    out << std::setw(6) << std::setprecision(0) << ta.bearing_deg << "°" << std::setprecision(2)
        << std::setw(10) << ta.echo_fraction;
    if (match == b.transducers.end()) {
      out << "  (no transducer at this bearing in the second)\n";
      continue;
    }
    out << std::setw(10) << match->echo_fraction << std::showpos << std::setw(7)
        << match->echo_fraction - ta.echo_fraction << std::noshowpos << std::setw(10) << ta.p50_m
        << std::setw(9) << match->p50_m << std::setw(7)
        << (ta.p50_m > 0.0 ? match->p50_m / ta.p50_m : 0.0) << std::setprecision(3) << std::setw(11)
        << ta.firings_per_100ms << std::setw(7) << match->firings_per_100ms << "\n";
  }
}

}  // namespace cogmap::experiments
