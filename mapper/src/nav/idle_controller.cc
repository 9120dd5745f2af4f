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

std::unique_ptr<Controller> make_idle_controller() { return std::make_unique<IdleController>(); }

}  // namespace cogmap::mapper::nav
