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

/// A YAML node that remembers which file and key path it came from.
class Node {
 public:
  Node(YAML::Node node, std::string file, std::string key_path);

  /// Parses a file; syntax errors become ConfigError with the line.
  static Node load_file(const std::filesystem::path& path);
  /// Parses text (tests, --set values); `file` names it in errors.
  static Node load_string(const std::string& text, const std::string& file);

  const YAML::Node& raw() const { return node_; }
  YAML::Node& raw() { return node_; }
  const std::string& file() const { return file_; }
  const std::string& key_path() const { return key_path_; }
  int line() const;  ///< 1-based line of this node, 0 when unknown

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

  /// Converts a scalar; throws ConfigError naming the expected type.
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
  YAML::Node node_;
  std::string file_;
  std::string key_path_;
};

/// Applies one `--set a.b.c=value` override to a document: walks (creating mappings as needed)
/// and sets the leaf to `value` parsed as YAML (so "55", "true", "[1, 2]" keep their types).
/// Throws ConfigError (file "--set") for a malformed assignment.
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
