#include "cogmap/experiments/sweep.h"

#include <charconv>
#include <map>
#include <stdexcept>

#include "cogmap/experiments/run_directory.h"

#include "cogmap/sim/yaml_strict.h"

namespace cogmap::experiments {
namespace {

// Flow-style YAML of a value, so lists survive as "[1, 2]" and strings stay bare.
std::string flow_text(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

std::size_t parse_count(const std::string& text, const std::string& whole) {
  std::size_t v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size() || text.empty()) {
    throw std::invalid_argument("--shard '" + whole + "': expected K/N with whole numbers");
  }
  return v;
}

}  // namespace

std::string SweepRun::dir_name() const {
  std::string out;
  for (const auto& [key, value] : values) {
    out += safe_path_component(key) + "=" + safe_path_component(value) + ",";
  }
  return out + "seed=" + std::to_string(seed);
}

std::vector<std::string> SweepRun::overrides() const {
  std::vector<std::string> out;
  for (const auto& [key, value] : values) out.push_back(key + "=" + value);
  return out;
}

SweepSpec load_sweep(const std::filesystem::path& path, const SweepLimits& limits) {
  const yaml::Node root = yaml::Node::load_file(path);
  root.expect_keys({"base", "seeds", "vary", "description"});
  SweepSpec spec;
  spec.file = path;
  if (const auto d = root.child("description")) (void)d->as<std::string>();
  const std::filesystem::path base(root.get<std::string>("base"));
  spec.base = (base.is_absolute() ? base : path.parent_path() / base).lexically_normal();
  const yaml::Node seeds = root["seeds"];
  if (seeds.is_sequence() && seeds.size() > limits.max_runs) {
    seeds.fail("more seeds than the " + std::to_string(limits.max_runs) + "-run sweep limit");
  }
  seeds.expect_sequence();
  if (seeds.size() == 0) seeds.fail("needs at least one seed");
  std::map<std::uint64_t, int> seed_lines;
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    const yaml::Node s = seeds.at(i);
    const std::uint64_t seed = s.as<std::uint64_t>();
    if (const auto [it, fresh] = seed_lines.emplace(seed, s.line()); !fresh) {
      s.fail("seed " + std::to_string(seed) + " is listed twice (also line " +
             std::to_string(it->second) + ")");
    }
    spec.seeds.push_back(seed);
  }
  // Counted before anything is expanded, with overflow in mind: a product of 10^7 runs must be
  // an error message, not bad_alloc.
  std::size_t total = spec.seeds.size();
  const auto count = [&](std::size_t n, const yaml::Node& at) {
    if (n != 0 && total > limits.max_runs / n) {
      at.fail("the sweep has more than " + std::to_string(limits.max_runs) +
              " runs (the sweep-size limit; raise it with --max-runs)");
    }
    total *= n;
  };
  if (const auto vary = root.child("vary")) {
    for (const std::string& key : vary->keys()) {
      const yaml::Node values = (*vary)[key];
      values.expect_sequence();
      if (values.size() == 0) values.fail("needs at least one value");
      if (key == "seed") values.fail("vary the seed with 'seeds', not under 'vary'");
      SweepAxis axis{key, {}};
      // Two values with the same run directory name are the same run (55 and "55"), or two
      // runs writing one directory ("a b" and "a_b"): both are refused.
      std::map<std::string, std::pair<std::string, int>> by_dir;
      for (std::size_t i = 0; i < values.size(); ++i) {
        const yaml::Node v = values.at(i);
        const std::string text = flow_text(v.raw());
        const auto [it, fresh] =
            by_dir.emplace(safe_path_component(text), std::pair{text, v.line()});
        if (!fresh) {
          v.fail("value '" + text + "' repeats '" + it->second.first + "' (line " +
                 std::to_string(it->second.second) + "): same run directory name");
        }
        axis.values.push_back(text);
      }
      count(axis.values.size(), values);
      spec.vary.push_back(std::move(axis));
    }
  }
  return spec;
}

std::vector<SweepRun> expand_sweep(const SweepSpec& spec) {
  std::size_t combos = 1;
  for (const SweepAxis& a : spec.vary) combos *= a.values.size();
  std::vector<SweepRun> runs;
  runs.reserve(combos * spec.seeds.size());
  for (std::size_t c = 0; c < combos; ++c) {
    // Mixed-radix digits of c, last axis fastest.
    std::vector<std::pair<std::string, std::string>> values(spec.vary.size());
    std::size_t rest = c;
    for (std::size_t a = spec.vary.size(); a-- > 0;) {
      const auto& axis = spec.vary[a];
      values[a] = {axis.key, axis.values[rest % axis.values.size()]};
      rest /= axis.values.size();
    }
    for (const std::uint64_t seed : spec.seeds) {
      SweepRun run;
      run.index = runs.size();
      run.values = values;
      run.seed = seed;
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

Shard parse_shard(const std::string& text) {
  const auto slash = text.find('/');
  if (slash == std::string::npos) {
    throw std::invalid_argument("--shard '" + text + "': expected K/N, e.g. 2/8");
  }
  Shard s{parse_count(text.substr(0, slash), text), parse_count(text.substr(slash + 1), text)};
  if (s.n == 0 || s.k == 0 || s.k > s.n) {
    throw std::invalid_argument("--shard '" + text + "': need 1 <= K <= N");
  }
  return s;
}

std::vector<SweepRun> shard_runs(const std::vector<SweepRun>& runs, Shard shard) {
  std::vector<SweepRun> out;
  for (const SweepRun& r : runs) {
    if (r.index % shard.n == shard.k - 1) out.push_back(r);
  }
  return out;
}

}  // namespace cogmap::experiments
