// libFuzzer entry: any bytes as a cogmap robot log (through a file, as `cogmap replay` reads
// it) must give frames and commands or a LogError naming a line, never a crash, a hang or
// another exception (scripts/fuzz).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "cogmap/hw/robot_log.h"

namespace {

// One file per process, rewritten for every input (tmpfs when /dev/shm exists) and removed when
// the fuzzer exits (a crash leaves it; libFuzzer saves the crashing input itself).
const std::string& scratch_path() {
  // Never destroyed: the exit handler reads it after static destructors may have run.
  static const std::string* path = [] {
    auto* p = new std::string((access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp") +
                              std::string("/cogmap_log_fuzz_") + std::to_string(getpid()));
    std::atexit([] { std::remove(scratch_path().c_str()); });
    return p;
  }();
  return *path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = scratch_path();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    cogmap::hw::LogReader reader(path);
    for (int i = 0; i < 100000; ++i) {
      if (!reader.next()) break;
    }
  } catch (const cogmap::hw::LogError&) {
  }
  return 0;
}
