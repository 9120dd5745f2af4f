// aria_map_metric MAP RUN_DIR MAX_MEDIAN_M MAX_P90_M MAX_SPURIOUS MIN_WALLS_M: compares the walls a
// `cogmap drive` run mapped (RUN_DIR/map_segments_odom.csv) with the map file's LINES, in the
// map frame placed by the RobotHome cairn (AMRISim starts the robot there); no fitting. Prints
// wall error median and p90 (samples every 5 cm of the mapped segments, distance to the nearest
// LINE), the spurious fraction (mapped length farther than 0.3 m from every LINE) and the mapped
// length. Exit 0 when all four are within the limits, 1 otherwise, 2 for bad input.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "aria_map.h"

using cogmap::mapper::Point2;
using cogmap::mapper::Segment;

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(
        stderr,
        "usage: aria_map_metric MAP RUN_DIR MAX_MEDIAN_M MAX_P90_M MAX_SPURIOUS MIN_WALLS_M\n");
    return 2;
  }
  try {
    const cogmap::peers::AriaMap map = cogmap::peers::read_aria_map(argv[1]);
    const std::filesystem::path run = argv[2];
    // The run's world frame is its odometry frame at the origin (no --experiment start). If the
    // odometry started at 0 the robot stood at RobotHome: place the segments there.
    cogmap::mapper::Pose2 place;
    {
      std::ifstream t(run / "trajectory.csv");
      std::string header, row;
      std::getline(t, header);
      std::getline(t, row);
      std::replace(row.begin(), row.end(), ',', ' ');
      std::istringstream f(row);
      double v[7] = {};
      f >> v[0];  // t_s; the true columns are empty for a real robot, so 6 numbers follow
      for (int i = 1; i <= 6 && f >> v[i]; ++i) {
      }
      const double ox = v[1], oy = v[2];
      if (map.robot_home && std::hypot(ox, oy) < 0.5) place = *map.robot_home;
    }
    std::ifstream in(run / "map_segments_odom.csv");
    if (!in) throw std::runtime_error((run / "map_segments_odom.csv").string() + ": cannot open");
    std::string line;
    std::getline(in, line);
    std::vector<double> errors;
    double total = 0, spurious = 0;
    while (std::getline(in, line)) {
      std::replace(line.begin(), line.end(), ',', ' ');
      std::istringstream f(line);
      int id;
      double x1, y1, x2, y2;
      if (!(f >> id >> x1 >> y1 >> x2 >> y2)) continue;
      const Point2 a = place.transform({x1, y1}), b = place.transform({x2, y2});
      const double len = (b - a).norm();
      const int n = std::max(1, static_cast<int>(len / 0.05));
      for (int i = 0; i <= n; ++i) {
        const Point2 p = a + (b - a) * (static_cast<double>(i) / n);
        double d = 1e9;
        for (const Segment& s : map.lines)
          d = std::min(d, cogmap::mapper::distance_to_segment_m(p, s));
        errors.push_back(d);
        if (d > 0.3) spurious += len / (n + 1);
      }
      total += len;
    }
    if (errors.empty()) {
      std::printf("aria_map_metric: no mapped walls\n");
      return 1;
    }
    std::sort(errors.begin(), errors.end());
    const double median = errors[errors.size() / 2], p90 = errors[errors.size() * 9 / 10];
    const double frac = total > 0 ? spurious / total : 0;
    std::printf(
        "aria_map_metric: %zu samples over %.1f m of walls: error median %.3f m, p90 %.3f m,"
        " spurious %.3f\n",
        errors.size(), total, median, p90, frac);
    return median <= std::stod(argv[3]) && p90 <= std::stod(argv[4]) &&
                   frac <= std::stod(argv[5]) && total >= std::stod(argv[6])
               ? 0
               : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "aria_map_metric: %s\n", e.what());
    return 2;
  }
}
