#include "cogmap/experiments/atomic_file.h"

#include <atomic>
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>

namespace cogmap::experiments {
namespace {

// A process-wide counter plus the thread id makes temp names unique when sweep threads
// write into the same directory (results.csv, plots) at the same time.
std::string temp_suffix() {
  static std::atomic<unsigned long> counter{0};
  const auto tid = std::hash<std::thread::id>{}(std::this_thread::get_id());
  return ".tmp." + std::to_string(tid % 1000000) + "." + std::to_string(counter.fetch_add(1));
}

}  // namespace

void write_file_atomic(const std::filesystem::path& path, std::string_view content) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.has_parent_path()) {
    fs::create_directories(path.parent_path(), ec);
    if (ec) {
      throw std::runtime_error(path.parent_path().string() +
                               ": cannot create directory: " + ec.message());
    }
  }
  const fs::path temp = path.string() + temp_suffix();
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(temp.string() + ": cannot open for writing");
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    out.flush();
    if (!out) {
      out.close();
      fs::remove(temp, ec);
      throw std::runtime_error(temp.string() + ": write failed (disk full?)");
    }
  }
  fs::rename(temp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw std::runtime_error(path.string() + ": cannot rename temporary file: " + ec.message());
  }
}

}  // namespace cogmap::experiments
