#pragma once
/// Test support for the log importers' tests: a log file written into the test's own scratch
/// folder, the error an import of it ends in, and the header Player's writelog writes.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cogmap/hw/log_import.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::hw::testing {

/// Writes `text` byte for byte to <scratch>/<suite>/<current test>/<name> and returns its path.
inline std::filesystem::path write_log(const std::string& suite, const std::string& name,
                                       const std::string& text) {
  const std::filesystem::path dir = test_support::process_scratch() / suite /
                                    ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name, std::ios::binary) << text;
  return dir / name;
}

/// The message `import` (an importer taking the path) throws, from the file's name on (the
/// folder before it differs from run to run); "" when it imports.
template <class Import>
std::string import_error(Import import, const std::filesystem::path& p) {
  try {
    (void)import(p);
  } catch (const LogError& e) {
    const std::string what = e.what();
    return what.substr(what.find(p.filename().string()));
  }
  return "";
}

/// The header WriteLog::OpenFile writes (Player 2.x and 3.x alike; note the spaces before the
/// newlines): 8 lines, so a file's first data line is line 9.
inline std::string writelog_header(const std::string& player_version) {
  return "## Player version " + player_version +
         " \n"
         "## File version 0.3.0 \n"
         "## Format: \n"
         "## - Messages are newline-separated\n"
         "## - Common header to each message is:\n"
         "##   time     host   robot  interface index  type   subtype\n"
         "##   (double) (uint) (uint) (string)  (uint) (uint) (uint)\n"
         "## - Following the common header is the message payload \n";
}

}  // namespace cogmap::hw::testing
