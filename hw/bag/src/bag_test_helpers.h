#pragma once
// What the bag importer's tests share: a scratch path per suite, the error an import must
// give, and a substring check with the whole message on failure.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cogmap/hw/bag_import.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::hw::bag::testing {

/// DIR/NAME.bag in the process's scratch folder (removed when the tests pass), DIR created.
inline std::filesystem::path temp_bag(const std::string& dir, const std::string& name) {
  const std::filesystem::path folder = test_support::process_scratch() / dir;
  std::filesystem::create_directories(folder);
  return folder / (name + ".bag");
}

/// The LogError's message, or a test failure when import_ros_bag does not throw one.
inline std::string import_error(const std::filesystem::path& path,
                                const BagImportOptions& options) {
  try {
    import_ros_bag(path, options);
  } catch (const LogError& e) {
    return e.what();
  }
  ADD_FAILURE() << path << " was accepted";
  return "";
}

inline void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "'" << part << "' not in: " << message;
}

}  // namespace cogmap::hw::bag::testing
