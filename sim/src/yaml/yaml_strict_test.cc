#include <gtest/gtest.h>

#include "config_error_test_support.h"

#include "cogmap/sim/yaml_strict.h"

namespace cogmap::yaml {
namespace {

using testing::config_error_of;

TEST(YamlStrict, UnknownKeyNamesFileLineAndKey) {
  const Node root = Node::load_string("a: 1\nrobot:\n  speed: 2\n  sped: 3\n", "x.yaml");
  const std::string msg = config_error_of([&] { root["robot"].expect_keys({"speed"}); });
  EXPECT_EQ(msg.rfind("x.yaml:4: robot.sped: unknown key", 0), 0u) << msg;
}

TEST(YamlStrict, WrongTypeAndMissingKey) {
  const Node root = Node::load_string("a: hello\nb: [1, 2]\n", "y.yaml");
  EXPECT_NE(
      config_error_of([&] { root.get<double>("a"); }).find("y.yaml:1: a: expected a finite number"),
      std::string::npos);
  EXPECT_NE(config_error_of([&] { root.get<double>("c"); }).find("missing required key 'c'"),
            std::string::npos);
  EXPECT_NE(config_error_of([&] { root.get<int>("b"); }).find("y.yaml:2: b: expected an integer"),
            std::string::npos);
  EXPECT_EQ(root["b"].at(1).as<int>(), 2);
  EXPECT_EQ(root.get_or<double>("missing", 4.5), 4.5);
}

// yaml-cpp marks an empty value ("key:" and nothing) at the next token: a key with nothing
// after it was reported on the next key's line, or past the end of its block.
TEST(YamlStrict, EmptyValueIsReportedOnItsKeysLine) {
  const Node root = Node::load_string(
      "a: 1\nduration_s:\nrobot:\n  speed:\n\n  turn: 2\nnone: ~\nlast:\n", "e.yaml");
  EXPECT_EQ(config_error_of([&] { root.get<double>("duration_s"); }),
            "e.yaml:2: duration_s: expected a number");
  EXPECT_EQ(config_error_of([&] { root["robot"].get_or<double>("speed", 0.0); }),
            "e.yaml:4: robot.speed: expected a number");
  EXPECT_EQ(root["none"].line(), 7);
  EXPECT_EQ(root.child("last")->line(), 8);
  // Values keep their own line: a block's is its first key's.
  EXPECT_EQ(root["robot"].line(), 4);
  EXPECT_EQ(root["robot"]["turn"].line(), 6);
}

TEST(YamlStrict, SyntaxErrorReportsLine) {
  const std::string msg = config_error_of([] { Node::load_string("a: 1\nb: [1, 2\n", "z.yaml"); });
  EXPECT_EQ(msg.rfind("z.yaml:", 0), 0u) << msg;
  EXPECT_NE(msg.find("YAML syntax"), std::string::npos);
}

TEST(YamlStrict, OverrideKeepsTypesAndCreatesMappings) {
  Node root = Node::load_string("mapper:\n  cell_scale_mm: 100\n", "e.yaml");
  apply_override(root.raw(), "mapper.cell_scale_mm=55");
  apply_override(root.raw(), "output.figures=false");
  EXPECT_EQ(root["mapper"].get<int>("cell_scale_mm"), 55);
  EXPECT_FALSE(root["output"].get<bool>("figures"));
  EXPECT_THROW(apply_override(root.raw(), "novalue"), ConfigError);
  EXPECT_THROW(apply_override(root.raw(), "mapper.cell_scale_mm.x=1"), ConfigError);
}

TEST(YamlStrict, KeyThatIsAListOrMappingIsRefusedWithItsLine) {
  for (const char* text : {"a: 1\n? [x, y]\n: 2\n", "a: 1\n? {x: 1}\n: 2\n"}) {
    const std::string msg = config_error_of([&] { Node::load_string(text, "k.yaml"); });
    EXPECT_EQ(msg.rfind("k.yaml:2: a key must be a plain name", 0), 0u) << text << " -> " << msg;
  }
  // An empty key has no text of its own: yaml-cpp marks it where its value starts.
  const std::string empty = config_error_of([] { Node::load_string("a: 1\n? \n: 2\n", "k.yaml"); });
  EXPECT_EQ(empty.rfind("k.yaml:3: a key must be a plain name", 0), 0u) << empty;
  // Nested: the key path of the mapping that holds it.
  const std::string nested =
      config_error_of([] { Node::load_string("mapper:\n  ? [grid]\n  : bayes\n", "n.yaml"); });
  EXPECT_EQ(nested.rfind("n.yaml:2: mapper: a key must be a plain name", 0), 0u) << nested;
}

TEST(YamlStrict, DuplicateKeyIsRefusedAtTheSecond) {
  const std::string msg = config_error_of(
      [] { Node::load_string("a: 1\nrobot:\n  cycle_s: 0.1\n  cycle_s: 0.2\n", "d.yaml"); });
  EXPECT_EQ(msg, "d.yaml:4: robot.cycle_s: duplicate key (each key may appear once in a mapping)");
  // The same key in two different mappings is fine.
  EXPECT_NO_THROW(Node::load_string("a: {x: 1}\nb: {x: 2}\n", "ok.yaml"));
}

TEST(YamlStrict, SecondDocumentIsRefused) {
  const std::string msg =
      config_error_of([] { Node::load_string("# c\na: 1\n---\nb: 2\n", "two.yaml"); });
  EXPECT_EQ(msg,
            "two.yaml:3: a second YAML document (or text after the end of the first): a "
            "configuration file holds exactly one");
  // Found by scripts/fuzz: YAML::LoadAll never returns on "[1]," (yaml-cpp 0.7), and
  // YAML::Load silently drops the ",". Both must be an error, at once.
  const std::string stray = config_error_of([] { Node::load_string("[1],\n", "s.yaml"); });
  EXPECT_EQ(stray.rfind("s.yaml:1: a second YAML document (or text after the end", 0), 0u) << stray;
  // A leading "---" alone starts the one document.
  EXPECT_NO_THROW(Node::load_string("---\na: 1\n", "one.yaml"));
}

TEST(YamlStrict, SizeNodeCountAndNestingAreBounded) {
  LoadLimits small;
  small.max_file_bytes = 100;
  EXPECT_NE(config_error_of([&] {
              Node::load_string(std::string(101, '#'), "big.yaml", small);
            }).find("big.yaml: larger than the 100-byte limit"),
            std::string::npos);
  EXPECT_NO_THROW(Node::load_string("a: 1\n" + std::string(90, '#'), "ok.yaml", small));
  // Aliases count at every use: 10 x 10 x 10 x 10 = 10^4 leaves from a 200-byte text.
  const std::string laughs =
      "a: &a [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\nb: &b [*a, *a, *a, *a, *a, *a, *a, *a, *a, *a]\n"
      "c: &c [*b, *b, *b, *b, *b, *b, *b, *b, *b, *b]\nd: [*c, *c, *c, *c, *c, *c, *c, *c, *c, "
      "*c]\n";
  LoadLimits nodes;
  nodes.max_nodes = 5000;
  EXPECT_NE(config_error_of([&] {
              Node::load_string(laughs, "l.yaml", nodes);
            }).find("more than 5000 nodes"),
            std::string::npos);
  EXPECT_NO_THROW(Node::load_string(laughs, "l.yaml"));  // 11 221 nodes < 200 000
  LoadLimits shallow;
  shallow.max_depth = 3;
  EXPECT_NE(config_error_of([&] {
              Node::load_string("a: [[[[1]]]]\n", "deep.yaml", shallow);
            }).find("nested more than 3 levels"),
            std::string::npos);
  // Deeper than yaml-cpp's own parser goes: its "bad file" is reported as the depth limit.
  const std::string very_deep = "a: " + std::string(5000, '[') + std::string(5000, ']') + "\n";
  EXPECT_EQ(config_error_of([&] { Node::load_string(very_deep, "deep.yaml"); }),
            "deep.yaml:1: YAML syntax: nested more than 64 levels deep");
}

TEST(YamlStrict, OnlyRegularFilesAreRead) {
  EXPECT_EQ(config_error_of([] { Node::load_file("/dev/zero"); }),
            "/dev/zero: not a regular file (a device, pipe or socket)");
  EXPECT_EQ(config_error_of([] { Node::load_file("/"); }), "/: is a directory, not a YAML file");
  EXPECT_EQ(config_error_of([] { Node::load_file("/nonexistent/x.yaml"); }),
            "/nonexistent/x.yaml: cannot open file");
}

TEST(YamlStrict, NulByteIsRefusedWithItsLine) {
  const std::string msg =
      config_error_of([] { Node::load_string(std::string("a: 1\nb: x\0y\n", 12), "z.yaml"); });
  EXPECT_EQ(msg, "z.yaml:2: a NUL byte: this is not a YAML text file");
}

TEST(YamlStrict, OverrideValueWithAListKeyIsRefused) {
  Node root = Node::load_string("mapper: {}\n", "e.yaml");
  const std::string msg = config_error_of([&] { apply_override(root.raw(), "mapper={? [a]: 1}"); });
  EXPECT_NE(msg.find("--set: mapper: value is not valid: a key must be a plain name"),
            std::string::npos)
      << msg;
}

// YAML::Load keeps the first document of a text: a --set value of two set the first and lost
// the second silently. Like a file, a value is one document.
TEST(YamlStrict, OverrideValueWithASecondDocumentIsRefused) {
  Node root = Node::load_string("duration_s: 10\n", "e.yaml");
  const std::string msg =
      config_error_of([&] { apply_override(root.raw(), "duration_s=3\n---\nx: 1"); });
  EXPECT_EQ(msg,
            "--set: duration_s: value holds a second YAML document (or text after the end of "
            "the first) at its line 2: a --set value is exactly one YAML value");
  EXPECT_NE(config_error_of([&] { apply_override(root.raw(), "duration_s=[1],"); }), "");
  EXPECT_EQ(root.raw()["duration_s"].as<double>(), 10.0);            // untouched
  EXPECT_NO_THROW(apply_override(root.raw(), "duration_s=---\n3"));  // one document
  EXPECT_EQ(root.raw()["duration_s"].as<double>(), 3.0);
}

}  // namespace
}  // namespace cogmap::yaml
