#include "cogmap/sim/sonar_material.h"

namespace cogmap::sim {

const std::vector<SonarMaterial>& builtin_sonar_materials() {
  // docs/sonar-model.md "Materials" gives the source of every number. painted_wall is fitted to
  // the real P3-DX corridor recording (tests/integration/sonar_calibration_test.cc); the others
  // are set relative to it by acoustic roughness and absorption, as assumptions to measure.
  static const std::vector<SonarMaterial> table = {
      // name, specular strength, lobe deg, diffuse strength /rad, cos exponent, mirror
      // reflectivity
      {"painted_wall", 60.0, 6.0, 8.0, 0.5, 0.5}, {"wood", 60.0, 5.0, 4.0, 1.0, 0.6},
      {"glass", 80.0, 4.0, 0.0, 1.0, 0.95},       {"metal", 100.0, 3.0, 0.4, 2.0, 0.95},
      {"fabric", 4.0, 15.0, 3.0, 1.0, 0.1},
  };
  return table;
}

std::optional<int> find_sonar_material(const std::vector<SonarMaterial>& table,
                                       const std::string& name) {
  for (std::size_t i = 0; i < table.size(); ++i) {
    if (table[i].name == name) return static_cast<int>(i);
  }
  return std::nullopt;
}

std::string sonar_material_names(const std::vector<SonarMaterial>& table) {
  std::string out;
  for (const SonarMaterial& m : table) out += (out.empty() ? "" : ", ") + m.name;
  return out;
}

}  // namespace cogmap::sim
