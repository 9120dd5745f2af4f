#pragma once
/// Checks shared by the subcommands' options, kept in one place (docs/reliability.md):
/// - number options: CLI11's Range and PositiveNumber compare with < and >, which are false for
///   NaN, so `--range nan` passed them and reached the code as NaN (written out as -nan, or cast
///   to an integer). These validators refuse anything but a finite number first (exit 2
///   through main's ParseError handler, naming the option);
/// - output files (`--csv`, `--record`, `sonar-model --out`): never one of the command's inputs,
///   never a file that exists unless --force says to replace it.

#include <CLI/CLI.hpp>
#include <charconv>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "cogmap/experiments/run_directory.h"

namespace cogmap::cli {

namespace detail {

// The option's text as CLI11 will convert it; "" when it is a finite number, else the error.
inline std::string finite_number_error(const std::string& text, double& value) {
  if (!CLI::detail::lexical_cast(text, value)) return "'" + text + "' is not a number";
  if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
  return {};
}

}  // namespace detail

/// A finite number in [lo, hi].
inline CLI::Validator finite_range(double lo, double hi) {
  std::ostringstream description;
  description << "finite number in [" << lo << ", " << hi << "]";
  return CLI::Validator(
      [lo, hi](std::string& text) {
        double value = 0.0;
        std::string error = detail::finite_number_error(text, value);
        if (error.empty() && (value < lo || value > hi)) {
          std::ostringstream s;
          s << text << " is not in [" << lo << ", " << hi << "]";
          error = s.str();
        }
        return error;
      },
      description.str());
}

/// A finite number above zero.
inline CLI::Validator finite_positive() {
  return CLI::Validator(
      [](std::string& text) {
        double value = 0.0;
        std::string error = detail::finite_number_error(text, value);
        if (error.empty() && value <= 0.0) error = text + " is not above zero";
        return error;
      },
      "finite number > 0");
}

/// A count of 1 or more: CLI::PositiveNumber said "Value 0 not in range 0.000000 to 1797693..."
/// (309 digits of DBL_MAX) for `--max-runs 0`.
inline CLI::Validator count_of_one_or_more() {
  return CLI::Validator(
      [](std::string& text) {
        std::size_t value = 0;
        const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
        if (r.ec != std::errc() || r.ptr != text.data() + text.size() || value < 1) {
          return "'" + text + "' is not a whole number of 1 or more";
        }
        return std::string();
      },
      "whole number >= 1");
}

/// A path or address given on the command line must not be empty: `--out ""` (an unset shell
/// variable) used to mean "not given" and wrote to the default directory instead of refusing.
inline CLI::Validator non_empty() {
  return CLI::Validator(
      [](std::string& text) {
        return text.empty() ? std::string("must not be empty") : std::string();
      },
      "not empty");
}

/// An output path a command must not write (exit 2): the message names the option, the path
/// and what to do instead.
class OutputPathError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Throws OutputPathError unless `path`, a file that option `option` makes the command write,
/// may take a new file; the message names the path and, as the way out, the option:
/// - it is not the same file as one of `inputs`, whatever `force` says: the command reads it
///   (`sonar-stats good.log --csv good.log` wrote the table over the log);
/// - it is not a directory or a device, and its nearest existing ancestor is a directory (the
///   writers create missing folders, but cannot make a file one);
/// - it does not exist, unless `force`: a user's file is replaced only when asked.
inline void check_output_file(const std::filesystem::path& path, std::string_view option,
                              const std::vector<std::filesystem::path>& inputs, bool force) {
  namespace fs = std::filesystem;
  const std::string name = path.string();
  const std::string other = "choose another " + std::string(option);
  std::error_code ec;
  for (const fs::path& input : inputs) {
    if (fs::equivalent(path, input, ec)) {
      throw OutputPathError(name + ": is the input " + input.string() + " (the same file), " +
                            "which would be overwritten; " + other);
    }
  }
  const fs::file_status status = fs::status(path, ec);
  if (fs::is_directory(status)) {
    throw OutputPathError(name + ": is a directory, not a file; " + other);
  }
  if (fs::exists(status) && !fs::is_regular_file(status)) {
    throw OutputPathError(name + ": not a regular file (a device, pipe or socket); " + other);
  }
  if (const auto up = experiments::file_in_the_way(fs::absolute(path, ec).parent_path())) {
    throw OutputPathError(name + ": " + up->string() + " is a file, not a directory; " + other);
  }
  // symlink_status: a link is the user's file too, even when it points nowhere.
  if (fs::exists(fs::symlink_status(path, ec)) && !force) {
    throw OutputPathError(name + ": already exists; pass --force to replace it, or " + other);
  }
}

}  // namespace cogmap::cli
