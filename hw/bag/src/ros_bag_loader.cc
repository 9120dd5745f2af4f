// list_topics and read_streams as the program sees them: each forwards to the ROS bag plugin,
// loaded with dlopen on first use, so a process that reads no bag never maps the ROS 1
// libraries (and the Python, ICU and Boost they bring). Runs in the child of bag_isolation.cc.
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cogmap/plugins/open_plugin.h"
#include "ros_bag_plugin_api.h"

namespace cogmap::hw::bag {
namespace {

using plugin::RosBagApi;

const RosBagApi* load_plugin() {
  std::string file = plugin::kFileName;
  if (const char* dir = std::getenv("COGMAP_PLUGIN_DIR"); dir != nullptr && *dir != '\0') {
    file = (std::filesystem::path(dir) / plugin::kFileName).string();
  }
  const std::string advice =
      "; reinstall cogmap (the plugin belongs in lib/cogmap beside its bin/) or set "
      "COGMAP_PLUGIN_DIR to the folder that holds it";
  std::string why;
  void* handle = plugins::open_plugin(file, RTLD_NOW | RTLD_LOCAL, why);  // kept for the process
  if (handle == nullptr) {
    throw BagReadError("cannot load the ROS bag reader " + file + " (" + why + ")" + advice);
  }
  using Entry = const RosBagApi* (*)();
  const auto entry = reinterpret_cast<Entry>(::dlsym(handle, plugin::kEntryPoint));
  const RosBagApi* api = entry != nullptr ? entry() : nullptr;
  if (api == nullptr || api->version != plugin::kRosBagApiVersion ||
      api->streams_size != sizeof(Streams)) {
    throw BagReadError("the ROS bag reader " + file +
                       " comes from another cogmap build (API mismatch)" + advice);
  }
  return api;
}

const RosBagApi& api() {
  static const RosBagApi* const loaded = load_plugin();  // retried after a failed load
  return *loaded;
}

}  // namespace

std::vector<TopicInfo> list_topics(const std::string& path) { return api().list_topics(path); }

Streams read_streams(const std::string& path, const StreamRequest& request,
                     const std::function<void(const std::string&, std::size_t)>& on_message) {
  return api().read_streams(path, request, on_message);
}

}  // namespace cogmap::hw::bag
