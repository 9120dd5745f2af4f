#include "cogmap/experiments/results_table.h"

#include <charconv>
#include <cstdint>

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <unordered_map>

#include "cogmap/experiments/number_format.h"

namespace cogmap::experiments {
namespace {

using Json = nlohmann::ordered_json;

void flatten(const Json& j, const std::string& prefix,
             std::vector<std::pair<std::string, std::string>>& out) {
  if (j.is_object()) {
    for (const auto& [k, v] : j.items()) flatten(v, prefix.empty() ? k : prefix + "." + k, out);
  } else if (j.is_array()) {
    return;
  } else if (j.is_null()) {
    out.emplace_back(prefix, "");
  } else if (j.is_boolean()) {
    out.emplace_back(prefix, j.get<bool>() ? "true" : "false");
  } else if (j.is_number_integer() || j.is_number_unsigned()) {
    out.emplace_back(prefix, j.dump());
  } else if (j.is_number_float()) {
    out.emplace_back(prefix, format_double(j.get<double>()));
  } else {
    out.emplace_back(prefix, j.get<std::string>());
  }
}

std::string quote(const std::string& field) {
  if (field.find_first_of(",\"\n\r") == std::string::npos) return field;
  std::string out = "\"";
  for (char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// Row `r`'s run index: a whole number, 0 or more (stoull took "-5" as 2^64 - 5, merged as one
// more run, and named no line for "abc").
std::size_t run_number(const ResultsTable& table, std::size_t r, const std::string& name) {
  const std::string& cell = table.rows[r].at(0);
  std::uint64_t run = 0;
  const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), run);
  if (!cell.empty() && ec == std::errc() && end == cell.data() + cell.size()) {
    return static_cast<std::size_t>(run);
  }
  const std::string at = r < table.row_lines.size() ? ":" + std::to_string(table.row_lines[r]) : "";
  const std::string shown = cell.size() > 40 ? cell.substr(0, 40) + "..." : cell;
  throw std::runtime_error(name + at + ": run: '" + shown +
                           "' is not a run index (a whole number, 0 or more)");
}

}  // namespace

std::vector<std::pair<std::string, std::string>> flatten_metrics_json(const std::string& json) {
  Json j;
  try {
    j = Json::parse(json);
  } catch (const Json::parse_error& e) {
    throw std::runtime_error(std::string("metrics.json: ") + e.what());
  }
  std::vector<std::pair<std::string, std::string>> out;
  flatten(j, "", out);
  return out;
}

ResultsTable build_results_table(
    const std::vector<SweepRun>& runs, const std::vector<std::string>& vary_keys,
    const std::vector<std::vector<std::pair<std::string, std::string>>>& metrics) {
  ResultsTable t;
  t.header.push_back("run");
  for (const auto& k : vary_keys) t.header.push_back(k);
  t.header.push_back("seed");
  std::vector<std::string> metric_keys;
  std::unordered_map<std::string, std::size_t> seen;
  for (const auto& m : metrics) {
    for (const auto& [k, v] : m) {
      if (seen.emplace(k, metric_keys.size()).second) metric_keys.push_back(k);
    }
  }
  for (const auto& k : metric_keys) t.header.push_back(k);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    std::vector<std::string> row{std::to_string(runs[i].index)};
    for (const auto& [key, value] : runs[i].values) row.push_back(value);
    row.push_back(std::to_string(runs[i].seed));
    std::vector<std::string> cells(metric_keys.size());
    for (const auto& [k, v] : metrics.at(i)) cells[seen.at(k)] = v;
    row.insert(row.end(), cells.begin(), cells.end());
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string to_csv(const ResultsTable& table) {
  std::string out;
  auto line = [&out](const std::vector<std::string>& cells) {
    for (std::size_t i = 0; i < cells.size(); ++i) out += (i ? "," : "") + quote(cells[i]);
    out += '\n';
  };
  line(table.header);
  for (const auto& r : table.rows) line(r);
  return out;
}

ResultsTable parse_csv(const std::string& text, const std::string& name) {
  std::vector<std::vector<std::string>> lines;
  std::vector<int> starts;  // the line each record starts on
  std::vector<std::string> row;
  std::string field;
  bool in_quotes = false, any = false;
  int line = 1, record_line = 1, quote_line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (!any && field.empty() && row.empty()) record_line = line;
    if (in_quotes) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        in_quotes = false;
      } else {
        if (c == '\n' || (c == '\r' && !(i + 1 < text.size() && text[i + 1] == '\n'))) ++line;
        field += c;
      }
      continue;
    }
    if (c == '"') {
      in_quotes = true;
      quote_line = line;
      any = true;
    } else if (c == ',') {
      row.push_back(std::move(field));
      field.clear();
      any = true;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      if (any || !field.empty()) {
        row.push_back(std::move(field));
        lines.push_back(std::move(row));
        starts.push_back(record_line);
      }
      ++line;
      row.clear();
      field.clear();
      any = false;
    } else {
      field += c;
      any = true;
    }
  }
  if (in_quotes) {  // named the file only: a stray quote swallows the rest of it
    throw std::runtime_error(name + ":" + std::to_string(quote_line) +
                             ": a quoted field opens here and is never closed");
  }
  if (any || !field.empty()) {
    row.push_back(std::move(field));
    lines.push_back(std::move(row));
    starts.push_back(record_line);
  }
  if (lines.empty()) throw std::runtime_error(name + ": empty file, expected a header");
  ResultsTable t;
  t.header = std::move(lines.front());
  for (std::size_t i = 1; i < lines.size(); ++i) {
    if (lines[i].size() != t.header.size()) {
      throw std::runtime_error(name + ":" + std::to_string(starts[i]) + ": expected " +
                               std::to_string(t.header.size()) + " columns, got " +
                               std::to_string(lines[i].size()));
    }
    t.rows.push_back(std::move(lines[i]));
    t.row_lines.push_back(starts[i]);
  }
  return t;
}

ResultsTable merge_results(const std::vector<std::pair<std::string, ResultsTable>>& tables) {
  if (tables.empty()) throw std::runtime_error("nothing to merge");
  ResultsTable out;
  out.header = tables.front().second.header;
  if (out.header.empty() || out.header.front() != "run") {
    throw std::runtime_error(tables.front().first + ": not a cogmap results.csv (no 'run' column)");
  }
  std::map<std::size_t, std::pair<std::string, std::vector<std::string>>> by_run;
  for (const auto& [name, table] : tables) {
    if (table.header != out.header) {
      throw std::runtime_error(name + ": header differs from " + tables.front().first +
                               " (results of different sweeps?)");
    }
    for (std::size_t r = 0; r < table.rows.size(); ++r) {
      const std::vector<std::string>& row = table.rows[r];
      const std::size_t run = run_number(table, r, name);
      const auto [it, inserted] = by_run.emplace(run, std::make_pair(name, row));
      if (!inserted && it->second.second != row) {
        throw std::runtime_error(name + ": run " + std::to_string(run) + " differs from " +
                                 it->second.first);
      }
    }
  }
  for (auto& [run, entry] : by_run) out.rows.push_back(entry.second);
  return out;
}

}  // namespace cogmap::experiments
