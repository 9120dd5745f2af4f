#pragma once
// What the experiment-file tests share: a file of their own to load, and the error it gives.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/test_support/scratch_dir.h"

namespace cogmap::experiments::test {

namespace fs = std::filesystem;

inline fs::path write_temp(const std::string& name, const std::string& text) {
  // One directory per test: ctest runs the tests of this file as parallel processes.
  const fs::path dir = test_support::process_scratch() / "experiment_config_test" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p;
}

/// The message load_experiment throws for `p` with `overrides`, or "no error".
inline std::string error_of(const fs::path& p, const std::vector<std::string>& overrides = {}) {
  try {
    (void)load_experiment(p, overrides);
  } catch (const yaml::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace cogmap::experiments::test
