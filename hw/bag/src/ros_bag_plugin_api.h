#pragma once
// The table the ROS bag plugin (libcogmap_ros_bag_plugin.so: ros_bag_reader.cc and the ROS 1
// libraries, which pull in Python, ICU, Boost and more) hands to the program that loads it
// (ros_bag_loader.cc). Only a process that reads a bag maps the ROS libraries. Plain standard
// types only: the plugin side is C++17 (ros_bag_reader.h says why).

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "ros_bag_reader.h"

namespace cogmap::hw::bag::plugin {

/// Raise when a signature below or a struct of ros_bag_reader.h changes.
inline constexpr int kRosBagApiVersion = 2;  // 2: StreamRequest::max_transducers

/// The plugin's one exported symbol: `const RosBagApi* cogmap_ros_bag_api()`.
inline constexpr const char* kEntryPoint = "cogmap_ros_bag_api";

/// Found on the program's run path (lib/cogmap) or in $COGMAP_PLUGIN_DIR.
inline constexpr const char* kFileName = "libcogmap_ros_bag_plugin.so";

struct RosBagApi {
  int version = kRosBagApiVersion;
  unsigned long streams_size = sizeof(Streams);
  std::vector<TopicInfo> (*list_topics)(const std::string&) = nullptr;
  Streams (*read_streams)(const std::string&, const StreamRequest&,
                          const std::function<void(const std::string&, std::size_t)>&) = nullptr;
};

}  // namespace cogmap::hw::bag::plugin
