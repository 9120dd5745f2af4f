#include "cogmap/sim/yaml_strict.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>
#include <system_error>

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include "scalar_text.h"

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
// Block scalars (| or >) get the style Block, which the emitter ignores for scalars: yaml-cpp
// keeps no scalar style, and only the text `text` (what was parsed) tells them from quoted
// ones, for the message where a number or boolean is expected (refuse_strings).
class TreeCheck {
 public:
  TreeCheck(const std::string& file, const LoadLimits& limits, std::string_view text)
      : file_(file), limits_(limits), text_(text) {}

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
    } else if (node.IsScalar() && node.Tag() == "!" && !node.Mark().is_null()) {
      // A mark's position leaves out a UTF-8 byte order mark; the text holds it.
      const std::size_t bom = text_.starts_with("\xEF\xBB\xBF") ? 3 : 0;
      if (detail::block_scalar_at(text_, static_cast<std::size_t>(node.Mark().pos) + bom)) {
        YAML::Node handle = node;  // the same node: a handle, not a copy
        handle.SetStyle(YAML::EmitterStyle::Block);
      }
    }
  }

 private:
  const std::string& file_;
  const LoadLimits& limits_;
  std::string_view text_;
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

// Refuses a scalar YAML reads as a string whatever its text, where a number or a boolean is
// expected: a quoted one ('2', "7"; yaml-cpp tags it "!", a plain scalar "?" and a node built
// in code not at all), a block scalar (| or >, tagged "!" as well; TreeCheck marks it) or one
// tagged !!str or a tag of its own. Quoted numbers used to be read as numbers, and a block
// scalar was called a quoted string, its line breaks in the message. `reads`: whether the text
// written plain would be accepted, for the advice.
void refuse_strings(const Node& node, const std::string& expected,
                    bool (*reads)(std::string_view)) {
  const std::string& tag = node.raw().Tag();
  constexpr std::string_view kCore = "tag:yaml.org,2002:";
  if (tag.empty() || tag == "?" || (tag.starts_with(kCore) && !tag.ends_with(":str"))) return;
  const std::string& text = node.raw().Scalar();
  if (tag != "!") {
    const std::string shown = tag.starts_with(kCore) ? "!!" + tag.substr(kCore.size()) : tag;
    node.fail("expected " + expected + ", got '" + text + "' tagged " + shown);
  }
  if (node.raw().Style() == YAML::EmitterStyle::Block) {
    // Its lines without the final line break(s) | and > add, each further break shown as \n.
    std::string_view body = text;
    while (body.ends_with('\n')) body.remove_suffix(1);
    std::string shown;
    for (const char ch : body) shown += ch == '\n' ? std::string("\\n") : std::string(1, ch);
    const bool one_line = body.find('\n') == std::string_view::npos;
    node.fail("expected " + expected + ", got a block scalar (| or >) holding '" + shown +
              "', a string in YAML" +
              (one_line && reads(body) ? " (write the plain " + shown + " instead)" : ""));
  }
  if (text.empty()) node.fail("expected " + expected + ", got the empty string ''");
  node.fail("expected " + expected + ", got the quoted string '" + text + "'" +
            (reads(text) ? " (write it without quotes)" : ""));
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
  TreeCheck(file, limits, text).visit(root, "", 0);
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
  const std::string& text = node_.Scalar();
  refuse_strings(*this, "a number", detail::reads_as_number);
  double v = 0.0;
  std::optional<detail::CoreInteger> n;  // 0x/0o: a core-schema integer, as an int key reads it
  if (text.starts_with("0x") || text.starts_with("0o")) n = detail::core_integer(text);
  const bool ok = n ? n->fits : YAML::convert<double>::decode(node_, v) && std::isfinite(v);
  if (n) v = static_cast<double>(n->magnitude);
  if (n && !n->fits) {
    fail("expected a number, got '" + text +
         "': hexadecimal and octal numbers must fit in 64 bits");
  }
  if (!ok) fail("expected a finite number, got '" + text + "'");
  return v;
}

template <>
int Node::as<int>() const {
  if (!node_.IsScalar()) fail("expected an integer");
  const std::string& text = node_.Scalar();
  refuse_strings(*this, "an integer", detail::reads_as_integer);
  const auto n = detail::core_integer(text);
  if (!n) fail("expected an integer, got '" + text + "'");
  using Limits = std::numeric_limits<int>;
  const std::uint64_t most = n->negative ? std::uint64_t{1} + Limits::max() : Limits::max();
  if (!n->fits || n->magnitude > most) {
    fail("expected an integer in [" + std::to_string(Limits::min()) + ", " +
         std::to_string(Limits::max()) + "], got '" + text + "'");
  }
  const auto m = static_cast<std::int64_t>(n->magnitude);
  return static_cast<int>(n->negative ? -m : m);
}

template <>
std::uint64_t Node::as<std::uint64_t>() const {
  if (!node_.IsScalar()) fail("expected a non-negative integer");
  const std::string& text = node_.Scalar();
  refuse_strings(*this, "a non-negative integer", detail::reads_as_count);
  const auto n = detail::core_integer(text);
  if (!n || n->negative) fail("expected a non-negative integer, got '" + text + "'");
  if (!n->fits) {
    fail("expected a non-negative integer of at most " +
         std::to_string(std::numeric_limits<std::uint64_t>::max()) + ", got '" + text + "'");
  }
  return n->magnitude;
}

// YAML 1.2's core booleans only, as the numbers follow YAML 1.2: yaml-cpp's YAML 1.1 reading
// took `yes`, `on`, `n`... too, so `--set output.figures=no` and `figures: off` said false.
template <>
bool Node::as<bool>() const {
  if (!node_.IsScalar()) fail("expected true or false");
  const std::string& text = node_.Scalar();
  refuse_strings(*this, "true or false", detail::reads_as_bool);
  if (const auto v = detail::core_bool(text)) return *v;
  if (const auto meant = detail::yaml11_only_bool(text)) {
    fail("expected true or false, got '" + text +
         "': a YAML 1.1 boolean, which YAML 1.2 reads as a string (write " +
         (*meant ? "true" : "false") + ")");
  }
  fail("expected true or false, got '" + text + "'");
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
  // getline drops one trailing empty component: "duration_s." would set duration_s.
  if (key.back() == '.') throw ConfigError("--set", 0, key, "empty key component");
  std::vector<std::string> parts;
  std::stringstream keys(key);
  for (std::string part; std::getline(keys, part, '.');) {
    if (part.empty()) throw ConfigError("--set", 0, key, "empty key component");
    parts.push_back(part);
  }
  // YAML is UTF-8 (or UTF-16/32 with a byte order mark): yaml-cpp read a value starting with
  // bytes FF FE as UTF-16 and said something about the text it made of them.
  if (const std::size_t at = invalid_utf8_at(value_text); at != std::string::npos) {
    std::ostringstream msg;
    msg << "not valid UTF-8 text (byte 0x" << std::hex
        << static_cast<int>(static_cast<unsigned char>(value_text[at])) << std::dec << " at offset "
        << at << "); a --set value is YAML text, which must be UTF-8";
    throw ConfigError("--set", 0, key, msg.str());
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
    TreeCheck("--set", LoadLimits{}, value_text).visit(value, key, 0);
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
