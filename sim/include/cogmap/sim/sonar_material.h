#pragma once
/// How a surface answers a 50 kHz sonar pulse: a mirror lobe around the normal plus a diffuse
/// (rough-surface) backscatter that weakens with incidence and range. The table of built-in
/// materials is data a world file can extend (docs/sonar-model.md, "Materials"), the way Box2D's
/// fixture definitions carry friction and restitution.

#include <optional>
#include <string>
#include <vector>

namespace cogmap::sim {

/// One surface material. Strengths are expected detections (the hazard of the receiver's
/// threshold detector, see docs/sonar-model.md), so 1 - exp(-strength) is a detection probability.
struct SonarMaterial {
  std::string name;
  /// Expected detections of the mirror return when the transducer axis is square to the surface
  /// (the specular point on the axis). Large for every hard surface: a wall faced squarely
  /// always answers.
  double specular_strength = 60.0;
  /// Standard deviation of the mirror lobe in incidence, degrees: how far off normal a surface
  /// still returns its mirror echo (smooth: a few degrees; the pulse's 6.9 mm wavelength against
  /// centimetre roughness widens it).
  double specular_lobe_deg = 6.0;
  /// Diffuse backscatter: expected detections per radian of beam at the beam axis, normal
  /// incidence and 1 m range. Zero makes a perfect mirror.
  double diffuse_strength = 8.0;
  /// n in cos^n(incidence): how fast the diffuse part weakens away from normal incidence.
  double diffuse_incidence_exponent = 0.5;
  /// Fraction of the pulse that goes on along the mirror direction after a hit: the strength of
  /// the one-bounce multipath echoes that leave from this surface.
  double mirror_reflectivity = 0.5;
};

/// The built-in materials, the first being the default of every world: painted_wall (plaster or
/// painted block, calibrated against a real Pioneer corridor recording), wood, glass, metal,
/// fabric. docs/sonar-model.md gives every value and where it comes from.
const std::vector<SonarMaterial>& builtin_sonar_materials();

/// The name of the default material of a world.
inline constexpr const char* kDefaultSonarMaterial = "painted_wall";

/// Index of `name` in `table`, or nullopt.
std::optional<int> find_sonar_material(const std::vector<SonarMaterial>& table,
                                       const std::string& name);

/// The names in `table`, comma separated (for error messages).
std::string sonar_material_names(const std::vector<SonarMaterial>& table);

}  // namespace cogmap::sim
