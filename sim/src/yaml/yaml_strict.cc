#include "cogmap/sim/yaml_strict.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

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

// The message without its "file:line: key: " prefix.
std::string bare(const ConfigError& e) {
  const std::string what = e.what();
  const std::string prefix = describe(e.file(), e.line(), e.key(), "");
  return what.starts_with(prefix) ? what.substr(prefix.size()) : what;
}

// What a parser error says. yaml-cpp stops nesting deeper than its own limit (a few hundred
// levels, far past LoadLimits::max_depth) with "bad file", which named neither the cause nor
// the limit: `x: [[[[...]]]]` 500 deep said "YAML syntax: bad file".
std::string syntax_message(const YAML::Exception& e, const LoadLimits& limits) {
  if (dynamic_cast<const YAML::DeepRecursion*>(&e) != nullptr) {
    return "nested more than " + std::to_string(limits.max_depth) + " levels deep";
  }
  return e.msg;
}

int line_of(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

// The line of `key` in `map` as the file wrote it; 0 for a key --set created (no mark).
int key_line_of(const YAML::Node& map, const std::string& key) {
  for (const auto& kv : map) {
    if (kv.first.IsScalar() && kv.first.Scalar() == key) return line_of(kv.first);
  }
  return 0;
}

// Walks the whole tree once after parsing: yaml-cpp accepts keys that are lists or mappings
// (which later crash any `as<std::string>()` on a key) and keeps only the first of two equal
// keys, silently. Both are refused here, with their lines, and the tree's size is bounded.
class TreeCheck {
 public:
  TreeCheck(const std::string& file, const LoadLimits& limits) : file_(file), limits_(limits) {}

  void visit(const YAML::Node& node, const std::string& path, std::size_t depth) {
    if (++nodes_ > limits_.max_nodes) {
      throw ConfigError(file_, line_of(node), path,
                        "the document has more than " + std::to_string(limits_.max_nodes) +
                            " nodes (aliases count at every use); refusing to read it");
    }
    if (depth > limits_.max_depth) {
      throw ConfigError(file_, line_of(node), path,
                        "nested more than " + std::to_string(limits_.max_depth) + " levels deep");
    }
    if (node.IsMap()) {
      std::set<std::string> seen;
      for (const auto& kv : node) {
        if (!kv.first.IsScalar()) {
          throw ConfigError(file_, line_of(kv.first), path,
                            "a key must be a plain name, not a list, a mapping or empty");
        }
        const std::string key = kv.first.Scalar();
        if (!seen.insert(key).second) {
          throw ConfigError(file_, line_of(kv.first), join_key(path, key),
                            "duplicate key (each key may appear once in a mapping)");
        }
        visit(kv.second, join_key(path, key), depth + 1);
      }
    } else if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i) {
        visit(node[i], path + "[" + std::to_string(i) + "]", depth + 1);
      }
    }
  }

 private:
  const std::string& file_;
  const LoadLimits& limits_;
  std::size_t nodes_ = 0;
};

// Records where the first event of a document is (its line, for messages) and nothing else.
class FirstMark final : public YAML::EventHandler {
 public:
  int line = 0;
  void OnDocumentStart(const YAML::Mark& m) override { note(m); }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& m, YAML::anchor_t) override { note(m); }
  void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { note(m); }
  void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                const std::string&) override {
    note(m);
  }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value) override {
    note(m);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t,
                  YAML::EmitterStyle::value) override {
    note(m);
  }
  void OnMapEnd() override {}

 private:
  void note(const YAML::Mark& m) {
    if (line == 0 && !m.is_null()) line = m.line + 1;
  }
};

// The line where a second document (or text the first one could not hold, such as a stray
// "]") starts; 0 when there is none. Asks the parser for at most two documents: YAML::LoadAll
// loops for ever on some such texts (yaml-cpp 0.7, found by scripts/fuzz).
int second_document_line(const std::string& text) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  FirstMark first, second;
  if (!parser.HandleNextDocument(first)) return 0;
  if (!parser.HandleNextDocument(second)) return 0;
  return std::max(second.line, 1);
}

}  // namespace

ConfigError::ConfigError(std::string file, int line, std::string key, const std::string& message)
    : std::runtime_error(describe(file, line, key, message)),
      file_(std::move(file)),
      line_(line),
      key_(std::move(key)) {}

Node::Node(YAML::Node node, std::string file, std::string key_path)
    : node_(std::move(node)), file_(std::move(file)), key_path_(std::move(key_path)) {}

Node Node::load_file(const std::filesystem::path& path, const LoadLimits& limits) {
  const std::string name = path.string();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw ConfigError(name, 0, "", "cannot open file");
  if (std::filesystem::is_directory(status)) {
    throw ConfigError(name, 0, "", "is a directory, not a YAML file");
  }
  // Devices (/dev/zero), pipes and sockets never end or never rewind: only regular files.
  if (!std::filesystem::is_regular_file(status)) {
    throw ConfigError(name, 0, "", "not a regular file (a device, pipe or socket)");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(name, 0, "", "cannot open file");
  // Read in pieces and stop one byte past the limit (the file may grow between stat and read):
  // a buffer of the limit's size, zero-filled for a 2 kB file, cost every command ~1 MB of peak
  // memory and its page faults.
  std::string text;
  std::array<char, 64 * 1024> piece{};
  while (in && text.size() <= limits.max_file_bytes) {
    in.read(piece.data(), static_cast<std::streamsize>(piece.size()));
    text.append(piece.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) throw ConfigError(name, 0, "", "read error");
  if (text.size() > limits.max_file_bytes) {
    throw ConfigError(name, 0, "",
                      "larger than the " + std::to_string(limits.max_file_bytes) +
                          "-byte limit for configuration files; is this the right file?");
  }
  return load_string(text, name, limits);
}

Node Node::load_string(const std::string& text, const std::string& file, const LoadLimits& limits) {
  if (text.size() > limits.max_file_bytes) {
    throw ConfigError(file, 0, "",
                      "larger than the " + std::to_string(limits.max_file_bytes) +
                          "-byte limit for configuration files");
  }
  if (text.find('\0') != std::string::npos) {
    const auto at = text.find('\0');
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
    throw ConfigError(file, line, "", "a NUL byte: this is not a YAML text file");
  }
  YAML::Node root;
  try {
    if (const int line = second_document_line(text); line > 0) {
      throw ConfigError(file, line, "",
                        "a second YAML document (or text after the end of the first): a "
                        "configuration file holds exactly one");
    }
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(file, e.mark.is_null() ? 0 : e.mark.line + 1, "",
                      "YAML syntax: " + syntax_message(e, limits));
  }
  if (!root.IsDefined() || root.IsNull()) throw ConfigError(file, 1, "", "the document is empty");
  TreeCheck(file, limits).visit(root, "", 0);
  return Node(root, file, "");
}

int Node::line() const {
  // An empty value's mark is the next token's (the next key, or past the end of its block):
  // "duration_s:" and nothing was reported a line too far down. Its key is where it was written.
  if (key_line_ > 0 && (node_.IsNull() || node_.Mark().is_null())) return key_line_;
  return line_of(node_);
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
    if (!kv.first.IsScalar()) fail("a key must be a plain name, not a list or mapping");
    const std::string key = kv.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      std::string list;
      for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      const YAML::Mark mark = kv.first.Mark();
      throw ConfigError(file_, mark.is_null() ? line() : mark.line + 1, join_key(key_path_, key),
                        "unknown key (allowed: " + list + ")");
    }
  }
}

Node Node::keyed_child(const YAML::Node& value, const std::string& key) const {
  Node c(value, file_, join_key(key_path_, key));
  c.key_line_ = key_line_of(node_, key);
  return c;
}

Node Node::operator[](const std::string& key) const {
  expect_map();
  const YAML::Node c = node_[key];
  if (!c.IsDefined()) fail("missing required key '" + key + "'");
  return keyed_child(c, key);
}

std::optional<Node> Node::child(const std::string& key) const {
  expect_map();
  const YAML::Node c = node_[key];
  if (!c.IsDefined()) return std::nullopt;
  return keyed_child(c, key);
}

Node Node::at(std::size_t i) const {
  expect_sequence();
  if (i >= node_.size()) fail("index " + std::to_string(i) + " out of range");
  return Node(node_[i], file_, key_path_ + "[" + std::to_string(i) + "]");
}

std::vector<std::string> Node::keys() const {
  expect_map();
  std::vector<std::string> out;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) fail("a key must be a plain name, not a list or mapping");
    out.push_back(kv.first.Scalar());
  }
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
    // YAML::Load keeps the first document and drops the rest: "3\n---\nx: 1" would set 3 and
    // lose "x: 1" silently. A value gets the one-document check a file gets.
    if (const int line = second_document_line(value_text); line > 0) {
      throw ConfigError("--set", 0, key,
                        "value holds a second YAML document (or text after the end of the "
                        "first) at its line " +
                            std::to_string(line) + ": a --set value is exactly one YAML value");
    }
    value = YAML::Load(value_text.empty() ? "''" : value_text);
  } catch (const YAML::Exception& e) {
    throw ConfigError("--set", 0, key,
                      "value is not valid YAML: " + syntax_message(e, LoadLimits{}));
  }
  try {
    TreeCheck("--set", LoadLimits{}).visit(value, key, 0);
  } catch (const ConfigError& e) {
    throw ConfigError("--set", 0, key, "value is not valid: " + bare(e));
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
