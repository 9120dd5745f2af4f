#include "grid/room_grid.h"

#include <algorithm>

namespace cogmap::mapper {

GridGeometry room_geometry(const Point2& center, const GridOptions& options) {
  const double cell_m = options.cell_scale_mm / 1000.0;
  const int side = std::max(1, static_cast<int>(std::ceil(options.initial_extent_m / cell_m)));
  // Half the side on each side of `center`, so the room starts centred on it.
  const double half_m = 0.5 * side * cell_m;
  return GridGeometry(center.x() - half_m, center.y() - half_m, options.cell_scale_mm, side, side);
}

}  // namespace cogmap::mapper
