#pragma once
// Test support: a bag written by TestBagWriter taken apart into its records (ROS bag format 2.0:
// each record a 4-byte header length, the header's `name=value` fields, a 4-byte data length and
// the data), edited by hand and written back: the damage a hand-made or corrupted bag carries in
// its index, which the rosbag API cannot write. Plain C++17, no ROS headers.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cogmap::hw::bag::testing {

/// Record ops of the format.
enum Op : int {
  kOpMessageData = 2,
  kOpBagHeader = 3,
  kOpIndexData = 4,
  kOpChunk = 5,
  kOpChunkInfo = 6,
  kOpConnection = 7,
};

/// One record: its header fields in file order, then its data.
struct RawRecord {
  std::vector<std::pair<std::string, std::string>> fields;
  std::string data;
  std::uint64_t pos = 0;  ///< where the file held it (RawBag's top-level records)
  bool in_index = false;  ///< at or after the bag header's index_pos

  int op() const;
  const std::string& field(const std::string& name) const;  ///< throws when missing
  void set_field(const std::string& name, const std::string& value);
  std::uint32_t u32(const std::string& name) const;
  std::uint64_t u64(const std::string& name) const;
  void set_u32(const std::string& name, std::uint32_t v);
  void set_u64(const std::string& name, std::uint64_t v);
  std::size_t size() const;  ///< bytes in the file
};

/// A block of `name=value` fields, each after its 4-byte length (a record's header, a connection
/// record's data).
std::vector<std::pair<std::string, std::string>> parse_fields(const std::string& bytes);
std::string serialize_fields(const std::vector<std::pair<std::string, std::string>>& fields);

/// Records laid end to end (a chunk's data, or a file after its version line).
std::vector<RawRecord> parse_records(const std::string& bytes, std::uint64_t base = 0);
std::string serialize_records(const std::vector<RawRecord>& records);

/// A chunk info record's data: (connection id, message count) pairs.
std::vector<std::pair<std::uint32_t, std::uint32_t>> chunk_info_counts(const RawRecord& r);
void set_chunk_info_counts(RawRecord& r,
                           const std::vector<std::pair<std::uint32_t, std::uint32_t>>& counts);

/// An index data record's entries: (time sec, time nsec, offset in the chunk's data).
struct RawIndexEntry {
  std::uint32_t sec = 0, nsec = 0, offset = 0;
};
std::vector<RawIndexEntry> index_entries(const RawRecord& r);
/// Replaces the entries and sets the record's `count`.
void set_index_entries(RawRecord& r, const std::vector<RawIndexEntry>& entries);

/// A whole bag file.
class RawBag {
 public:
  explicit RawBag(const std::string& path);

  /// Writes the records back. The bag header's index_pos becomes the position of the first
  /// record marked in_index, and a chunk info's chunk_pos that named a record load() found
  /// follows that record to where it now lies (other values are written as they are), so
  /// records may change length or be added; counts in the header are written as they are.
  void save(const std::string& path) const;

  /// Position of records[i] as save() writes it.
  std::uint64_t position(std::size_t i) const;
  /// Where records[i]'s data begins as save() writes it.
  std::uint64_t data_position(std::size_t i) const;
  /// Indices into records of every record with this op, in file order.
  std::vector<std::size_t> find(int op) const;
  /// The first connection record in the index for `topic`.
  const RawRecord& connection(const std::string& topic) const;
  /// The index data records that follow chunk record `chunk` (an index into records).
  std::vector<std::size_t> index_records_of(std::size_t chunk) const;

  std::string version_line;        ///< "#ROSBAG V2.0\n"
  std::vector<RawRecord> records;  ///< the bag header record first
};

}  // namespace cogmap::hw::bag::testing
