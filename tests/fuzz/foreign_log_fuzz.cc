// libFuzzer entry: any bytes as a foreign log (through a file, as `cogmap replay --format auto`
// reads it) through the format detection, the CARMEN importer and the Player importer, each
// of which must give frames or a LogError naming the file, never a crash, a hang or another
// exception. What an importer accepts must also export as a cogmap log that the cogmap reader
// reads back whole (scripts/fuzz; docs/reliability.md "Fuzzing").
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "cogmap/hw/log_import.h"
#include "cogmap/hw/robot_log.h"

namespace {

// Two files per process (the input, its export), rewritten for every input (tmpfs when /dev/shm
// exists) and removed when the fuzzer exits (a crash leaves them; libFuzzer saves the input).
const std::string& scratch_base() {
  // Never destroyed: the exit handler reads it after static destructors may have run.
  static const std::string* base = [] {
    auto* b = new std::string((access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp") +
                              std::string("/cogmap_foreign_fuzz_") + std::to_string(getpid()));
    std::atexit([] {
      std::remove((scratch_base() + ".log").c_str());
      std::remove((scratch_base() + ".cogmap.log").c_str());
    });
    return b;
  }();
  return *base;
}

// An import that succeeded exports to a log the cogmap reader takes frame for frame.
void round_trip(const cogmap::hw::ImportedLog& log) {
  const std::string path = scratch_base() + ".cogmap.log";
  cogmap::hw::write_cogmap_log(path, log);
  try {
    cogmap::hw::LogReader reader(path);
    std::size_t frames = 0;
    while (reader.next()) ++frames;
    if (frames != log.frames.size()) {
      std::fprintf(stderr, "export of %zu frames read back as %zu\n", log.frames.size(), frames);
      std::abort();
    }
  } catch (const cogmap::hw::LogError& e) {
    std::fprintf(stderr, "an imported log exported unreadable: %s\n", e.what());
    std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = scratch_base() + ".log";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    (void)cogmap::hw::detect_log_format(path);
  } catch (const cogmap::hw::LogError&) {
  }
  try {
    round_trip(cogmap::hw::import_carmen_log(path));
  } catch (const cogmap::hw::LogError&) {
  }
  try {
    round_trip(cogmap::hw::import_player_log(path));
  } catch (const cogmap::hw::LogError&) {
  }
  return 0;
}
