#include "cogmap/experiments/ros_map.h"

#include <cstdint>
#include <iterator>

#include "cogmap/experiments/number_format.h"
#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::experiments {

namespace {

/// A binary PGM (P5) of w x h pixels; `pixel_of(x, y)` gives the grey of map cell (x, y), whose
/// rows run with y upwards, while PGM rows run top to bottom: the last row comes first.
template <class PixelOf>
std::string pgm_bottom_up(int w, int h, PixelOf pixel_of) {
  std::string out = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  const std::size_t header = out.size();
  out.resize(header + static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  char* pixel = out.data() + header;
  for (int y = h - 1; y >= 0; --y) {
    for (int x = 0; x < w; ++x) *pixel++ = static_cast<char>(pixel_of(x, y));
  }
  return out;
}

}  // namespace

std::string histogram_to_pgm(const mapper::HistogramGrid& grid, double occupied_threshold) {
  return pgm_bottom_up(grid.width(), grid.height(), [&](int x, int y) {
    const float v = grid.row(y)[x];
    if (v > occupied_threshold) return kPgmOccupied;
    return v < 0.0f ? kPgmFree : kPgmUnknown;
  });
}

namespace {

std::string map_server_yaml(const std::string& comment, const std::string& image_name,
                            double resolution_m, double origin_x_m, double origin_y_m) {
  std::string out;
  out += "# " + comment + "\n";
  out += "image: " + image_name + "\n";
  out += "resolution: " + format_double(resolution_m) + "\n";
  out += "origin: [" + format_double(origin_x_m) + ", " + format_double(origin_y_m) + ", 0.0]\n";
  out += "negate: 0\n";
  out += "occupied_thresh: 0.65\n";
  out += "free_thresh: 0.196\n";
  return out;
}

}  // namespace

std::string ros_map_yaml(const mapper::GridGeometry& geometry, const std::string& image_name) {
  return map_server_yaml("cogmap room grid; the origin is in the room's local (ASR) frame, metres",
                         image_name, geometry.cell_size_m(), geometry.origin_x_m(),
                         geometry.origin_y_m());
}

std::string explore_map_pgm(const mapper::nav::ExploreMapImage& image) {
  // Indexed by ExploreMapImage::Cell: unseen, free, obstacle, frontier, frontier given up.
  constexpr unsigned char kGrey[] = {kPgmUnknown, kPgmFree, kPgmOccupied, kPgmFrontier,
                                     kPgmBannedFrontier};
  return pgm_bottom_up(image.width, image.height, [&](int x, int y) {
    const std::uint8_t cell = image.cells[static_cast<std::size_t>(y) * image.width + x];
    return cell < std::size(kGrey) ? kGrey[cell] : kPgmUnknown;
  });
}

void write_explore_map(const mapper::nav::ExploreMapImage& image, const std::filesystem::path& dir,
                       mapper::io::Durability durability) {
  mapper::io::write_file_atomic(dir / "explore_map.pgm", explore_map_pgm(image), durability);
  mapper::io::write_file_atomic(
      dir / "explore_map.yaml",
      map_server_yaml("cogmap explore map (the explorer's own, estimate frame, metres): 254 free, "
                      "0 obstacle, 205 unseen, 160 frontier, 100 frontier given up",
                      "explore_map.pgm", image.cell_m, image.origin_m.x(), image.origin_m.y()),
      durability);
}

void write_ros_map(const mapper::HistogramGrid& grid, double occupied_threshold,
                   const std::filesystem::path& dir, const std::string& stem,
                   mapper::io::Durability durability) {
  mapper::io::write_file_atomic(dir / (stem + ".pgm"), histogram_to_pgm(grid, occupied_threshold),
                                durability);
  mapper::io::write_file_atomic(dir / (stem + ".yaml"),
                                ros_map_yaml(grid.geometry(), stem + ".pgm"), durability);
}

}  // namespace cogmap::experiments
