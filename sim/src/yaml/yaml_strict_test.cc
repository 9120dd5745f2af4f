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

TEST(YamlStrict, ANameIsOnePrintableLine) {
  const Node root = Node::load_string("name: x\n", "e.yaml");
  EXPECT_NO_THROW(expect_one_printable_line(root["name"], "caf\xc3\xa9 r\xc3\xa4ume 2"));
  for (const auto& [text, byte] : {std::pair<std::string, std::string>{"a\tb", "0x9 at offset 1"},
                                   {"a\nb", "0xa at offset 1"},
                                   {"e\x1b[2J", "0x1b at offset 1"},
                                   {"del\x7f", "0x7f at offset 3"}}) {
    const std::string msg = config_error_of([&] { expect_one_printable_line(root["name"], text); });
    EXPECT_NE(msg.find("e.yaml:1: name: holds a control character (byte " + byte + ")"),
              std::string::npos)
        << msg;
  }
}

TEST(YamlStrict, OverrideKeepsTypesAndCreatesMappings) {
  Node root = Node::load_string("mapper:\n  cell_scale_mm: 100\n", "e.yaml");
  apply_override(root.raw(), "mapper.cell_scale_mm=55");
  apply_override(root.raw(), "output.figures=false");
  EXPECT_EQ(root["mapper"].get<int>("cell_scale_mm"), 55);
  EXPECT_FALSE(root["output"].get<bool>("figures"));
  EXPECT_THROW(apply_override(root.raw(), "novalue"), ConfigError);
  EXPECT_THROW(apply_override(root.raw(), "mapper.cell_scale_mm.x=1"), ConfigError);
  for (const char* empty_part :
       {"mapper.=1", ".mapper=1", "mapper..x=1", "mapper.cell_scale_mm.=1"}) {
    EXPECT_NE(config_error_of([&] {
                apply_override(root.raw(), empty_part);
              }).find("empty key component"),
              std::string::npos)
        << empty_part;
  }
  EXPECT_EQ(root["mapper"].get<int>("cell_scale_mm"), 55);  // none of them touched the value
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

// A quoted scalar is a string in YAML: `duration_s: '2'` and `seed: "7"` were read as numbers,
// `flag: 'true'` as a boolean. yaml-cpp tags quoted scalars "!" and plain ones "?".
TEST(YamlStrict, QuotedScalarIsNotANumberOrABoolean) {
  const Node root = Node::load_string(
      "a: '2'\nb: \"7\"\nc: 'true'\nd: 'abc'\ne: ''\nf: !!str 3\ng: !!int 4\nh: 2\ni: true\n",
      "q.yaml");
  ASSERT_EQ(root["a"].raw().Tag(), "!");
  ASSERT_EQ(root["h"].raw().Tag(), "?");
  EXPECT_EQ(config_error_of([&] { root.get<double>("a"); }),
            "q.yaml:1: a: expected a number, got the quoted string '2' (write it without quotes)");
  EXPECT_EQ(
      config_error_of([&] { root.get<int>("b"); }),
      "q.yaml:2: b: expected an integer, got the quoted string '7' (write it without quotes)");
  EXPECT_EQ(config_error_of([&] { root.get<std::uint64_t>("b"); }),
            "q.yaml:2: b: expected a non-negative integer, got the quoted string '7' (write it "
            "without quotes)");
  EXPECT_EQ(config_error_of([&] { root.get<bool>("c"); }),
            "q.yaml:3: c: expected true or false, got the quoted string 'true' (write it without "
            "quotes)");
  // No advice to drop quotes that would not help.
  EXPECT_EQ(config_error_of([&] { root.get<double>("d"); }),
            "q.yaml:4: d: expected a number, got the quoted string 'abc'");
  EXPECT_EQ(config_error_of([&] { root.get<double>("e"); }),
            "q.yaml:5: e: expected a number, got the empty string ''");
  EXPECT_EQ(config_error_of([&] { root.get<int>("f"); }),
            "q.yaml:6: f: expected an integer, got '3' tagged !!str");
  EXPECT_EQ(root.get<int>("g"), 4);
  EXPECT_EQ(root.get<double>("h"), 2.0);
  EXPECT_TRUE(root.get<bool>("i"));
  EXPECT_EQ(root.get<std::string>("a"), "2");  // a string key takes it as it is
  // A node built in code has no tag (--seed sets `seed` so): a number, not a string.
  Node built = Node::load_string("a: 1\n", "b.yaml");
  built.raw()["seed"] = std::uint64_t{9};
  EXPECT_EQ(built.get<std::uint64_t>("seed"), 9u);
}

// One rule for every number key: YAML 1.2 core-schema integers (decimal, 0o octal, 0x hex) read
// the same as an int, a uint64 or a double. yaml-cpp read 0x10 as 16 for int keys but refused it
// for double keys, never read 0o17, and read 017 as octal 15 for int keys but 17 for doubles.
TEST(YamlStrict, HexAndOctalIntegersReadAlikeForEveryNumberKey) {
  const Node root = Node::load_string(
      "x: 0x10\no: 0o17\nz: 017\np: +5\nbig: 0xffffffffffffffff\nf: 2.5e1\n", "n.yaml");
  for (const auto& [key, want] : {std::pair{"x", 16}, {"o", 15}, {"z", 17}, {"p", 5}}) {
    EXPECT_EQ(root.get<int>(key), want) << key;
    EXPECT_EQ(root.get<std::uint64_t>(key), static_cast<std::uint64_t>(want)) << key;
    EXPECT_EQ(root.get<double>(key), static_cast<double>(want)) << key;
  }
  EXPECT_EQ(root.get<std::uint64_t>("big"), 18446744073709551615u);
  EXPECT_EQ(root.get<double>("big"), 18446744073709551615.0);
  EXPECT_EQ(root.get<double>("f"), 25.0);
  EXPECT_EQ(config_error_of([&] { root.get<int>("f"); }),
            "n.yaml:6: f: expected an integer, got '2.5e1'");
}

TEST(YamlStrict, IntegersOutOfRangeOrMalformedAreRefusedAtTheirLine) {
  const Node root = Node::load_string(
      "i: 2147483648\nh: 0x80000000\nn: -2147483649\nlo: -2147483648\nu: 0x10000000000000000\n"
      "d: 18446744073709551616\nx: 0x\nz: 0xZZ\no: 0o8\ns: -0x10\nX: 0X10\nm: -3\n",
      "r.yaml");
  const std::string int_range = "expected an integer in [-2147483648, 2147483647], got ";
  EXPECT_EQ(config_error_of([&] { root.get<int>("i"); }),
            "r.yaml:1: i: " + int_range + "'2147483648'");
  EXPECT_EQ(config_error_of([&] { root.get<int>("h"); }),
            "r.yaml:2: h: " + int_range + "'0x80000000'");
  EXPECT_EQ(config_error_of([&] { root.get<int>("n"); }),
            "r.yaml:3: n: " + int_range + "'-2147483649'");
  EXPECT_EQ(root.get<int>("lo"), -2147483648);
  EXPECT_EQ(root.get<double>("h"), 2147483648.0);  // in range for a double key
  EXPECT_EQ(config_error_of([&] { root.get<std::uint64_t>("u"); }),
            "r.yaml:5: u: expected a non-negative integer of at most 18446744073709551615, got "
            "'0x10000000000000000'");
  EXPECT_EQ(config_error_of([&] { root.get<std::uint64_t>("d"); }),
            "r.yaml:6: d: expected a non-negative integer of at most 18446744073709551615, got "
            "'18446744073709551616'");
  EXPECT_EQ(config_error_of([&] { root.get<double>("u"); }),
            "r.yaml:5: u: expected a number, got '0x10000000000000000': hexadecimal and octal "
            "numbers must fit in 64 bits");
  EXPECT_EQ(config_error_of([&] { root.get<std::uint64_t>("m"); }),
            "r.yaml:12: m: expected a non-negative integer, got '-3'");
  // Not core-schema integers: no digits, bad digits, a sign or a capital X before hex.
  int line = 7;
  for (const char* key : {"x", "z", "o", "s", "X"}) {
    const std::string text = root[key].as<std::string>();
    const std::string at = "r.yaml:" + std::to_string(line++) + ": " + key + ": ";
    EXPECT_EQ(config_error_of([&] { root.get<int>(key); }),
              at + "expected an integer, got '" + text + "'");
    EXPECT_EQ(config_error_of([&] { root.get<std::uint64_t>(key); }),
              at + "expected a non-negative integer, got '" + text + "'");
    EXPECT_EQ(config_error_of([&] { root.get<double>(key); }),
              at + "expected a finite number, got '" + text + "'");
  }
}

// --set values are parsed as YAML too: the same rule as a file's values.
TEST(YamlStrict, OverrideValuesFollowTheNumberRule) {
  Node root = Node::load_string("seed: 1\nduration_s: 10\n", "e.yaml");
  apply_override(root.raw(), "seed=0x10");
  EXPECT_EQ(root.get<std::uint64_t>("seed"), 16u);
  apply_override(root.raw(), "duration_s=0o20");
  EXPECT_EQ(root.get<double>("duration_s"), 16.0);
  apply_override(root.raw(), "duration_s='2'");
  EXPECT_NE(config_error_of([&] { root.get<double>("duration_s"); })
                .find("duration_s: expected a number, got the quoted string '2' (write it without "
                      "quotes)"),
            std::string::npos);
  apply_override(root.raw(), "duration_s=");  // an empty value is the empty string
  EXPECT_NE(config_error_of([&] {
              root.get<double>("duration_s");
            }).find("duration_s: expected a number, got the empty string ''"),
            std::string::npos);
}

// Booleans follow YAML 1.2's core schema, as the numbers do: yaml-cpp (YAML 1.1) also read
// yes/no/on/off/y/n in three cases each, so `figures: no` and `--set relax=off` said false.
TEST(YamlStrict, BooleansAreYaml12CoreOnly) {
  const Node root = Node::load_string(
      "a: true\nb: True\nc: TRUE\nd: false\ne: False\nf: FALSE\ng: yes\nh: No\ni: on\nj: OFF\n"
      "k: y\nl: N\nm: tRUE\nn: 1\no: !!bool yes\np: \"True\"\n",
      "b.yaml");
  for (const char* key : {"a", "b", "c"}) EXPECT_TRUE(root.get<bool>(key)) << key;
  for (const char* key : {"d", "e", "f"}) EXPECT_FALSE(root.get<bool>(key)) << key;
  int line = 7;
  for (const auto& [key, meant] : {std::pair{"g", "true"},
                                   {"h", "false"},
                                   {"i", "true"},
                                   {"j", "false"},
                                   {"k", "true"},
                                   {"l", "false"}}) {
    const std::string text = root[key].as<std::string>();
    EXPECT_EQ(config_error_of([&] { root.get<bool>(key); }),
              "b.yaml:" + std::to_string(line++) + ": " + key + ": expected true or false, got '" +
                  text + "': a YAML 1.1 boolean, which YAML 1.2 reads as a string (write " + meant +
                  ")");
  }
  EXPECT_EQ(config_error_of([&] { root.get<bool>("m"); }),
            "b.yaml:13: m: expected true or false, got 'tRUE'");
  EXPECT_EQ(config_error_of([&] { root.get<bool>("n"); }),
            "b.yaml:14: n: expected true or false, got '1'");
  EXPECT_EQ(config_error_of([&] { root.get<bool>("o"); }),
            "b.yaml:15: o: expected true or false, got 'yes': a YAML 1.1 boolean, which YAML 1.2 "
            "reads as a string (write true)");
  EXPECT_EQ(config_error_of([&] { root.get<bool>("p"); }),
            "b.yaml:16: p: expected true or false, got the quoted string 'True' (write it without "
            "quotes)");
}

// A --set value is YAML text: the same booleans as a file's.
TEST(YamlStrict, OverrideBooleansFollowTheSameRule) {
  Node root = Node::load_string("name: e\nfigures: true\n", "e.yaml");
  apply_override(root.raw(), "figures=off");
  EXPECT_EQ(config_error_of([&] { root.get<bool>("figures"); }),
            "e.yaml:1: figures: expected true or false, got 'off': a YAML 1.1 boolean, which YAML "
            "1.2 reads as a string (write false)");
  apply_override(root.raw(), "figures='false'");
  EXPECT_EQ(config_error_of([&] { root.get<bool>("figures"); }),
            "e.yaml:1: figures: expected true or false, got the quoted string 'false' (write it "
            "without quotes)");
  apply_override(root.raw(), "figures=False");
  EXPECT_FALSE(root.get<bool>("figures"));
}

// A block scalar (| or >) is a string in YAML: it was refused as "the quoted string '2\n'",
// its line break inside the message.
TEST(YamlStrict, BlockScalarWhereANumberOrBooleanIsExpectedIsNamedAsSuch) {
  const Node root = Node::load_string(
      "a: |\n  2\nb: >-\n  7\nc: |\n  true\nd: &x |+\n  1\n  2\n\ne: *x\nf: |\n  abc\n"
      "g: '2'\n",
      "k.yaml");
  const std::string block = "got a block scalar (| or >) holding ";
  EXPECT_EQ(config_error_of([&] { root.get<double>("a"); }),
            "k.yaml:1: a: expected a number, " + block +
                "'2', a string in YAML (write the plain 2 instead)");
  EXPECT_EQ(config_error_of([&] { root.get<int>("b"); }),
            "k.yaml:3: b: expected an integer, " + block +
                "'7', a string in YAML (write the plain 7 instead)");
  EXPECT_EQ(config_error_of([&] { root.get<bool>("c"); }),
            "k.yaml:5: c: expected true or false, " + block +
                "'true', a string in YAML (write the plain true instead)");
  EXPECT_EQ(config_error_of([&] { root.get<std::uint64_t>("d"); }),
            "k.yaml:7: d: expected a non-negative integer, " + block + "'1\\n2', a string in YAML");
  EXPECT_NE(config_error_of([&] { root.get<int>("e"); }).find(block + "'1\\n2'"),
            std::string::npos);  // an alias of a block scalar
  EXPECT_EQ(config_error_of([&] { root.get<double>("f"); }),
            "k.yaml:12: f: expected a number, " + block + "'abc', a string in YAML");
  EXPECT_EQ(config_error_of([&] { root.get<double>("g"); }),
            "k.yaml:14: g: expected a number, got the quoted string '2' (write it without quotes)");
  EXPECT_EQ(root.get<std::string>("a"), "2\n");  // a string key takes it as it is
  // A byte order mark is not in yaml-cpp's positions; a --set value is told apart as well.
  const Node bom = Node::load_string(
      "\xEF\xBB\xBF"
      "a: >\n  2\n",
      "m.yaml");
  EXPECT_EQ(config_error_of([&] { bom.get<int>("a"); }),
            "m.yaml:1: a: expected an integer, " + block +
                "'2', a string in YAML (write the plain 2 instead)");
  Node set = Node::load_string("a: 1\n", "s.yaml");
  apply_override(set.raw(), "a=|-\n  2");
  EXPECT_EQ(config_error_of([&] { set.get<double>("a"); }),
            "s.yaml:1: a: expected a number, " + block +
                "'2', a string in YAML (write the plain 2 instead)");
}

// yaml-cpp reads a text starting with FF FE as UTF-16: `--set $'name=\xff\xfe'` was refused
// for what the bytes became. A value that is not UTF-8 is named as such, with the byte offset.
TEST(YamlStrict, OverrideValueThatIsNotUtf8NamesTheByte) {
  Node root = Node::load_string("name: a\n", "e.yaml");
  EXPECT_EQ(config_error_of([&] { apply_override(root.raw(), "name=\xff\xfe"); }),
            "--set: name: not valid UTF-8 text (byte 0xff at offset 0); a --set value is YAML "
            "text, which must be UTF-8");
  EXPECT_EQ(config_error_of([&] { apply_override(root.raw(), "name=r\xc3\xa4um\xc3"); }),
            "--set: name: not valid UTF-8 text (byte 0xc3 at offset 5); a --set value is YAML "
            "text, which must be UTF-8");
  EXPECT_EQ(root.get<std::string>("name"), "a");  // untouched
  apply_override(root.raw(), "name=r\xc3\xa4ume");
  EXPECT_EQ(root.get<std::string>("name"), "r\xc3\xa4ume");
}

TEST(YamlStrict, InvalidUtf8AtFindsTheFirstBadByte) {
  EXPECT_EQ(invalid_utf8_at("plain r\xc3\xa4ume \xe2\x9c\x93 \xf0\x9d\x84\x9e"),
            std::string_view::npos);
  EXPECT_EQ(invalid_utf8_at("ab\xff"), 2u);
  EXPECT_EQ(invalid_utf8_at("\xc0\xaf"), 0u);          // overlong "/"
  EXPECT_EQ(invalid_utf8_at("x\xed\xa0\x80"), 1u);     // a UTF-16 surrogate
  EXPECT_EQ(invalid_utf8_at("\xf4\x90\x80\x80"), 0u);  // past U+10FFFF
  EXPECT_EQ(invalid_utf8_at("ok\xe2\x9c"), 2u);        // cut short
}

}  // namespace
}  // namespace cogmap::yaml
