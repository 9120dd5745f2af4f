#pragma once
/// results.csv of a sweep: one row a run — run index, every varied key, the seed, then every
/// scalar of metrics.json as a flattened dotted key ("map.wall_error_median_m").

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "cogmap/experiments/sweep.h"

namespace cogmap::experiments {

/// A CSV table held as text cells.
struct ResultsTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  /// The 1-based line each of `rows` starts on in the text parse_csv read (a quoted field may
  /// span lines, blank lines hold no row), so errors name it; empty for built tables.
  std::vector<int> row_lines;
};

/// The scalars of a metrics.json document as (dotted key, text) in document order: numbers in
/// shortest round-trip form, null as "", booleans as true/false; arrays are skipped (per-room
/// lists belong in metrics.json, not in a table). Throws std::runtime_error on bad JSON.
std::vector<std::pair<std::string, std::string>> flatten_metrics_json(const std::string& json);

/// Builds the table for finished runs; `metrics[i]` is the flattened metrics of `runs[i]`.
/// Metric columns are the union of keys in first-seen order; missing cells are empty.
ResultsTable build_results_table(
    const std::vector<SweepRun>& runs, const std::vector<std::string>& vary_keys,
    const std::vector<std::vector<std::pair<std::string, std::string>>>& metrics);

/// RFC 4180 text (fields with a comma, quote or newline are quoted), '\n' line ends.
std::string to_csv(const ResultsTable& table);

/// Parses CSV text written by to_csv; `name` appears in errors (std::runtime_error).
ResultsTable parse_csv(const std::string& text, const std::string& name);

/// Joins shard tables: every header must equal the first (else std::runtime_error naming the
/// file); rows are ordered by the `run` column; a run present twice must have identical rows.
ResultsTable merge_results(const std::vector<std::pair<std::string, ResultsTable>>& tables);

}  // namespace cogmap::experiments
