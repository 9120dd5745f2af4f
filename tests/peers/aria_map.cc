// ARIA .map: header lines (`2D-Map`, `Key: value`, `Cairn: ...`), then `LINES`, then `DATA`.
#include "aria_map.h"

#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace cogmap::peers {

AriaMap read_aria_map(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  auto fail = [&](std::size_t line, const std::string& what) {
    throw std::runtime_error(path.string() + ":" + std::to_string(line) + ": " + what);
  };
  AriaMap map;
  std::string text;
  std::size_t line = 0;
  long declared = -1;
  bool in_lines = false;
  while (std::getline(in, text)) {
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    if (line == 1) {
      if (text.rfind("2D-Map", 0) != 0) fail(line, "not an ARIA map (expected 2D-Map)");
      continue;
    }
    std::istringstream words(text);
    if (in_lines) {
      if (text == "DATA") break;
      double v[4];
      for (double& x : v) {
        if (!(words >> x)) fail(line, "expected x1 y1 x2 y2 (mm), got '" + text + "'");
      }
      map.lines.push_back({{v[0] / 1000, v[1] / 1000}, {v[2] / 1000, v[3] / 1000}});
      continue;
    }
    std::string key;
    words >> key;
    if (key == "LINES") {
      in_lines = true;
    } else if (key == "NumLines:") {
      words >> declared;
    } else if (key == "Cairn:") {
      std::string kind;
      double x_mm, y_mm, th_deg;
      if (words >> kind && kind == "RobotHome") {
        if (!(words >> x_mm >> y_mm >> th_deg)) fail(line, "RobotHome without x y theta");
        map.robot_home = mapper::Pose2{x_mm / 1000, y_mm / 1000, th_deg * std::numbers::pi / 180};
      }
    }
  }
  if (declared >= 0 && static_cast<long>(map.lines.size()) != declared) {
    fail(line, "NumLines " + std::to_string(declared) + " but " + std::to_string(map.lines.size()) +
                   " LINES rows");
  }
  return map;
}

}  // namespace cogmap::peers
