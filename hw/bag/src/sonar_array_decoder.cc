// p2os_msgs/SonarArray from its definition text and raw bytes.
#include "sonar_array_decoder.h"

#include <cstring>
#include <sstream>
#include <utility>

#include "ros_bag_reader.h"

namespace cogmap::hw::bag {
namespace {

// The fields of the first section of a definition (up to the `=====` line that starts the
// nested types), comments and constants' values dropped: {type, name} per field.
std::vector<std::pair<std::string, std::string>> top_level_fields(const std::string& text) {
  std::vector<std::pair<std::string, std::string>> fields;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("====", 0) == 0) break;
    if (const auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string type, name;
    if (!(words >> type)) continue;
    words >> name;
    if (const auto eq = name.find('='); eq != std::string::npos) name.erase(eq);
    fields.emplace_back(type, name);
  }
  return fields;
}

class Cursor {
 public:
  Cursor(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  std::uint32_t u32(const char* what) {
    need(4, what);
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | data_[pos_ + static_cast<std::size_t>(i)];
    pos_ += 4;
    return v;
  }
  double f64(const char* what) {
    need(8, what);
    std::uint64_t bits = 0;
    for (int i = 7; i >= 0; --i) bits = (bits << 8) | data_[pos_ + static_cast<std::size_t>(i)];
    pos_ += 8;
    double v;
    std::memcpy(&v, &bits, sizeof v);
    return v;
  }
  void skip(std::size_t n, const char* what) {
    need(n, what);
    pos_ += n;
  }
  std::size_t left() const { return size_ - pos_; }

 private:
  void need(std::size_t n, const char* what) const {
    if (n > size_ - pos_) {
      throw BagReadError("SonarArray truncated: " + std::string(what) + " needs " +
                         std::to_string(n) + " bytes at offset " + std::to_string(pos_) + " of " +
                         std::to_string(size_));
    }
  }
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace

void check_sonar_array_definition(const std::string& md5, const std::string& definition) {
  const std::string layout = "header (std_msgs/Header), int32 ranges_count, float64[] ranges";
  if (md5 != kSonarArrayMd5) {
    throw BagReadError(std::string(kSonarArrayType) + " with MD5 " + md5 + ", expected " +
                       kSonarArrayMd5 + " (" + layout + "): not p2os's message");
  }
  if (definition.empty()) return;  // the MD5 alone pins the layout
  const auto fields = top_level_fields(definition);
  const bool ok = fields.size() == 3 &&
                  (fields[0].first == "Header" || fields[0].first == "std_msgs/Header") &&
                  fields[0].second == "header" && fields[1].first == "int32" &&
                  fields[1].second == "ranges_count" && fields[2].first == "float64[]" &&
                  fields[2].second == "ranges";
  if (!ok) {
    throw BagReadError(std::string(kSonarArrayType) + " definition in the bag does not declare " +
                       layout);
  }
}

SonarArrayData decode_sonar_array(const std::uint8_t* data, std::size_t size) {
  Cursor c(data, size);
  SonarArrayData out;
  c.u32("header.seq");
  const std::uint32_t sec = c.u32("header.stamp.sec");
  const std::uint32_t nsec = c.u32("header.stamp.nsec");
  out.stamp_s = static_cast<double>(sec) + static_cast<double>(nsec) * 1e-9;
  c.skip(c.u32("header.frame_id length"), "header.frame_id");
  const auto count = static_cast<std::int32_t>(c.u32("ranges_count"));
  const std::uint32_t n = c.u32("ranges length");
  if (static_cast<std::uint64_t>(n) * 8u > c.left()) {
    throw BagReadError("SonarArray truncated: " + std::to_string(n) + " ranges need " +
                       std::to_string(static_cast<std::uint64_t>(n) * 8u) + " bytes, " +
                       std::to_string(c.left()) + " left");
  }
  out.ranges_m.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) out.ranges_m.push_back(c.f64("range"));
  if (c.left() != 0) {
    throw BagReadError("SonarArray has " + std::to_string(c.left()) +
                       " bytes after its last field");
  }
  if (count != static_cast<std::int32_t>(n)) {
    throw BagReadError("SonarArray ranges_count " + std::to_string(count) + " but " +
                       std::to_string(n) + " ranges");
  }
  return out;
}

}  // namespace cogmap::hw::bag
