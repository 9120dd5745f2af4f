#pragma once
/// Geometry of one sonar cone against a SonarScene (internal to the sonar model): ray casting,
/// specular bounces and the first-arriving echo. Noise-free and deterministic.

#include <optional>
#include <vector>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/sim/sonar_model.h"
#include "sonar_scene_index.h"
#include "sonar_surface_test.h"

namespace cogmap::sim::sonar_detail {

/// Where a ray first meets a surface.
struct RayHit {
  double t_m = 0.0;       ///< distance along the ray, metres
  int surface = -1;       ///< index into SonarScene::surfaces
  mapper::Point2 point;   ///< hit point, world frame
  mapper::Point2 normal;  ///< unit surface normal (either side; use |d·n|)
};

/// The first surface hit by the ray origin + t·dir (dir unit) with t in (eps, max_t];
/// `skip_surface` is ignored (the surface a bounce leaves from). With `index` (built from a scene
/// bit-identical to `scene`) only the surfaces near the ray are tested, in the same order, so the
/// answer is bit-identical to the full scan.
std::optional<RayHit> first_hit(const SonarScene& scene, const mapper::Point2& origin,
                                const mapper::Point2& dir, double max_t_m, int skip_surface = -1,
                                const SceneIndex* index = nullptr);

/// The hit kept by test_surface (`best_i` < 0: none), with its point and the surface's unit
/// normal, computed from the same operands whichever scan found it.
std::optional<RayHit> finish_hit(const SonarScene& scene, const mapper::Point2& origin,
                                 const mapper::Point2& dir, double best_t, int best_i);

/// The mirror image of `dir` about a surface with unit `normal`.
mapper::Point2 reflect(const mapper::Point2& dir, const mapper::Point2& normal);

/// The beam of one transducer, world frame.
struct Cone {
  mapper::Point2 origin{0.0, 0.0};  ///< transducer position, metres
  double axis_rad = 0.0;            ///< beam axis heading, radians
  double max_range_m = 5.0;
};

/// Every way an echo can come back (docs/sonar-model.md "Echo candidates"): per ray of the fan
/// the first surface's mirror lobe and diffuse backscatter, one-bounce multipath and the
/// retro-reflection of concave corners; and every convex corner in sight. Sorted by range
/// (stable). `index`, if given, must be built from a scene bit-identical to `scene`; it changes
/// only the speed, never the candidates.
std::vector<EchoCandidate> echo_candidates(const SonarScene& scene, const Cone& cone,
                                           const SonarModelOptions& options,
                                           const SceneIndex* index = nullptr);

/// The same candidates written into `out` (cleared first), so a caller can reuse its buffer.
void echo_candidates(const SonarScene& scene, const Cone& cone, const SonarModelOptions& options,
                     const SceneIndex* index, std::vector<EchoCandidate>& out);

/// Decides, candidate by candidate, whether the receiver hears an echo.
class EchoListener {
 public:
  virtual ~EchoListener() = default;
  /// True when `candidate` is heard; then no later candidate is offered.
  virtual bool hears(const EchoCandidate& candidate) = 0;
};

/// Offers `listener` the candidates of echo_candidates() in the same order until it hears one,
/// and returns that one (nullopt if none is heard). A ray's bounces are traced only when the
/// candidates offered reach the range of its first hit (a bounce is never nearer), so a ping
/// heard early traces few of them: the same answer as offering the full list, for less work.
std::optional<EchoCandidate> first_heard(const SonarScene& scene, const Cone& cone,
                                         const SonarModelOptions& options, const SceneIndex* index,
                                         EchoListener& listener);

}  // namespace cogmap::sim::sonar_detail
