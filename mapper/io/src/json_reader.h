#pragma once
// Validating access to parsed JSON: every failure names the file and the field path.

#include <cstddef>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "cogmap/mapper/seam/geometry.h"
#include "cogmap/mapper/seam/pose2.h"

namespace cogmap::mapper::io {

using nlohmann::json;
/// Writers keep the documented key order (format and version first).
using ojson = nlohmann::ordered_json;

/// Reads fields out of a json value, throwing "file: path: what" on anything unexpected.
class JsonReader {
 public:
  explicit JsonReader(std::string file) : file_(std::move(file)) {}

  /// Parses `text`; a syntax error or truncation becomes "file: not valid JSON at byte N".
  json parse(std::string_view text) const;

  [[noreturn]] void fail(const std::string& path, const std::string& what) const;

  /// `path` joined with a key ("pose" + "x_m" -> "pose.x_m").
  static std::string join(const std::string& path, std::string_view key);
  /// `path` with an index ("walls" + 2 -> "walls[2]").
  static std::string index(const std::string& path, std::size_t i);

  /// Checks `v` is an object holding exactly the keys `required` plus any of `optional`.
  void expect_object(const json& v, const std::string& path,
                     std::initializer_list<std::string_view> required,
                     std::initializer_list<std::string_view> optional = {}) const;
  const json& array(const json& v, const std::string& path) const;
  double number(const json& v, const std::string& path) const;      ///< finite
  int integer(const json& v, const std::string& path) const;        ///< fits int
  std::size_t count(const json& v, const std::string& path) const;  ///< non-negative
  std::string string(const json& v, const std::string& path) const;
  Point2 point(const json& v, const std::string& path) const;  ///< [x, y]
  Pose2 pose(const json& v, const std::string& path) const;    ///< {x_m, y_m, theta_rad}
  std::optional<int> optional_integer(const json& v, const std::string& path) const;  ///< or null
  /// Checks "format" and "version" of a file's root object.
  void header(const json& root, std::string_view format) const;

 private:
  std::string file_;
};

/// Throws std::invalid_argument naming `path` when `x` is not finite (JSON cannot hold it).
double finite_or_throw(double x, const std::string& path);
/// [x, y] with finite numbers.
ojson point_json(const Point2& p, const std::string& path);
/// {x_m, y_m, theta_rad}.
ojson pose_json(const Pose2& p, const std::string& path);

}  // namespace cogmap::mapper::io
