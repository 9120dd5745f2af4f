// The idle controller (teleop / none) and the Controller defaults.

#include "cogmap/mapper/nav/controller.h"

namespace cogmap::mapper::nav {
namespace {

class IdleController final : public Controller {
 public:
  VelocityCommand step(const NavInput&) override { return {}; }
  bool done() const override { return false; }
};

}  // namespace

const NavTrace& Controller::trace() const {
  static const NavTrace kEmpty;
  return kEmpty;
}

const char* to_string(NavMode mode) {
  switch (mode) {
    case NavMode::kIdle:
      return "idle";
    case NavMode::kDrive:
      return "drive";
    case NavMode::kBlocked:
      return "blocked";
    case NavMode::kBackOff:
      return "back_off";
    case NavMode::kTurn:
      return "turn";
    case NavMode::kDone:
      return "done";
    case NavMode::kDoorAlign:
      return "door_align";
    case NavMode::kDoorCross:
      return "door_cross";
    case NavMode::kExploreDone:
      return "explore_done";
    case NavMode::kDoorProbe:
      return "door_probe";
    case NavMode::kDirect:
      return "direct";
    case NavMode::kLook:
      return "look";
    case NavMode::kEdgeFollow:
      return "edge_follow";
    case NavMode::kEdgeCorner:
      return "edge_corner";
    case NavMode::kEdgePivot:
      return "edge_pivot";
    case NavMode::kDoorSearch:
      return "door_search";
  }
  return "?";
}

std::unique_ptr<Controller> make_idle_controller() { return std::make_unique<IdleController>(); }

}  // namespace cogmap::mapper::nav
