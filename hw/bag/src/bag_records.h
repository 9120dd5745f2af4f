#pragma once
// The records of a ROS 1 bag (format 2.0), read with every length checked against where the
// record must end: each record is a 4-byte header length, the header (fields, each a 4-byte
// length and `name=value`), a 4-byte data length and the data. bag_index_check.cc reads a bag's
// index with it before rosbag_storage, which trusts every length it finds. Plain C++17, no ROS
// headers.

#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <string>

namespace cogmap::hw::bag::records {

/// The `op` of each record kind.
enum Op : int {
  kMessageDefinition = 1,  ///< format 1.2; rosbag skips it before a message's data
  kMessageData = 2,
  kBagHeader = 3,
  kIndexData = 4,
  kChunk = 5,
  kChunkInfo = 6,
  kConnection = 7,
};

/// "a chunk", "an index data record", ..., "a record of op 9", "a record without an op".
std::string op_name(int op);

/// A record header's fields (or a connection header's); of a name given twice the last counts,
/// as in rosbag.
using Fields = std::map<std::string, std::string>;

/// Parses a block of fields. Returns "" or what is wrong with it.
std::string parse_fields(const char* p, std::size_t n, Fields& out);

/// Where records are read from.
class Bytes {
 public:
  virtual ~Bytes() = default;
  virtual std::uint64_t size() const = 0;
  /// Copies [pos, pos + n), which the caller keeps within size().
  virtual void read(std::uint64_t pos, void* out, std::size_t n) const = 0;
};

class FileBytes final : public Bytes {
 public:
  /// Throws BagReadError when the file cannot be opened.
  explicit FileBytes(const std::string& path);
  std::uint64_t size() const override { return size_; }
  void read(std::uint64_t pos, void* out, std::size_t n) const override;  ///< BagReadError

 private:
  mutable std::ifstream in_;
  std::uint64_t size_ = 0;
};

/// A record's place and header.
struct Record {
  std::uint64_t pos = 0;       ///< its header length's first byte
  std::uint64_t data_pos = 0;  ///< its data's first byte
  std::uint32_t data_len = 0;
  int op = -1;  ///< -1: no one-byte `op` field
  Fields fields;
  std::uint64_t end() const { return data_pos + data_len; }
};

/// No record of the format has a header near this (rosbag's own are under 200 bytes).
inline constexpr std::uint32_t kMaxHeaderBytes = 1u << 20;

/// The record at `pos`, which must end by `limit`; nullopt, and `why` says what is wrong, when
/// its header or data would run past `limit`, its header is longer than kMaxHeaderBytes, or its
/// fields do not parse.
std::optional<Record> read_record(const Bytes& bytes, std::uint64_t pos, std::uint64_t limit,
                                  std::string& why);

/// As much of a record in memory as checking a chunk's contents needs: where it ends, its op and
/// its conn field (the thousands of records of a chunk, read without a copy).
struct Brief {
  std::uint64_t end = 0;
  int op = -1;
  std::optional<std::uint32_t> conn;
};

/// The record at `pos` of `data`, which must end by `size`; nullopt and `why` as read_record.
std::optional<Brief> scan_record(const char* data, std::uint64_t size, std::uint64_t pos,
                                 std::string& why);

/// A record's data (its length was checked by read_record).
std::string read_data(const Bytes& bytes, const Record& r);

/// A field of exactly 4 or 8 bytes, little-endian; nullopt when missing or of another size.
std::optional<std::uint32_t> u32(const Fields& f, const std::string& name);
std::optional<std::uint64_t> u64(const Fields& f, const std::string& name);

std::uint32_t le32(const char* p);

}  // namespace cogmap::hw::bag::records
