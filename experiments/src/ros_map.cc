#include "cogmap/experiments/ros_map.h"

#include "cogmap/experiments/number_format.h"
#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::experiments {

std::string histogram_to_pgm(const mapper::HistogramGrid& grid, double occupied_threshold) {
  const int w = grid.width(), h = grid.height();
  std::string out = "P5\n" + std::to_string(w) + " " + std::to_string(h) + "\n255\n";
  const std::size_t header = out.size();
  out.resize(header + static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  char* pixel = out.data() + header;
  // PGM rows run top to bottom; grid rows run with y upwards, so the last row comes first.
  for (int y = h - 1; y >= 0; --y) {
    const float* cells = grid.row(y);
    for (int x = 0; x < w; ++x) {
      const float v = cells[x];
      unsigned char px = kPgmUnknown;
      if (v > occupied_threshold) {
        px = kPgmOccupied;
      } else if (v < 0.0f) {
        px = kPgmFree;
      }
      *pixel++ = static_cast<char>(px);
    }
  }
  return out;
}

std::string ros_map_yaml(const mapper::GridGeometry& geometry, const std::string& image_name) {
  std::string out;
  out += "# cogmap room grid; the origin is in the room's local (ASR) frame, metres\n";
  out += "image: " + image_name + "\n";
  out += "resolution: " + format_double(geometry.cell_size_m()) + "\n";
  out += "origin: [" + format_double(geometry.origin_x_m()) + ", " +
         format_double(geometry.origin_y_m()) + ", 0.0]\n";
  out += "negate: 0\n";
  out += "occupied_thresh: 0.65\n";
  out += "free_thresh: 0.196\n";
  return out;
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
