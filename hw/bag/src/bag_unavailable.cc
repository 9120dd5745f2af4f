// Built instead of the reader when the ROS 1 libraries were missing at configure time: the rest
// of cogmap works, and a bag gets a message that says what to install.
#include "cogmap/hw/bag_import.h"

namespace cogmap::hw {

bool ros_bag_support() { return false; }

ImportedBag import_ros_bag(const std::filesystem::path& path, const BagImportOptions&) {
  throw LogError(path.string() +
                 ": this cogmap was built without ROS bag support; install the Debian "
                 "packages librosbag-storage-dev libsensor-msgs-dev libnav-msgs-dev "
                 "libtf2-msgs-dev (scripts/install-deps does) and build again");
}

}  // namespace cogmap::hw
