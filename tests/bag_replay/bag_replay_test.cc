// `cogmap replay` on ROS bags written here (hw/bag/src/corridor_scenario.h: a P3-DX in a 2 m
// corridor, walls at y = ±1 m of the odometry frame). The map's walls must lie on the corridor's.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cogmap/test_support/scratch_dir.h"
#include "corridor_scenario.h"

namespace {

namespace fs = std::filesystem;
using cogmap::hw::bag::testing::OdomForm;
using cogmap::hw::bag::testing::SonarForm;

struct CliRun {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

// Runs the CLI; its output goes through `log` (one per test: ctest runs tests in parallel).
CliRun cli(const std::string& args, const fs::path& log) {
  const std::string cmd = std::string(COGMAP_CLI) + " " + args + " > " + log.string() + " 2>&1";
  // (paths here are made by the test: no quoting needed)
  const int status = std::system(cmd.c_str());
  CliRun r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  std::stringstream ss;
  ss << in.rdbuf();
  r.output = ss.str();
  return r;
}

fs::path work_dir(const std::string& name) { return cogmap::test_support::fresh_scratch(name); }

// Distances of points every 5 cm along the map's segments to the nearer corridor wall, and the
// mapped length on the left (y > 0) and right wall.
struct WallFit {
  std::vector<double> errors;
  double left_m = 0.0, right_m = 0.0;
};

WallFit wall_errors(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  WallFit fit;
  std::vector<double>& errors = fit.errors;
  while (std::getline(in, line)) {
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream f(line);
    int id;
    double x1, y1, x2, y2;
    if (!(f >> id >> x1 >> y1 >> x2 >> y2)) continue;
    const double length = std::hypot(x2 - x1, y2 - y1);
    (y1 + y2 > 0 ? fit.left_m : fit.right_m) += length;
    const int n = std::max(1, static_cast<int>(length / 0.05));
    for (int i = 0; i <= n; ++i) {
      const double y = y1 + (y2 - y1) * i / n;
      errors.push_back(std::abs(std::abs(y) - cogmap::hw::bag::testing::kWallY));
    }
  }
  std::sort(errors.begin(), errors.end());
  return fit;
}

void expect_corridor_map(SonarForm sonar, OdomForm odom, const std::string& name) {
  const fs::path dir = work_dir(name);
  const fs::path bag = dir / (name + ".bag");
  cogmap::hw::bag::testing::write_corridor_bag(bag.string(), sonar, odom);
  const CliRun r =
      cli("replay " + bag.string() + " --robot p3dx --no-figures --out " + (dir / "run").string(),
          dir / "cli.txt");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("500 frames, 752 readings accepted (2 without echo), 3236 unchanged, "
                          "4012 never reported, 0 outside odometry"),
            std::string::npos)
      << r.output;
  const WallFit fit = wall_errors(dir / "run" / "map_segments_odom.csv");
  const std::vector<double>& e = fit.errors;
  ASSERT_FALSE(e.empty()) << "no wall segments in the map";
  const double median = e[e.size() / 2];
  const double p90 = e[e.size() * 9 / 10];
  std::cout << name << ": " << e.size() << " wall samples, error median " << median << " m, p90 "
            << p90 << " m, walls mapped " << fit.left_m << " m left, " << fit.right_m
            << " m right\n";
  // Measured: median and p90 0.05 m (half a 10 cm cell), 6.5 m of each wall (5 m driven, and
  // the 30° sonars see 1.6 m ahead).
  EXPECT_LT(median, 0.06);
  EXPECT_LT(p90, 0.08);
  EXPECT_GT(fit.left_m, 6.0);
  EXPECT_GT(fit.right_m, 6.0);
}

TEST(BagReplay, RosAriaPointCloudCorridorMapsItsWalls) {
  expect_corridor_map(SonarForm::kPointCloud, OdomForm::kOdometry, "rosaria_pc");
}

TEST(BagReplay, RosAriaPointCloud2CorridorMapsItsWalls) {
  expect_corridor_map(SonarForm::kPointCloud2, OdomForm::kOdometry, "rosaria_pc2");
}

TEST(BagReplay, P2osCorridorMapsItsWalls) {
  expect_corridor_map(SonarForm::kSonarArray, OdomForm::kOdometry, "p2os");
}

TEST(BagReplay, TfOnlyCorridorMapsItsWalls) {
  expect_corridor_map(SonarForm::kPointCloud, OdomForm::kTf, "tf_only");
}

TEST(BagReplay, BadBagsExitTwoAndWriteNothing) {
  const fs::path dir = work_dir("bad");
  const fs::path bag = dir / "cut.bag";
  cogmap::hw::bag::testing::write_corridor_bag(bag.string(), SonarForm::kPointCloud,
                                               OdomForm::kOdometry);
  const fs::path whole = dir / "whole.bag";
  fs::copy_file(bag, whole);
  fs::resize_file(bag, fs::file_size(bag) / 2);
  CliRun r = cli("replay " + bag.string() + " --robot p3dx --out " + (dir / "run1").string(),
                 dir / "cli.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(bag.string() + ": not a readable ROS 1 bag"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "run1"));

  r = cli("replay " + whole.string() + " --out " + (dir / "run2").string(), dir / "cli.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("pass --robot (one of p2at, p2at8, p3at, p3dx, p2dx, p2de, peoplebot)"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "run2"));

  r = cli("replay " + whole.string() + " --robot p3dx --sonar-topic /RosAria/pose --out " +
              (dir / "run3").string(),
          dir / "cli.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("topic /RosAria/pose is nav_msgs/Odometry, not a sonar type"),
            std::string::npos)
      << r.output;

  r = cli("replay " + std::string(COGMAP_HW_TESTDATA) + "/sample.carmen.log --robot p3dx --out " +
              (dir / "run4").string(),
          dir / "cli.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("apply to ROS bags only"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "run4"));
}

// A pose beyond the +/-1000 m every log is held to: refused before the run directory exists
// (it exited 1 with a partial run at 1e30 m and 0 with a 21 MB grid of nothing at 5000 m).
TEST(BagReplay, OdometryBeyondTheLogLimitsExitsTwoAndWritesNothing) {
  const fs::path dir = work_dir("far");
  for (const double x : {5000.0, 1e30}) {
    const fs::path bag = dir / "far.bag";
    {
      cogmap::hw::bag::testing::TestBagWriter w(bag.string());
      for (int k = 0; k < 10; ++k) {
        const double t = 10.0 + 0.1 * k;
        w.odometry("/RosAria/pose", t, k == 5 ? x : 0.01 * k, 0.0, 0.0);
        w.point_cloud("/RosAria/sonar", t + 0.05, {{1.0, 1.0 + 0.01 * k}});
      }
    }
    const fs::path run = dir / "run";
    const CliRun r =
        cli("replay " + bag.string() + " --robot p3dx --out " + run.string(), dir / "cli.txt");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(
        r.output.find(bag.string() + ": topic /RosAria/pose, message 5: odometry x_m must be in "
                                     "[-1000, 1000]"),
        std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(run));
  }
}

// Sonar and odometry stamped by two clocks (an hour apart): no reading has a pose. It was "0
// rooms", exit 0, and a run directory of empty files; now exit 2 before anything is written.
TEST(BagReplay, SonarAndOdometryThatNeverOverlapExitTwoAndWriteNothing) {
  const fs::path dir = work_dir("two_clocks");
  const fs::path bag = dir / "two_clocks.bag";
  {
    cogmap::hw::bag::testing::TestBagWriter w(bag.string());
    for (int k = 0; k < 20; ++k) {
      const double t = 1.7e9 + 0.1 * k;
      w.odometry("/RosAria/pose", t, 0.01 * k, 0.0, 0.0);
      w.point_cloud("/RosAria/sonar", t - 3600.0, {{1.0, 1.0 + 0.01 * k}}, t);
    }
  }
  const fs::path run = dir / "run";
  const CliRun r =
      cli("replay " + bag.string() + " --robot p3dx --out " + run.string(), dir / "cli.txt");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(bag.string() + ": the header stamps of /RosAria/sonar ("),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("nothing to map"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(run));
}

}  // namespace
