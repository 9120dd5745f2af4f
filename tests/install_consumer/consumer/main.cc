// A robot program that maps with cogmap's mapper: a P3-DX standing 1 m beside a wall, its 90°
// sonar hearing that wall on every frame, rooms stored as JSON files. Every reading must be
// used; the store must be the installed mapper_io's.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "cogmap/mapper/io/directory_asr_store.h"
#include "cogmap/mapper/mapper.h"
#include "cogmap/mapper/seam/robot_models.h"

int main() {
  const cogmap::mapper::RobotModel* model = cogmap::mapper::find_robot_model("p3dx");
  if (!model || model->geometry.sonars.size() != 16) return 1;
  // A folder of its own for the rooms, removed unless the check fails.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("cogmap_consumer_asrs_" + std::to_string(::getpid()));
  std::size_t used = 0;
  {
    cogmap::mapper::io::DirectoryAsrStore store(dir);
    cogmap::mapper::Mapper mapper(cogmap::mapper::MapperOptions{}, model->geometry, store, {});
    for (int k = 1; k <= 50; ++k) {
      cogmap::mapper::SensorFrame f;
      f.time_s = 0.1 * k;
      f.sonar.push_back({0, 1.0 - 0.136, true, f.time_s});  // sonar 0: y = 0.136 m, 90°
      mapper.process(f);
    }
    used = mapper.stats().readings_used;
  }
  std::printf("p3dx: %zu sonars, %zu of 50 readings used\n", model->geometry.sonars.size(), used);
  if (used != 50) {
    std::printf("its rooms are kept in %s\n", dir.c_str());
    return 2;
  }
  std::filesystem::remove_all(dir);
  return 0;
}
