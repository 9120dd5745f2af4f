#include "cogmap/mapper/seam/robot_geometry.h"

#include "cogmap/mapper/seam/robot_models.h"

namespace cogmap::mapper {

RobotGeometry p2at_geometry() {
  // The table holds the facts (ARIA p2at.p; docs/p2at.md); this stays for the many callers.
  return find_robot_model("p2at")->geometry;
}

}  // namespace cogmap::mapper
