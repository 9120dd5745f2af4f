#pragma once
/// Strict YAML reading for every configuration file (worlds, experiments, sweeps): unknown keys,
/// missing keys and wrong types are errors that name the file, line and key path, so a typo
/// never silently falls back to a default.

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cogmap::yaml {

/// A configuration error: "<file>:<line>:<column>: <key path>: <message>".
class ConfigError : public std::runtime_error {
 public:
  ConfigError(std::string file, int line, std::string key, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }  ///< 1-based; 0 when unknown
  const std::string& key() const { return key_; }

 private:
  std::string file_;
  int line_;
  std::string key_;
};

/// Bounds on what a configuration file may be (docs/reliability.md "Limits"). Anything beyond
/// them is refused with a ConfigError before yaml-cpp builds a tree, so a wrong file (a log, a
/// device, a generated monster) costs milliseconds, not gigabytes.
struct LoadLimits {
  /// Largest file read, bytes. 1 MiB: the largest shipped world or experiment is 2 kB, and
  /// yaml-cpp holds roughly 80 bytes of tree per byte of text (measured on a 53 MB world).
  std::size_t max_file_bytes = std::size_t{1} << 20;
  /// Most nodes in the document, an alias counted at every use ("billion laughs" guard).
  std::size_t max_nodes = 200000;
  /// Deepest nesting of mappings and lists; the shipped files nest 4 deep.
  std::size_t max_depth = 64;
};

/// A YAML node that remembers which file and key path it came from.
class Node {
 public:
  Node(YAML::Node node, std::string file, std::string key_path);

  /// Parses a file: a regular file of at most limits.max_file_bytes holding exactly one
  /// document whose mapping keys are plain scalars, each at most once in its mapping. Every
  /// violation and every syntax error becomes a ConfigError with the line.
  static Node load_file(const std::filesystem::path& path, const LoadLimits& limits = {});
  /// Parses text (tests, --set values) with the same checks; `file` names it in errors.
  static Node load_string(const std::string& text, const std::string& file,
                          const LoadLimits& limits = {});

  const YAML::Node& raw() const { return node_; }
  YAML::Node& raw() { return node_; }
  const std::string& file() const { return file_; }
  const std::string& key_path() const { return key_path_; }
  /// 1-based line of this node, 0 when unknown. A child reached by its key (operator[],
  /// child) with an empty value ("key:" and nothing, or a value set in code) is on its key's
  /// line: yaml-cpp marks an empty value at the next token, a line or more further down.
  int line() const;

  bool is_map() const { return node_.IsMap(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }
  bool has(const std::string& key) const;
  std::size_t size() const { return node_.size(); }

  /// Requires a mapping whose keys are all in `allowed`; names the first unknown key.
  void expect_keys(std::initializer_list<std::string_view> allowed) const;
  void expect_map() const;
  void expect_sequence() const;

  /// A required child of a mapping.
  Node operator[](const std::string& key) const;
  /// An optional child of a mapping.
  std::optional<Node> child(const std::string& key) const;
  /// Element `i` of a sequence.
  Node at(std::size_t i) const;
  /// The keys of a mapping, in file order.
  std::vector<std::string> keys() const;

  /// Converts a scalar; throws ConfigError naming the expected type. Numbers and booleans
  /// follow one rule (docs/experiment-format.md "Numbers"): a plain scalar only (a quoted or
  /// block one is a string in YAML: '2' is refused, not read as 2); integers as YAML 1.2's
  /// core schema writes them (decimal, 0o octal, 0x hexadecimal) for int, uint64 and double
  /// keys alike, within the key type's range; booleans as it writes them too (true, True,
  /// TRUE, false, False, FALSE; YAML 1.1's yes, on, n... are refused).
  template <typename T>
  T as() const;
  /// Required key of type T.
  template <typename T>
  T get(const std::string& key) const {
    return (*this)[key].template as<T>();
  }
  /// Optional key with a default.
  template <typename T>
  T get_or(const std::string& key, const T& fallback) const {
    const auto c = child(key);
    return c ? c->template as<T>() : fallback;
  }

  /// Throws ConfigError at this node.
  [[noreturn]] void fail(const std::string& message) const;

 private:
  Node keyed_child(const YAML::Node& value, const std::string& key) const;

  YAML::Node node_;
  std::string file_;
  std::string key_path_;
  int key_line_ = 0;  ///< line of the key this node is the value of; 0 for none or unknown
};

/// The byte offset where `text` stops being UTF-8 (RFC 3629: no overlong forms, surrogates or
/// code points past U+10FFFF), or std::string_view::npos when all of it is.
std::size_t invalid_utf8_at(std::string_view text);

/// Throws ConfigError at `node` when `text` (its value) holds a control character (a byte
/// below 0x20, or 0x7F), naming the byte and its offset: a name titles figures and the
/// commands' messages, and an ESC sequence or newline in it reached the terminal raw.
void expect_one_printable_line(const Node& node, std::string_view text);

/// Applies one `--set a.b.c=value` override to a document: walks (creating mappings as needed)
/// and sets the leaf to `value` parsed as YAML (so "55", "true", "[1, 2]" keep their types).
/// Throws ConfigError (file "--set") for a malformed assignment, a value that is not UTF-8
/// (yaml-cpp read a value starting with bytes FF FE as UTF-16) or one that breaks the load
/// checks (a list as a key, a duplicate key).
void apply_override(YAML::Node& root, const std::string& assignment);

template <>
double Node::as<double>() const;
template <>
int Node::as<int>() const;
template <>
std::uint64_t Node::as<std::uint64_t>() const;
template <>
bool Node::as<bool>() const;
template <>
std::string Node::as<std::string>() const;

}  // namespace cogmap::yaml
