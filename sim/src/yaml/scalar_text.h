#pragma once
/// The text side of reading a scalar (yaml_strict.cc): which texts YAML 1.2's core schema reads
/// as integers and booleans, which texts each key type takes, and whether a scalar was written
/// as a block (| or >). Functions of the text alone, so that every number and boolean of every
/// configuration file and
/// --set value is judged by the same few lines (docs/experiment-format.md "Numbers").

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

#include <yaml-cpp/yaml.h>

namespace cogmap::yaml::detail {

/// An integer as YAML 1.2's core schema writes one: [-+]?[0-9]+ in decimal (a leading 0 is
/// still decimal: 017 is 17, as a double key always read it; yaml-cpp's int conversion took it
/// as octal 15), 0o[0-7]+ in octal or 0x[0-9a-fA-F]+ in hexadecimal (no sign; yaml-cpp read
/// hex for int keys only and never 0o). `fits`: the magnitude fits in 64 bits.
struct CoreInteger {
  bool negative = false;
  std::uint64_t magnitude = 0;
  bool fits = true;
};

inline std::optional<CoreInteger> core_integer(std::string_view s) {
  CoreInteger out;
  int base = 10;
  if (s.starts_with("0x") || s.starts_with("0o")) {
    base = s[1] == 'x' ? 16 : 8;
    s.remove_prefix(2);
  } else if (s.starts_with('-') || s.starts_with('+')) {
    out.negative = s[0] == '-';
    s.remove_prefix(1);
  }
  if (s.empty()) return std::nullopt;  // "0x", "-"
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out.magnitude, base);
  if (end != s.data() + s.size()) return std::nullopt;  // "0xZZ", "1.5", "-0x10"
  if (ec == std::errc::result_out_of_range) {
    out.fits = false;
  } else if (ec != std::errc()) {
    return std::nullopt;
  }
  return out;
}

/// A boolean as YAML 1.2's core schema writes one: true, True, TRUE, false, False, FALSE. The
/// numbers follow YAML 1.2, so the booleans do too: yaml-cpp (YAML 1.1) also read yes, on, y...
inline std::optional<bool> core_bool(std::string_view s) {
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  return std::nullopt;
}

/// The booleans YAML 1.1 (and yaml-cpp) added to those: y, yes, on and n, no, off, in lower
/// case, capitalised or upper case. Only to say in an error which of true or false was meant.
inline std::optional<bool> yaml11_only_bool(std::string_view s) {
  for (const auto& [word, value] : {std::pair{std::string_view("y"), true},
                                    {"yes", true},
                                    {"on", true},
                                    {"n", false},
                                    {"no", false},
                                    {"off", false}}) {
    if (s.size() != word.size()) continue;
    bool lower = true, upper = true, capital = true;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const char up = static_cast<char>(word[i] - 'a' + 'A');
      lower = lower && s[i] == word[i];
      upper = upper && s[i] == up;
      capital = capital && s[i] == (i == 0 ? up : word[i]);
    }
    if (lower || upper || capital) return value;
  }
  return std::nullopt;
}

/// Whether plain text `s` is what a key of each type reads (a number, an integer, a
/// non-negative integer, a boolean); the rest of each check (ranges) is the key's.
inline bool reads_as_number(std::string_view s) {
  if (s.starts_with("0x") || s.starts_with("0o")) {
    const auto n = core_integer(s);
    return n && n->fits;
  }
  double v = 0.0;
  return YAML::convert<double>::decode(YAML::Node(std::string(s)), v) && std::isfinite(v);
}
inline bool reads_as_integer(std::string_view s) { return core_integer(s).has_value(); }
inline bool reads_as_count(std::string_view s) {
  const auto n = core_integer(s);
  return n && !n->negative;
}
inline bool reads_as_bool(std::string_view s) { return core_bool(s).has_value(); }

/// Whether the scalar whose node starts at byte `at` of `text` (yaml-cpp's mark: where its
/// properties start, `&anchor` or `!tag`, else its first character) is a block scalar, | or >.
/// yaml-cpp tags block and quoted scalars alike ("!") and keeps no style, so only the text can
/// tell them apart. A position past the text (a mark of other text) answers false.
inline bool block_scalar_at(std::string_view text, std::size_t at) {
  const auto blank = [&](std::size_t i) {
    return text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n';
  };
  while (at < text.size()) {
    if (blank(at)) {
      ++at;
    } else if (text[at] == '#') {  // a comment between the properties and the scalar
      while (at < text.size() && text[at] != '\n') ++at;
    } else if (text[at] == '&' || text[at] == '!') {
      while (at < text.size() && !blank(at)) ++at;
    } else {
      return text[at] == '|' || text[at] == '>';
    }
  }
  return false;
}

}  // namespace cogmap::yaml::detail
