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

}  // namespace
}  // namespace cogmap::yaml
