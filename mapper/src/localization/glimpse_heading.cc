// In-room heading correction from short glimpses of the walls; see the header.

#include "cogmap/mapper/localization/glimpse_heading.h"

#include <cmath>
#include <utility>

namespace cogmap::mapper {

GlimpseHeading::GlimpseHeading(const GlimpseOptions& options, std::unique_ptr<GridUpdater> grid,
                               const AsrBuilderOptions& builder, const LocalizerOptions& localizer,
                               double path_spacing_m)
    : options_(options),
      grid_(std::move(grid)),
      builder_(builder),
      localizer_(localizer),
      path_spacing_m_(path_spacing_m) {}

void GlimpseHeading::begin(const Pose2& pose) {
  grid_->reset(pose.translation());
  path_.clear();
  travelled_m_ = 0.0;
  turned_rad_ = 0.0;
  last_position_ = pose.translation();
  grid_->mark_robot(pose);
  path_.push_back(pose.translation());
}

bool GlimpseHeading::visit(const Pose2& pose, double turned_rad) {
  const Point2 p = pose.translation();
  travelled_m_ += (p - last_position_).norm();
  turned_rad_ += std::abs(turned_rad);
  last_position_ = p;
  grid_->mark_robot(pose);
  // The path feeds the clean-map rays; a vertex per half cell is enough (as for rooms).
  if ((p - path_.back()).norm() >= path_spacing_m_) path_.push_back(p);
  return travelled_m_ >= options_.distance_m || turned_rad_ >= options_.turn_rad;
}

GlimpseFix GlimpseHeading::measure(std::span<const Polyline> reference,
                                   const RotationPrior& prior) const {
  GlimpseFix out;
  const AsrTrace trace = build_room_polylines(grid_->histogram(), path_, builder_);
  double total_m = 0.0;
  for (Polyline& wall : accepted_walls(trace)) {
    const double length_m = (wall.back() - wall.front()).norm();
    if (length_m < options_.min_wall_length_m) continue;
    total_m += length_m;
    out.walls.push_back(std::move(wall));
  }
  if (total_m < options_.min_total_wall_m) return out;  // not applied: too little evidence
  out.localization = localizer_.estimate(reference, out.walls, prior);
  return out;
}

}  // namespace cogmap::mapper
