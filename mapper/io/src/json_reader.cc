#include "json_reader.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::mapper::io {

json JsonReader::parse(std::string_view text) const {
  try {
    return json::parse(text.begin(), text.end());
  } catch (const json::parse_error& e) {
    throw std::runtime_error(file_ + ": not valid JSON at byte " + std::to_string(e.byte));
  } catch (const json::out_of_range&) {
    // nlohmann refuses numbers beyond a double's range (e.g. 1e999) without a byte offset.
    throw std::runtime_error(file_ + ": not valid JSON: a number is too large for a double");
  }
}

void JsonReader::fail(const std::string& path, const std::string& what) const {
  throw std::runtime_error(file_ + ": " + (path.empty() ? std::string("(root)") : path) + ": " +
                           what);
}

std::string JsonReader::join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string JsonReader::index(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

void JsonReader::expect_object(const json& v, const std::string& path,
                               std::initializer_list<std::string_view> required,
                               std::initializer_list<std::string_view> optional) const {
  if (!v.is_object()) fail(path, "expected an object");
  for (const std::string_view key : required) {
    if (!v.contains(key)) fail(join(path, key), "missing required field");
  }
  // Unknown keys are errors (docs/formats.md): a typo must never fall back silently.
  for (const auto& [key, value] : v.items()) {
    bool known = false;
    for (const std::string_view k : required) known = known || k == key;
    for (const std::string_view k : optional) known = known || k == key;
    if (!known) fail(join(path, key), "unknown field");
  }
}

const json& JsonReader::array(const json& v, const std::string& path) const {
  if (!v.is_array()) fail(path, "expected an array");
  return v;
}

double JsonReader::number(const json& v, const std::string& path) const {
  if (!v.is_number()) fail(path, "expected a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(path, "expected a finite number");
  return x;
}

int JsonReader::integer(const json& v, const std::string& path) const {
  if (!v.is_number_integer()) fail(path, "expected an integer");
  const auto x = v.get<std::int64_t>();
  if (v.is_number_unsigned() && v.get<std::uint64_t>() > std::uint64_t{INT32_MAX}) {
    fail(path, "integer out of range");
  }
  if (x < std::numeric_limits<int>::min() || x > std::numeric_limits<int>::max()) {
    fail(path, "integer out of range");
  }
  return static_cast<int>(x);
}

std::size_t JsonReader::count(const json& v, const std::string& path) const {
  if (!v.is_number_integer()) fail(path, "expected a non-negative integer");
  if (v.is_number_unsigned()) return static_cast<std::size_t>(v.get<std::uint64_t>());
  const auto x = v.get<std::int64_t>();
  if (x < 0) fail(path, "expected a non-negative integer");
  return static_cast<std::size_t>(x);
}

std::string JsonReader::string(const json& v, const std::string& path) const {
  if (!v.is_string()) fail(path, "expected a string");
  return v.get<std::string>();
}

Point2 JsonReader::point(const json& v, const std::string& path) const {
  if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number()) {
    fail(path, "expected [x, y] numbers");
  }
  return {number(v[0], index(path, 0)), number(v[1], index(path, 1))};
}

Pose2 JsonReader::pose(const json& v, const std::string& path) const {
  expect_object(v, path, {"x_m", "y_m", "theta_rad"});
  return {number(v["x_m"], join(path, "x_m")), number(v["y_m"], join(path, "y_m")),
          number(v["theta_rad"], join(path, "theta_rad"))};
}

std::optional<int> JsonReader::optional_integer(const json& v, const std::string& path) const {
  if (v.is_null()) return std::nullopt;
  if (!v.is_number_integer()) fail(path, "expected an integer or null");
  return integer(v, path);
}

void JsonReader::header(const json& root, std::string_view format) const {
  if (!root.is_object()) fail("", "expected an object");
  if (!root.contains("format")) fail("format", "missing required field");
  if (string(root["format"], "format") != format) {
    fail("format", "expected \"" + std::string(format) + "\"");
  }
  if (!root.contains("version")) fail("version", "missing required field");
  const int version = integer(root["version"], "version");
  if (version != kFormatVersion) {
    fail("version", "unsupported version " + std::to_string(version) + " (this reader knows " +
                        std::to_string(kFormatVersion) + ")");
  }
}

double finite_or_throw(double x, const std::string& path) {
  if (!std::isfinite(x)) throw std::invalid_argument(path + ": not a finite number");
  return x;
}

ojson point_json(const Point2& p, const std::string& path) {
  return ojson::array({finite_or_throw(p.x(), path + "[0]"), finite_or_throw(p.y(), path + "[1]")});
}

ojson pose_json(const Pose2& p, const std::string& path) {
  return ojson{{"x_m", finite_or_throw(p.x_m, path + ".x_m")},
               {"y_m", finite_or_throw(p.y_m, path + ".y_m")},
               {"theta_rad", finite_or_throw(p.theta_rad, path + ".theta_rad")}};
}

}  // namespace cogmap::mapper::io
