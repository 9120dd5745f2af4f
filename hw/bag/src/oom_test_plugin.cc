// A stand-in for the ROS bag plugin, built under its name in a folder of its own: it lists a
// sonar and an odometry topic, and its reading runs out of memory at message 2 of the sonar,
// asking for 8 GiB as a damaged length would. With it as COGMAP_PLUGIN_DIR, a test sees how the
// child process of bag_isolation.cc, under its address-space limit, reports a std::bad_alloc
// (bag_message_length_test.cc). Never installed.
#include <vector>

#include "ros_bag_plugin_api.h"

namespace {

using cogmap::hw::bag::StreamRequest;
using cogmap::hw::bag::Streams;
using cogmap::hw::bag::TopicInfo;
using cogmap::hw::bag::plugin::RosBagApi;

std::vector<TopicInfo> list_topics(const std::string&) {
  return {{"/RosAria/pose", "nav_msgs/Odometry", "", 3},
          {"/RosAria/sonar", "sensor_msgs/PointCloud", "", 3}};
}

Streams read_streams(const std::string&, const StreamRequest& request,
                     const std::function<void(const std::string&, std::size_t)>& on_message) {
  for (std::size_t i = 0; i < 3; ++i) {
    if (on_message) on_message(request.sonar_topic, i);
  }
  // Past the child's limit, below what the kernel grants untouched without it.
  std::vector<char> claimed;
  claimed.reserve(std::size_t{8} << 30);
  return {};
}

const RosBagApi kApi = [] {
  RosBagApi api;
  api.list_topics = &list_topics;
  api.read_streams = &read_streams;
  return api;
}();

}  // namespace

extern "C" __attribute__((visibility("default"))) const RosBagApi* cogmap_ros_bag_api() {
  return &kApi;
}
