#pragma once
/// One plot per headline metric of a sweep against its first varied key: mean ± sd over seeds,
/// one line per combination of the other varied keys (render::write_metric_plot).

#include <filesystem>
#include <string>
#include <vector>

#include "cogmap/experiments/results_table.h"

namespace cogmap::experiments {

/// One plotted line: the label and, per distinct x, mean and sample standard deviation.
struct MetricSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> mean;
  std::vector<double> sd;  ///< sample sd (n − 1); 0 for a single seed
};

/// The metrics plotted (dotted results.csv columns).
const std::vector<std::string>& plotted_metrics();

/// Groups `table` by the varied columns (those between `run` and `seed`) for `metric`. The x
/// axis is the first varied column: its numbers when every value is numeric, else the index of
/// the value in first-seen order (`x_categories` then lists the values). Empty cells are
/// skipped; empty when the table has no varied column or the metric no number.
std::vector<MetricSeries> metric_series(const ResultsTable& table, const std::string& metric,
                                        std::vector<std::string>* x_categories = nullptr);

/// Writes `dir/<metric>.png` for every plotted metric that has data, on up to `jobs` threads
/// (figures draw in parallel). Returns the files written, in plotted_metrics() order. Throws
/// the first failure (in that order) after every thread has finished.
std::vector<std::filesystem::path> write_sweep_plots(const ResultsTable& table,
                                                     const std::filesystem::path& dir,
                                                     unsigned jobs = 1);

}  // namespace cogmap::experiments
