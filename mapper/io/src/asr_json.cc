// One ASR <-> JSON, version 1 (docs/asr-format.md).

#include <string>

#include "cogmap/mapper/io/asr_json.h"
#include "json_reader.h"

namespace cogmap::mapper::io {
namespace {

ojson points_json(const std::vector<Point2>& points, const std::string& path) {
  ojson out = ojson::array();
  for (std::size_t i = 0; i < points.size(); ++i) {
    out.push_back(point_json(points[i], JsonReader::index(path, i)));
  }
  return out;
}

std::vector<Point2> read_points(const JsonReader& r, const json& v, const std::string& path) {
  std::vector<Point2> out;
  const json& a = r.array(v, path);
  out.reserve(a.size());
  for (std::size_t i = 0; i < a.size(); ++i)
    out.push_back(r.point(a[i], JsonReader::index(path, i)));
  return out;
}

}  // namespace

std::string asr_to_json_text(const Asr& asr) {
  ojson walls = ojson::array();
  for (std::size_t i = 0; i < asr.walls.size(); ++i) {
    walls.push_back(points_json(asr.walls[i], JsonReader::index("walls", i)));
  }
  ojson exits = ojson::array();
  for (std::size_t i = 0; i < asr.exits.size(); ++i) {
    const Exit& e = asr.exits[i];
    const std::string path = JsonReader::index("exits", i);
    exits.push_back(ojson{{"center", point_json(e.center, path + ".center")},
                          {"width_m", finite_or_throw(e.width_m, path + ".width_m")},
                          {"heading_rad", finite_or_throw(e.heading_rad, path + ".heading_rad")},
                          {"neighbour", e.neighbour ? ojson(*e.neighbour) : ojson(nullptr)}});
  }
  const ojson root{{"format", kAsrFormat},
                   {"version", kFormatVersion},
                   {"id", asr.id},
                   {"pose", pose_json(asr.pose, "pose")},
                   {"odometry_pose", pose_json(asr.odometry_pose, "odometry_pose")},
                   {"walls", walls},
                   {"exits", exits},
                   {"reference_point", point_json(asr.reference_point, "reference_point")},
                   {"parent", asr.parent ? ojson(*asr.parent) : ojson(nullptr)},
                   {"heading_correction_rad",
                    finite_or_throw(asr.heading_correction_rad, "heading_correction_rad")},
                   {"path", points_json(asr.path, "path")},
                   {"cell_scale_mm", finite_or_throw(asr.cell_scale_mm, "cell_scale_mm")},
                   {"grid_bytes", asr.grid_bytes},
                   {"extracted_vertex_count", asr.extracted_vertex_count},
                   {"start_time_s", finite_or_throw(asr.start_time_s, "start_time_s")},
                   {"end_time_s", finite_or_throw(asr.end_time_s, "end_time_s")}};
  return root.dump(1) + "\n";
}

Asr asr_from_json_text(std::string_view text, const std::string& file) {
  const JsonReader r(file);
  const json root = r.parse(text);
  r.header(root, kAsrFormat);
  r.expect_object(root, "",
                  {"format", "version", "id", "pose", "odometry_pose", "walls", "exits",
                   "reference_point", "parent", "heading_correction_rad", "path", "cell_scale_mm",
                   "grid_bytes", "extracted_vertex_count", "start_time_s", "end_time_s"});
  Asr asr;
  asr.id = r.integer(root["id"], "id");
  if (asr.id < 0) r.fail("id", "expected a non-negative integer");
  asr.pose = r.pose(root["pose"], "pose");
  asr.odometry_pose = r.pose(root["odometry_pose"], "odometry_pose");
  const json& walls = r.array(root["walls"], "walls");
  for (std::size_t i = 0; i < walls.size(); ++i) {
    asr.walls.push_back(read_points(r, walls[i], JsonReader::index("walls", i)));
  }
  const json& exits = r.array(root["exits"], "exits");
  for (std::size_t i = 0; i < exits.size(); ++i) {
    const std::string path = JsonReader::index("exits", i);
    const json& e = exits[i];
    r.expect_object(e, path, {"center", "width_m", "heading_rad", "neighbour"});
    Exit exit;
    exit.center = r.point(e["center"], path + ".center");
    exit.width_m = r.number(e["width_m"], path + ".width_m");
    if (exit.width_m < 0.0) r.fail(path + ".width_m", "expected a non-negative number");
    exit.heading_rad = r.number(e["heading_rad"], path + ".heading_rad");
    exit.neighbour = r.optional_integer(e["neighbour"], path + ".neighbour");
    asr.exits.push_back(exit);
  }
  asr.reference_point = r.point(root["reference_point"], "reference_point");
  asr.parent = r.optional_integer(root["parent"], "parent");
  asr.heading_correction_rad = r.number(root["heading_correction_rad"], "heading_correction_rad");
  asr.path = read_points(r, root["path"], "path");
  asr.cell_scale_mm = r.number(root["cell_scale_mm"], "cell_scale_mm");
  if (asr.cell_scale_mm <= 0.0) r.fail("cell_scale_mm", "expected a positive number");
  asr.grid_bytes = r.count(root["grid_bytes"], "grid_bytes");
  asr.extracted_vertex_count = r.count(root["extracted_vertex_count"], "extracted_vertex_count");
  asr.start_time_s = r.number(root["start_time_s"], "start_time_s");
  asr.end_time_s = r.number(root["end_time_s"], "end_time_s");
  return asr;
}

}  // namespace cogmap::mapper::io
