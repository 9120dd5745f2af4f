// list_topics and read_streams as the program sees them: each forwards to the ROS bag plugin,
// loaded with dlopen on first use, so a process that reads no bag never maps the ROS 1
// libraries (and the Python, ICU and Boost they bring). Runs in the child of bag_isolation.cc.
#include <dlfcn.h>

#include <cstddef>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "ros_bag_plugin_api.h"

namespace cogmap::hw::bag {
namespace {

using plugin::RosBagApi;

// Why the plain dlopen failed, kept when the search that followed found nothing.
std::string& load_error() {
  static std::string error;
  return error;
}

// The program's own library search path (its RUNPATH, $ORIGIN expanded, then the system's),
// as the dynamic linker would walk it for a library the program itself asked for.
std::vector<std::string> program_search_path() {
  std::vector<std::string> dirs;
  void* self = ::dlopen(nullptr, RTLD_NOW);
  if (self == nullptr) return dirs;
  Dl_serinfo size{};
  if (::dlinfo(self, RTLD_DI_SERINFOSIZE, &size) == 0 && size.dls_size >= sizeof(Dl_serinfo)) {
    std::vector<std::max_align_t> buffer(size.dls_size / sizeof(std::max_align_t) + 1);
    auto* info = reinterpret_cast<Dl_serinfo*>(buffer.data());
    *info = size;
    if (::dlinfo(self, RTLD_DI_SERINFOSIZE, info) == 0 &&
        ::dlinfo(self, RTLD_DI_SERINFO, info) == 0) {
      for (unsigned i = 0; i < info->dls_cnt; ++i) dirs.emplace_back(info->dls_serpath[i].dls_name);
    }
  }
  ::dlclose(self);
  return dirs;
}

// dlopen of a bare file name searches the RUNPATH of the object that calls it; under the
// sanitizers the call comes from their runtime's interceptor, whose RUNPATH is not the
// program's (every bag test failed to load the plugin in the asan preset), so the program's
// own search path is walked here once the plain call has failed.
void* open_plugin(const std::string& file) {
  void* handle = ::dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);  // kept for the process
  if (handle != nullptr || file.find('/') != std::string::npos) return handle;
  const std::string first_error = [] {
    const char* why = ::dlerror();
    return std::string(why != nullptr ? why : "unknown reason");
  }();
  for (const std::string& dir : program_search_path()) {
    const std::string candidate = (std::filesystem::path(dir) / file).string();
    if (!std::filesystem::exists(candidate)) continue;
    handle = ::dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle != nullptr) return handle;
    return nullptr;  // found but not loadable: dlerror() says why
  }
  load_error() = first_error;
  return nullptr;
}

const RosBagApi* load_plugin() {
  std::string file = plugin::kFileName;
  if (const char* dir = std::getenv("COGMAP_PLUGIN_DIR"); dir != nullptr && *dir != '\0') {
    file = (std::filesystem::path(dir) / plugin::kFileName).string();
  }
  const std::string advice =
      "; reinstall cogmap (the plugin belongs in lib/cogmap beside its bin/) or set "
      "COGMAP_PLUGIN_DIR to the folder that holds it";
  load_error().clear();
  void* handle = open_plugin(file);
  if (handle == nullptr) {
    const char* why = ::dlerror();
    const std::string reason =
        !load_error().empty() ? load_error() : (why != nullptr ? why : "unknown reason");
    throw BagReadError("cannot load the ROS bag reader " + file + " (" + reason + ")" + advice);
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
