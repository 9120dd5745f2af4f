#pragma once
// A ROS 1 bag's layout and index as rosbag_storage reads them when it opens the bag: the bag
// header record, the chunks (each followed by its index data records), and at index_pos the
// connection records and chunk info records. read_bag_index reads them with bag_records.h and
// refuses every disagreement between them that would make rosbag read the wrong bytes, skip
// messages, read messages twice or fail without saying where. Plain C++17.

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bag_records.h"

namespace cogmap::hw::bag {

// "byte 123": how an error names a position in the bag file.
inline std::string byte_name(std::uint64_t pos) { return "byte " + std::to_string(pos); }

struct BagConnection {
  std::uint32_t id = 0;
  std::uint64_t pos = 0;            ///< the connection record in the index
  std::string topic, type, header;  ///< header: the connection header's bytes
};

struct BagChunkInfo {
  std::uint64_t pos = 0;  ///< the chunk info record
  std::uint64_t chunk_pos = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> counts;  ///< connection, messages
};

/// One message as an index data record lists it.
struct BagIndexEntry {
  std::uint32_t sec = 0, nsec = 0;
  std::uint32_t offset = 0;  ///< in the chunk's (unpacked) data
};

struct BagIndexData {
  std::uint64_t pos = 0;  ///< the index data record
  std::uint32_t conn = 0;
  std::vector<BagIndexEntry> entries;
};

struct BagChunk {
  records::Record record;           ///< the chunk record: its data is the (packed) messages
  std::string compression;          ///< "none", "bz2" or "lz4"
  std::uint32_t size = 0;           ///< bytes unpacked
  std::vector<BagIndexData> index;  ///< the index data records after it that rosbag reads
  const BagChunkInfo* info = nullptr;
};

struct BagIndex {
  std::uint64_t file_size = 0, index_pos = 0;
  std::map<std::uint32_t, BagConnection> connections;
  std::vector<BagChunkInfo> chunk_infos;
  std::vector<BagChunk> chunks;  ///< in the order rosbag reads them (its chunk infos' order)

  /// "connection 1 (/RosAria/sonar)", or "connection 7 (which no connection record declares)".
  std::string describe(std::uint32_t conn) const;
};

/// The most a compressed chunk may unpack to: rosbag allocates what a chunk's header says
/// before it unpacks it, and writes chunks of 768 KiB (plus the message that fills one).
inline constexpr std::uint32_t kMaxChunkBytes = 256u << 20;

/// Reads the layout and the index. Throws BagReadError naming the record's byte for an index
/// that disagrees with the records. Returns nullopt for a file it leaves to rosbag_storage's
/// own messages: not a format 2.0 bag, an unreadable bag header record, no index (index_pos
/// 0: the recording was not closed), an index past the end of the file (cut short), an
/// encrypted bag.
std::optional<BagIndex> read_bag_index(const records::Bytes& file);

/// "1 message", "2 messages".
std::string count_of(std::uint64_t n, const std::string& what);

}  // namespace cogmap::hw::bag
