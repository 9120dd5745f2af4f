#pragma once
/// One seed of an experiment through the real simulator, mapper and runner, figures off, in a
/// fresh directory in the process's scratch folder; its metrics.json, parsed.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cogmap/experiments/experiment_config.h"
#include "cogmap/experiments/runner.h"
#include "cogmap/test_support/scratch_dir.h"
#include "source_dir.h"

namespace cogmap::integration {

inline nlohmann::json run_seed_metrics(experiments::Experiment e, std::uint64_t seed,
                                       const std::string& tag) {
  e.seed = seed;
  experiments::RunOptions o;
  o.out_dir = test_support::process_scratch() / tag;
  o.figures = false;
  std::filesystem::remove_all(o.out_dir);
  (void)experiments::run_experiment(e, o);
  return nlohmann::json::parse(read_file(o.out_dir / "metrics.json"));
}

}  // namespace cogmap::integration
