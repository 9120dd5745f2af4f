#include "cogmap/experiments/sweep_plots.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <exception>
#include <map>
#include <optional>
#include <thread>

#include "cogmap/render/figures.h"

namespace cogmap::experiments {
namespace {

std::optional<double> number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(v)) {
    return std::nullopt;
  }
  return v;
}

}  // namespace

const std::vector<std::string>& plotted_metrics() {
  static const std::vector<std::string> kMetrics{"asr_count",
                                                 "map.wall_error_median_m",
                                                 "map.wall_error_p90_m",
                                                 "map.wall_coverage",
                                                 "map.spurious_fraction",
                                                 "map.polyline_bytes",
                                                 "map.grid_bytes",
                                                 "map.compression_ratio",
                                                 "localization.heading_error_final_deg.odometry",
                                                 "localization.heading_error_final_deg.corrected",
                                                 "localization.ate_rmse_m.odometry",
                                                 "localization.ate_rmse_m.corrected",
                                                 "timing.real_time_factor"};
  return kMetrics;
}

std::vector<MetricSeries> metric_series(const ResultsTable& table, const std::string& metric,
                                        std::vector<std::string>* x_categories) {
  const auto& h = table.header;
  const auto seed_it = std::find(h.begin(), h.end(), "seed");
  const auto metric_it = std::find(h.begin(), h.end(), metric);
  if (h.empty() || h.front() != "run" || seed_it == h.end() || metric_it == h.end()) return {};
  const std::size_t seed_col = static_cast<std::size_t>(seed_it - h.begin());
  const std::size_t metric_col = static_cast<std::size_t>(metric_it - h.begin());
  if (seed_col < 2) return {};  // nothing varied

  // x values: numeric when all are, else categories in first-seen order.
  std::vector<std::string> categories;
  bool numeric = true;
  for (const auto& row : table.rows) {
    if (std::find(categories.begin(), categories.end(), row[1]) == categories.end()) {
      categories.push_back(row[1]);
    }
    numeric = numeric && number(row[1]).has_value();
  }
  auto x_of = [&](const std::string& v) {
    return numeric ? *number(v)
                   : static_cast<double>(std::find(categories.begin(), categories.end(), v) -
                                         categories.begin());
  };
  if (x_categories) *x_categories = numeric ? std::vector<std::string>{} : categories;

  // label -> x -> values over seeds; labels in first-seen order.
  std::vector<std::string> labels;
  std::map<std::string, std::map<double, std::vector<double>>> groups;
  for (const auto& row : table.rows) {
    const auto y = number(row[metric_col]);
    if (!y) continue;
    std::string label;
    for (std::size_t c = 2; c < seed_col; ++c) {
      label += (label.empty() ? "" : ", ") + h[c] + "=" + row[c];
    }
    if (label.empty()) label = metric;
    if (!groups.contains(label)) labels.push_back(label);
    groups[label][x_of(row[1])].push_back(*y);
  }
  std::vector<MetricSeries> out;
  for (const std::string& label : labels) {
    MetricSeries s;
    s.label = label;
    for (const auto& [x, ys] : groups[label]) {
      double mean = 0.0;
      for (double y : ys) mean += y;
      mean /= static_cast<double>(ys.size());
      double var = 0.0;
      for (double y : ys) var += (y - mean) * (y - mean);
      s.x.push_back(x);
      s.mean.push_back(mean);
      s.sd.push_back(ys.size() > 1 ? std::sqrt(var / static_cast<double>(ys.size() - 1)) : 0.0);
    }
    out.push_back(std::move(s));
  }
  return out;
}

namespace {

// One metric's plot, or nothing when the table has no data for it.
std::optional<std::filesystem::path> write_metric_plot_png(const ResultsTable& table,
                                                           const std::string& metric,
                                                           const std::filesystem::path& dir) {
  std::vector<std::string> categories;
  const auto series = metric_series(table, metric, &categories);
  if (series.empty()) return std::nullopt;
  std::vector<render::PlotSeries> plot;
  for (const auto& s : series) plot.push_back({s.label, s.x, s.mean, s.sd});
  std::string x_label = table.header[1];
  if (!categories.empty()) {
    x_label += " (";
    for (std::size_t i = 0; i < categories.size(); ++i) {
      x_label += (i ? ", " : "") + std::to_string(i) + "=" + categories[i];
    }
    x_label += ")";
  }
  const auto png = dir / (metric + ".png");
  render::write_metric_plot(metric + " vs " + table.header[1], x_label, metric, plot, png);
  return png;
}

}  // namespace

std::vector<std::filesystem::path> write_sweep_plots(const ResultsTable& table,
                                                     const std::filesystem::path& dir,
                                                     unsigned jobs) {
  // Drawing is most of a sweep's serial tail: the plots share out over the sweep's threads.
  const std::vector<std::string> metrics = plotted_metrics();
  std::vector<std::optional<std::filesystem::path>> pngs(metrics.size());
  std::vector<std::exception_ptr> errors(metrics.size());
  std::atomic<std::size_t> next{0};
  auto worker = [&] {
    for (std::size_t i = next.fetch_add(1); i < metrics.size(); i = next.fetch_add(1)) {
      try {
        pngs[i] = write_metric_plot_png(table, metrics[i], dir);
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  const unsigned threads_wanted =
      std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(metrics.size())));
  std::vector<std::thread> threads;
  for (unsigned t = 1; t < threads_wanted; ++t) threads.emplace_back(worker);
  worker();
  for (std::thread& t : threads) t.join();
  std::vector<std::filesystem::path> written;
  for (std::size_t i = 0; i < metrics.size(); ++i) {
    if (errors[i]) std::rethrow_exception(errors[i]);
    if (pngs[i]) written.push_back(*pngs[i]);
  }
  return written;
}

}  // namespace cogmap::experiments
