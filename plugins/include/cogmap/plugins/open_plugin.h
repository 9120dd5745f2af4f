#pragma once
/// Opens one of the program's plugins with dlopen: a path as given, a bare file name along the
/// program's own library search path (its RUNPATH, where the build and the install put lib/cogmap).

#include <dlfcn.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace cogmap::plugins {

/// The main program's library search path (its RUNPATH with $ORIGIN expanded, then the
/// system's), as the dynamic linker walks it for a library the program itself asks for.
inline std::vector<std::string> program_search_path() {
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

/// dlopen(file, flags); for a bare name that the plain call cannot open, the program's own
/// search path is walked too. A bare name is searched along the RUNPATH of the object that
/// calls dlopen, and under the sanitizers that is their runtime's interceptor, not the program
/// (the asan preset loaded neither plugin). On failure returns nullptr and sets `error` to why
/// (the plain call's reason when no folder holds the file).
inline void* open_plugin(const std::string& file, int flags, std::string& error) {
  void* handle = ::dlopen(file.c_str(), flags);
  if (handle != nullptr) return handle;
  const char* why = ::dlerror();
  error = why != nullptr ? why : "unknown reason";
  if (file.find('/') != std::string::npos) return nullptr;
  for (const std::string& dir : program_search_path()) {
    const std::filesystem::path candidate = std::filesystem::path(dir) / file;
    std::error_code ec;
    if (!std::filesystem::exists(candidate, ec)) continue;
    handle = ::dlopen(candidate.c_str(), flags);
    if (handle == nullptr) {
      why = ::dlerror();
      error = why != nullptr ? why : "unknown reason";
    }
    return handle;
  }
  return nullptr;
}

}  // namespace cogmap::plugins
