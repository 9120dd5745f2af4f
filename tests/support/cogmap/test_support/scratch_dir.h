#pragma once
// Scratch folders for tests' files that go away when the tests pass. Standard library, POSIX
// getpid and GoogleTest only, so every test tree can include it (mapper/ too); cogmap_add_test
// puts tests/support on every test's include path.

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>

namespace cogmap::test_support {

/// NAME_<pid> under the system's temporary folder, made empty on construction: the pid keeps
/// apart the tests ctest runs in parallel (each GoogleTest case is its own process). The
/// destructor removes it, unless a test has failed: then it stays, and stderr says where.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() / (name + "_" + std::to_string(::getpid()))),
        owner_(::getpid()) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    if (::getpid() != owner_) return;  // a forked child ending: the folder is its parent's
    if (failed()) {
      std::cerr << "test failed: its scratch is kept in " << path_.string() << "\n";
      return;
    }
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  // The running test's result; between tests (a static ending with the process), all of them.
  static bool failed() {
    const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
    return unit.current_test_info() != nullptr ? ::testing::Test::HasFailure() : unit.Failed();
  }

  std::filesystem::path path_;
  pid_t owner_;
};

/// This process's scratch folder, cogmap_<program>_<pid>, for helpers that hand out paths:
/// made on first use and removed when the process ends (kept, and named, if a test failed).
inline const std::filesystem::path& process_scratch() {
  static const ScratchDir dir([] {
    std::error_code ec;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return "cogmap_" + (ec ? std::string("test") : exe.filename().string());
  }());
  return dir.path();
}

/// process_scratch()/NAME, made empty: one test's folder.
inline std::filesystem::path fresh_scratch(const std::filesystem::path& name) {
  const std::filesystem::path dir = process_scratch() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace cogmap::test_support
