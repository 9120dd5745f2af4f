#include "cogmap/experiments/sweep.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <stdexcept>
#include <string_view>

#include "cogmap/experiments/run_directory.h"

#include "cogmap/sim/yaml_strict.h"

namespace cogmap::experiments {
namespace {

// A value as results.csv and the run directory show it: a scalar's text as it is ("007",
// "x y"), anything else as flow YAML ("[1, 2]").
std::string flow_text(const YAML::Node& node) {
  if (node.IsScalar()) return node.Scalar();
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

// A string as a YAML double-quoted scalar: every byte as it is but '"', '\\' and control
// characters, which are escaped (a byte that is not UTF-8 stays, for --set's check to name).
std::string double_quoted(std::string_view text) {
  std::string out = "\"";
  for (const char ch : text) {
    const auto b = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      out += {'\\', ch};
    } else if (ch == '\n') {
      out += "\\n";
    } else if (b < 0x20 || b == 0x7F) {
      constexpr char kHex[] = "0123456789abcdef";
      out += {'\\', 'x', kHex[b >> 4], kHex[b & 0xF]};
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

// A block scalar's text as a literal block scalar that reads back as exactly that text: an
// explicit indentation (its first line may start with spaces) and the chomping its final line
// breaks need (- none, clip one, + several or a text of line breaks alone).
std::string literal_block(std::string_view text) {
  std::size_t breaks = 0;
  while (breaks < text.size() && text[text.size() - 1 - breaks] == '\n') ++breaks;
  const std::string_view body = text.substr(0, text.size() - breaks);
  const char* chomp = breaks == 0 ? "-" : breaks == 1 && !body.empty() ? "" : "+";
  std::string out = std::string("|2") + chomp + "\n";
  std::size_t start = 0;
  while (!body.empty() && start <= body.size()) {
    const std::size_t end = std::min(body.find('\n', start), body.size());
    const std::string_view line = body.substr(start, end - start);
    out += line.empty() ? "\n" : "  " + std::string(line) + "\n";
    start = end + 1;
  }
  for (std::size_t k = body.empty() ? 0 : 1; k < breaks; ++k) out += "\n";
  return out;
}

// The --set text of a value: YAML that reads back as the sweep file wrote it. yaml-cpp's
// emitter writes a quoted scalar plain ('007' became 007, '0.5' a number, 'a: b' a mapping,
// '#x' nothing): a plain scalar stays plain (so 55 and true keep their types), a quoted one is
// double-quoted, a block scalar (| or >) a literal block (the message for it stays its own),
// tags stay; inside a list or mapping (flow YAML) a plain scalar that flow YAML would split is
// quoted, a string either way, and a block scalar is quoted.
std::string set_text(const YAML::Node& node, bool top) {
  const std::string& tag = node.Tag();
  const std::string prefix =
      tag.empty() || tag == "?" || tag == "!" ? "" : "!<" + tag + "> ";  // verbatim
  if (node.IsSequence() || node.IsMap()) {
    std::string out = node.IsMap() ? "{" : "[";
    for (auto it = node.begin(); it != node.end(); ++it) {
      if (it != node.begin()) out += ", ";
      out += node.IsMap() ? set_text(it->first, false) + ": " + set_text(it->second, false)
                          : set_text(*it, false);
    }
    return prefix + out + (node.IsMap() ? "}" : "]");
  }
  if (!node.IsScalar()) return prefix + "~";
  const std::string& text = node.Scalar();
  if (tag == "!") {
    const bool block = node.Style() == YAML::EmitterStyle::Block;
    return block && top ? literal_block(text) : double_quoted(text);
  }
  // With an explicit tag the tag says what it is; quoted, the text cannot be read as YAML of
  // its own ('#x' a comment, 'a: b' a mapping) whatever the tag.
  if (!prefix.empty()) return prefix + double_quoted(text);
  // Plain: as written, where it cannot read back as anything else.
  const bool risky = text.empty() || text.find('\n') != std::string::npos ||
                     text.starts_with("---") || text.starts_with("...") ||
                     (!top && text.find_first_of(",[]{}:#") != std::string::npos);
  return risky ? double_quoted(text) : text;
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
  for (std::size_t i = 0; i < values.size(); ++i) {
    out.push_back(values[i].first + "=" + (set_texts.empty() ? values[i].second : set_texts[i]));
  }
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
      SweepAxis axis{key, {}, {}};
      // Two values with the same run directory name would be two runs writing one directory
      // (55 and "55", "a b" and "a_b"): refused.
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
        axis.set_texts.push_back(set_text(v.raw(), true));
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
    std::vector<std::string> set_texts(spec.vary.size());
    std::size_t rest = c;
    for (std::size_t a = spec.vary.size(); a-- > 0;) {
      const auto& axis = spec.vary[a];
      const std::size_t i = rest % axis.values.size();
      values[a] = {axis.key, axis.values[i]};
      set_texts[a] = i < axis.set_texts.size() ? axis.set_texts[i] : axis.values[i];
      rest /= axis.values.size();
    }
    for (const std::uint64_t seed : spec.seeds) {
      SweepRun run;
      run.index = runs.size();
      run.values = values;
      run.set_texts = set_texts;
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
