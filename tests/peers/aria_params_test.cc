// The robot model table (mapper/src/seam/robot_models.cc) against ARIA's own parameter files,
// params/*.p of AriaCoda: SonarNum, every SonarUnit, RobotLength, RobotWidth, DiffConvFactor.
// A peer test: runs where the AriaCoda sources are unpacked (scripts/test --peers), skips
// elsewhere saying so.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "cogmap/mapper/seam/robot_models.h"

namespace cogmap::peers {
namespace {

namespace fs = std::filesystem;

std::optional<fs::path> params_dir() {
  const char* peers = std::getenv("COGMAP_PEERS");
  if (!peers) return std::nullopt;
  const fs::path dir = fs::path(peers) / "AriaCoda" / "params";
  if (!fs::is_directory(dir)) return std::nullopt;
  return dir;
}

struct ParamFile {
  std::map<std::string, std::string> values;         // first word after the key
  std::map<int, std::array<double, 3>> sonar_units;  // SonarUnit i x y th
};

ParamFile read_params(const fs::path& file) {
  ParamFile p;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    if (const auto semi = line.find(';'); semi != std::string::npos) line.erase(semi);
    std::istringstream words(line);
    std::string key;
    if (!(words >> key)) continue;
    if (key == "SonarUnit") {
      int i;
      std::array<double, 3> u;
      if (words >> i >> u[0] >> u[1] >> u[2]) p.sonar_units[i] = u;
    } else {
      std::string value;
      if (words >> value && !p.values.count(key)) p.values[key] = value;
    }
  }
  return p;
}

void expect_model_matches(const mapper::RobotModel& m, const fs::path& file) {
  SCOPED_TRACE(m.name + " vs " + file.string());
  ASSERT_TRUE(fs::exists(file));
  const ParamFile p = read_params(file);
  const mapper::RobotGeometry& g = m.geometry;
  ASSERT_EQ(std::stoul(p.values.at("SonarNum")), g.sonars.size());
  for (std::size_t i = 0; i < g.sonars.size(); ++i) {
    const auto& u = p.sonar_units.at(static_cast<int>(i));
    EXPECT_NEAR(g.sonars[i].x_m * 1000, u[0], 1e-9) << "SonarUnit " << i;
    EXPECT_NEAR(g.sonars[i].y_m * 1000, u[1], 1e-9) << "SonarUnit " << i;
    EXPECT_NEAR(g.sonars[i].heading_rad * 180 / M_PI, u[2], 1e-9) << "SonarUnit " << i;
  }
  EXPECT_NEAR(g.length_m * 1000, std::stod(p.values.at("RobotLength")), 1e-9);
  EXPECT_NEAR(g.width_m * 1000, std::stod(p.values.at("RobotWidth")), 1e-9);
  EXPECT_NEAR(m.geometry.odometry_track_m, 2.0 / std::stod(p.values.at("DiffConvFactor")) / 1000,
              1e-9);
}

TEST(AriaParams, EveryModelMatchesItsParameterFile) {
  const auto dir = params_dir();
  if (!dir)
    GTEST_SKIP() << "peers not built: set COGMAP_PEERS to build-peers.sh's folder "
                    "(scripts/test --peers does)";
  for (const mapper::RobotModel& m : mapper::robot_models()) {
    expect_model_matches(m, *dir / m.aria_params);
  }
}

TEST(AriaParams, Sync2AliasesShareTheirModelsGeometry) {
  const auto dir = params_dir();
  if (!dir)
    GTEST_SKIP() << "peers not built: set COGMAP_PEERS to build-peers.sh's folder "
                    "(scripts/test --peers does)";
  for (const char* subclass : {"p2at8+", "p3at-sh", "p3dx-sh", "p2d8", "p2d8+", "peoplebot-sh"}) {
    const mapper::RobotModel* m = mapper::find_robot_model(subclass);
    ASSERT_NE(m, nullptr) << subclass;
    const ParamFile p = read_params(*dir / (std::string(subclass) + ".p"));
    ASSERT_EQ(std::stoul(p.values.at("SonarNum")), m->geometry.sonars.size()) << subclass;
    for (std::size_t i = 0; i < m->geometry.sonars.size(); ++i) {
      EXPECT_NEAR(m->geometry.sonars[i].x_m * 1000, p.sonar_units.at(static_cast<int>(i))[0], 1e-9)
          << subclass << " SonarUnit " << i;
      EXPECT_NEAR(m->geometry.sonars[i].y_m * 1000, p.sonar_units.at(static_cast<int>(i))[1], 1e-9)
          << subclass << " SonarUnit " << i;
    }
  }
}

}  // namespace
}  // namespace cogmap::peers
