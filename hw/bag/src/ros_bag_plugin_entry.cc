// The ROS bag plugin's entry point: the reader of ros_bag_reader.h as one table. Everything else
// in the plugin stays hidden from the program that loads it.
#include "ros_bag_plugin_api.h"

namespace {

using cogmap::hw::bag::plugin::RosBagApi;

const RosBagApi kApi = [] {
  RosBagApi api;
  api.list_topics = &cogmap::hw::bag::list_topics;
  api.read_streams = &cogmap::hw::bag::read_streams;
  return api;
}();

}  // namespace

extern "C" __attribute__((visibility("default"))) const RosBagApi* cogmap_ros_bag_api() {
  return &kApi;
}
