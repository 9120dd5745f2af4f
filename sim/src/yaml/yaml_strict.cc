#include "cogmap/sim/yaml_strict.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace cogmap::yaml {
namespace {

std::string describe(const std::string& file, int line, const std::string& key,
                     const std::string& message) {
  std::ostringstream out;
  out << file;
  if (line > 0) out << ':' << line;
  out << ": ";
  if (!key.empty()) out << key << ": ";
  out << message;
  return out.str();
}

std::string join_key(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

}  // namespace

ConfigError::ConfigError(std::string file, int line, std::string key, const std::string& message)
    : std::runtime_error(describe(file, line, key, message)),
      file_(std::move(file)),
      line_(line),
      key_(std::move(key)) {}

Node::Node(YAML::Node node, std::string file, std::string key_path)
    : node_(std::move(node)), file_(std::move(file)), key_path_(std::move(key_path)) {}

Node Node::load_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path.string(), 0, "", "cannot open file");
  std::stringstream text;
  text << in.rdbuf();
  return load_string(text.str(), path.string());
}

Node Node::load_string(const std::string& text, const std::string& file) {
  try {
    YAML::Node root = YAML::Load(text);
    if (!root.IsDefined() || root.IsNull()) throw ConfigError(file, 1, "", "the document is empty");
    return Node(root, file, "");
  } catch (const YAML::Exception& e) {
    throw ConfigError(file, e.mark.is_null() ? 0 : e.mark.line + 1, "", "YAML syntax: " + e.msg);
  }
}

int Node::line() const {
  const YAML::Mark mark = node_.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

void Node::fail(const std::string& message) const {
  throw ConfigError(file_, line(), key_path_, message);
}

bool Node::has(const std::string& key) const { return node_.IsMap() && node_[key].IsDefined(); }

void Node::expect_map() const {
  if (!node_.IsMap()) fail("expected a mapping of keys");
}

void Node::expect_sequence() const {
  if (!node_.IsSequence()) fail("expected a list");
}

void Node::expect_keys(std::initializer_list<std::string_view> allowed) const {
  expect_map();
  for (const auto& kv : node_) {
    const std::string key = kv.first.as<std::string>();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string list;
      for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      const YAML::Mark mark = kv.first.Mark();
      throw ConfigError(file_, mark.is_null() ? line() : mark.line + 1, join_key(key_path_, key),
                        "unknown key (allowed: " + list + ")");
    }
  }
}

Node Node::operator[](const std::string& key) const {
  expect_map();
  const YAML::Node c = node_[key];
  if (!c.IsDefined()) fail("missing required key '" + key + "'");
  return Node(c, file_, join_key(key_path_, key));
}

std::optional<Node> Node::child(const std::string& key) const {
  expect_map();
  const YAML::Node c = node_[key];
  if (!c.IsDefined()) return std::nullopt;
  return Node(c, file_, join_key(key_path_, key));
}

Node Node::at(std::size_t i) const {
  expect_sequence();
  if (i >= node_.size()) fail("index " + std::to_string(i) + " out of range");
  return Node(node_[i], file_, key_path_ + "[" + std::to_string(i) + "]");
}

std::vector<std::string> Node::keys() const {
  expect_map();
  std::vector<std::string> out;
  for (const auto& kv : node_) out.push_back(kv.first.as<std::string>());
  return out;
}

template <>
double Node::as<double>() const {
  if (!node_.IsScalar()) fail("expected a number");
  double v = 0.0;
  if (!YAML::convert<double>::decode(node_, v) || !std::isfinite(v)) {
    fail("expected a finite number, got '" + node_.Scalar() + "'");
  }
  return v;
}

template <>
int Node::as<int>() const {
  if (!node_.IsScalar()) fail("expected an integer");
  int v = 0;
  if (!YAML::convert<int>::decode(node_, v))
    fail("expected an integer, got '" + node_.Scalar() + "'");
  return v;
}

template <>
std::uint64_t Node::as<std::uint64_t>() const {
  if (!node_.IsScalar() || node_.Scalar().starts_with("-")) fail("expected a non-negative integer");
  std::uint64_t v = 0;
  if (!YAML::convert<std::uint64_t>::decode(node_, v)) {
    fail("expected a non-negative integer, got '" + node_.Scalar() + "'");
  }
  return v;
}

template <>
bool Node::as<bool>() const {
  if (!node_.IsScalar()) fail("expected true or false");
  bool v = false;
  if (!YAML::convert<bool>::decode(node_, v))
    fail("expected true or false, got '" + node_.Scalar() + "'");
  return v;
}

template <>
std::string Node::as<std::string>() const {
  if (!node_.IsScalar()) fail("expected a string");
  return node_.Scalar();
}

void apply_override(YAML::Node& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw ConfigError("--set", 0, assignment, "expected key=value");
  }
  const std::string key = assignment.substr(0, eq);
  const std::string value_text = assignment.substr(eq + 1);
  std::vector<std::string> parts;
  std::stringstream keys(key);
  for (std::string part; std::getline(keys, part, '.');) {
    if (part.empty()) throw ConfigError("--set", 0, key, "empty key component");
    parts.push_back(part);
  }
  YAML::Node value;
  try {
    value = YAML::Load(value_text.empty() ? "''" : value_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError("--set", 0, key, "value is not valid YAML: " + e.msg);
  }
  // yaml-cpp nodes are handles: walk with reset() so assignment never aliases a parent.
  YAML::Node cursor;
  cursor.reset(root);
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    if (cursor[parts[i]].IsDefined() && !cursor[parts[i]].IsMap()) {
      throw ConfigError("--set", 0, key, "'" + parts[i] + "' is not a mapping");
    }
    if (!cursor[parts[i]].IsDefined()) cursor[parts[i]] = YAML::Node(YAML::NodeType::Map);
    YAML::Node next = cursor[parts[i]];
    cursor.reset(next);
  }
  cursor[parts.back()] = value;
}

}  // namespace cogmap::yaml
