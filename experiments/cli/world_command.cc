// `cogmap world check FILE...`: validates world files and prints one summary line each
// (docs/worlds.md). Exit 0 when all are valid, 1 when any is not, 2 on bad usage. A start the
// walls do not enclose is a warning on stderr, which changes neither the line nor the exit code.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "cogmap/sim/world_enclosure.h"
#include "cogmap/sim/world_spec.h"
#include "command_registry.h"

namespace cogmap::cli {
namespace {

// Extent of the floor plan: the wall centre lines (what the author drew), else everything.
std::pair<mapper::Point2, mapper::Point2> plan_extent(const sim::WorldSpec& world) {
  if (world.walls.empty()) return sim::world_bounds(world);
  mapper::Point2 lo{std::numeric_limits<double>::infinity(),
                    std::numeric_limits<double>::infinity()};
  mapper::Point2 hi = -lo;
  for (const sim::WallPolyline& wall : world.walls) {
    for (const mapper::Point2& p : wall.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  return {lo, hi};
}

std::string summary(const std::string& path, const sim::WorldSpec& world) {
  const auto [lo, hi] = plan_extent(world);
  const double theta_deg = world.start.theta_rad * 180.0 / std::numbers::pi;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "OK %s: %s, %zu wall polylines, %zu obstacles, %.1f x %.1f m, start (%.2f, %.2f, "
                "%.0f\u00b0)",
                path.c_str(), world.name.c_str(), world.walls.size(), world.obstacles.size(),
                hi.x() - lo.x(), hi.y() - lo.y(), world.start.x_m, world.start.y_m,
                theta_deg == 0.0 ? 0.0 : theta_deg);  // never print "-0°"
  return buf;
}

void add_world_command(CLI::App& app, int& exit_code) {
  CLI::App* world = app.add_subcommand("world", "Inspect and validate world files");
  world->require_subcommand(1);
  CLI::App* check = world->add_subcommand(
      "check", "Validate world files: schema, degenerate shapes, start pose clearance");
  auto files = std::make_shared<std::vector<std::string>>();
  check->add_option("files", *files, "World YAML files")->required();
  check->callback([files, &exit_code] {
    bool all_ok = true;
    for (const std::string& path : *files) {
      try {
        const sim::WorldSpec world = sim::load_world(path);
        std::cout << summary(path, world) << '\n';
        if (const auto warning = sim::start_enclosure_warning(world, world.start.translation())) {
          std::cerr << path << ':' << world.start_source.line << ": warning: " << *warning << '\n';
        }
      } catch (const yaml::ConfigError& e) {
        std::cout << "ERROR " << e.what() << '\n';
        all_ok = false;
      }
    }
    exit_code = all_ok ? kExitOk : kExitFailed;
  });
}

const CommandRegistrar kWorldRegistrar{"world", add_world_command};

}  // namespace
}  // namespace cogmap::cli
