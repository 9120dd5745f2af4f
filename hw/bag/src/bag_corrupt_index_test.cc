// Bags whose index disagrees with their records (the damage a hand-made or broken bag carries,
// made with test_raw_bag.h): rosbag_storage trusts the index, so each is refused naming the
// record's byte (and a message's topic and index) before rosbag reads the bag; damage that does
// not change what is read is read as before. The rest of the bad bags: bag_corrupt_test.cc.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "bag_test_helpers.h"
#include "cogmap/hw/bag_import.h"
#include "corridor_scenario.h"
#include "test_raw_bag.h"

namespace cogmap::hw {
namespace {

namespace fs = std::filesystem;
using bag::testing::expect_contains;
using bag::testing::import_error;
using bag::testing::TestBagWriter;

using bag::testing::chunk_info_counts;
using bag::testing::Compression;
using bag::testing::index_entries;
using bag::testing::RawBag;
using bag::testing::RawRecord;
using Counts = std::vector<std::pair<std::uint32_t, std::uint32_t>>;
constexpr int kIndexData = bag::testing::kOpIndexData, kChunk = bag::testing::kOpChunk,
              kChunkInfo = bag::testing::kOpChunkInfo, kConnection = bag::testing::kOpConnection;

// 40 odometry and 40 sonar messages in chunks of about 1 kB (22 chunks): 39 frames.
fs::path chunked_bag(const std::string& name, Compression c = Compression::kNone) {
  const fs::path path = bag::testing::temp_bag("cogmap_bag_corrupt_index_test", name);
  TestBagWriter w(path.string(), c, 1024);
  for (int k = 0; k < 40; ++k) {
    const double t = 100.0 + 0.1 * k;
    w.odometry("/RosAria/pose", t, 0.01 * k, 0, 0);
    w.point_cloud("/RosAria/sonar", t + 0.05, {{0.069, 1.0 + 0.001 * k}});
  }
  return path;
}

std::string saved_error(const RawBag& b, const fs::path& path) {
  b.save(path.string());
  return import_error(path, bag::testing::with_robot("p3dx"));
}

std::size_t saved_frames(const RawBag& b, const fs::path& path) {
  b.save(path.string());
  return import_ros_bag(path, bag::testing::with_robot("p3dx")).log.frames.size();
}

std::string bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string at(const RawBag& b, std::size_t i) {
  return "at byte " + std::to_string(b.position(i));
}

// The first chunk holding sonar (connection 1; the odometry is 0) and its sonar index record.
std::pair<std::size_t, std::size_t> sonar_chunk(const RawBag& b, std::size_t nth = 0) {
  for (const std::size_t c : b.find(kChunk)) {
    for (const std::size_t i : b.index_records_of(c)) {
      if (b.records[i].u32("conn") == 1 && nth-- == 0) return {c, i};
    }
  }
  throw std::runtime_error("no sonar chunk");
}

void set_entry_offset(RawRecord& index, std::uint32_t offset) {
  auto entries = index_entries(index);
  entries.at(0).offset = offset;
  bag::testing::set_index_entries(index, entries);
}

TEST(BagCorruptIndex, IndexNamesAConnectionThatNoRecordDeclares) {
  // Was "no sonar topic (... with messages); topics: /RosAria/pose (nav_msgs/Odometry, 40
  // messages)": rosbag drops the index of a connection it does not know, silently.
  for (const bool chunk_infos_too : {true, false}) {
    const fs::path path = chunked_bag("undeclared");
    RawBag b(path.string());
    std::size_t first = 0;
    for (std::size_t i = 0; i < b.records.size(); ++i) {
      RawRecord& r = b.records[i];
      if (r.op() == kIndexData && r.u32("conn") == 1) {
        r.set_u32("conn", 7);
        if (first == 0 && !chunk_infos_too) first = i;
      }
      if (r.op() != kChunkInfo || !chunk_infos_too) continue;
      Counts counts = chunk_info_counts(r);
      for (auto& [conn, n] : counts) conn = conn == 1 ? 7 : conn;
      bag::testing::set_chunk_info_counts(r, counts);
      if (first == 0 && counts.back().first == 7) first = i;
    }
    const std::string e = saved_error(b, path);
    expect_contains(e, path.string() + ": the " + (chunk_infos_too ? "chunk info" : "index data") +
                           " record " + at(b, first));
    expect_contains(e, chunk_infos_too ? " names connection 7 (1 message in the chunk at byte "
                                       : " lists 1 message of connection 7, but ");
    expect_contains(e,
                    ", but no connection record declares connection 7 (the index declares 0 "
                    "/RosAria/pose, 1 /RosAria/sonar): the bag's index is damaged");
  }
}

TEST(BagCorruptIndex, NoConnectionRecordsButMessages) {
  // Was "no sonar topic (...); topics: none".
  const fs::path path = chunked_bag("no_connections");
  RawBag b(path.string());
  auto& rs = b.records;
  rs.erase(std::remove_if(rs.begin(), rs.end(),
                          [](const RawRecord& r) { return r.in_index && r.op() == kConnection; }),
           rs.end());
  rs[0].set_u32("conn_count", 0);
  const std::string e = saved_error(b, path);
  expect_contains(e,
                  "the chunk info record " + at(b, b.find(kChunkInfo)[0]) + " names connection 0");
  expect_contains(e, "no connection record declares connection 0 (the index declares none)");
}

TEST(BagCorruptIndex, MessageRecordOfAnUndeclaredConnection) {
  // Was "topic /RosAria/sonar, message 0: Unknown connection ID: 7" (no byte).
  const fs::path path = chunked_bag("record_conn");
  RawBag b(path.string());
  const std::size_t chunk = sonar_chunk(b).first;
  auto inner = bag::testing::parse_records(b.records[chunk].data);
  for (RawRecord& r : inner) {
    if (r.op() == bag::testing::kOpMessageData && r.u32("conn") == 1) r.set_u32("conn", 7);
  }
  b.records[chunk].data = bag::testing::serialize_records(inner);
  const std::string e = saved_error(b, path);
  expect_contains(e, path.string() + ": topic /RosAria/sonar, message 0: its message data record ");
  expect_contains(e, " names connection 7, which no connection record declares");
}

// rosbag reads the messages its index data records list; a chunk info's per-connection count is
// never used to read (rosbag_storage's Bag only takes how many connections it lists), so a count
// that disagrees changes nothing and the bag reads as it did.
TEST(BagCorruptIndex, ChunkInfoCountThatDisagreesReadsAsBefore) {
  const fs::path path = chunked_bag("chunk_info_count");
  RawBag b(path.string());
  for (const std::size_t i : b.find(kChunkInfo)) {
    Counts counts = chunk_info_counts(b.records[i]);
    for (auto& c : counts) c.second += 5;
    bag::testing::set_chunk_info_counts(b.records[i], counts);
  }
  EXPECT_EQ(saved_frames(b, path), 39u);
}

TEST(BagCorruptIndex, IndexListsFewerMessagesThanTheChunkHolds) {
  // Was read without a word, the unlisted message skipped.
  const fs::path path = chunked_bag("unlisted");
  RawBag b(path.string());
  const auto [chunk, index] = sonar_chunk(b, 3);
  auto entries = index_entries(b.records[index]);
  const std::size_t held = entries.size();
  entries.pop_back();
  bag::testing::set_index_entries(b.records[index], entries);
  const std::string e = saved_error(b, path);
  expect_contains(e,
                  path.string() + ": the chunk " + at(b, chunk) +
                      " holds a message data record of connection 1 (/RosAria/sonar) at offset ");
  expect_contains(e, "that its index does not list (it lists " + std::to_string(held - 1) +
                         " of the chunk's " + std::to_string(held) + ")");
}

TEST(BagCorruptIndex, IndexEntryOutsideItsChunk) {
  // Was "topic /RosAria/sonar, message 2: Error parsing header" (rosbag read past its buffer),
  // or "Required 'op' field missing".
  for (const Compression c : {Compression::kNone, Compression::kLz4}) {
    for (const bool far : {false, true}) {
      const fs::path path = chunked_bag("outside", c);
      RawBag b(path.string());
      const auto [chunk, index] = sonar_chunk(b, 2);
      const std::uint32_t length = b.records[chunk].u32("size");
      const std::uint32_t offset = far ? 0xFFFFFFF0u : length + 100;
      set_entry_offset(b.records[index], offset);
      expect_contains(saved_error(b, path),
                      path.string() + ": topic /RosAria/sonar, message 2: the index data record " +
                          at(b, index) + " puts it at offset " + std::to_string(offset) +
                          " of the " + (c == Compression::kNone ? "" : "lz4 ") + "chunk " +
                          at(b, chunk) + ", whose data is " + std::to_string(length) +
                          " bytes long" + (c == Compression::kNone ? "" : " unpacked"));
    }
  }
}

TEST(BagCorruptIndex, IndexEntryAtARecordThatIsNotItsMessage) {
  // Was "Error parsing header" for an offset inside a record; at the odometry's message, read as
  // a PointCloud without a word: a frame of garbage points.
  for (const bool other_message : {false, true}) {
    const fs::path path = chunked_bag("not_a_message");
    RawBag b(path.string());
    const auto [chunk, index] = sonar_chunk(b, 2);
    std::uint32_t offset = index_entries(b.records[index]).at(0).offset + 3;  // inside it
    if (other_message) {  // the odometry message of the same chunk
      for (const std::size_t i : b.index_records_of(chunk)) {
        if (b.records[i].u32("conn") == 0) offset = index_entries(b.records[i]).at(0).offset;
      }
    }
    set_entry_offset(b.records[index], offset);
    const std::string e = saved_error(b, path);
    expect_contains(e, path.string() + ": topic /RosAria/sonar, message 2: the index data record " +
                           at(b, index) + " puts it at offset " + std::to_string(offset));
    expect_contains(e, other_message ? "where the message data record is connection 0's "
                                       "(/RosAria/pose), not connection 1's"
                                     : "where no record begins");
  }
}

TEST(BagCorruptIndex, ChunkPosBeyondTheFileOrAtARecordThatIsNoChunk) {
  // Was "not a readable ROS 1 bag: " and "Error reading from file: wanted 4 bytes, read 0
  // bytes", "Expected CHUNK op not found" or "wanted 1701736302 bytes, read 49574 bytes".
  const fs::path path = chunked_bag("chunk_pos");
  const RawBag clean(path.string());
  const std::size_t info = clean.find(kChunkInfo).at(2), chunk = clean.find(kChunk).at(1);
  const std::uint64_t chunk_pos = clean.position(chunk);
  const std::vector<std::pair<std::uint64_t, std::string>> cases = {
      {fs::file_size(path) + 100, "past the end of the file"},
      {clean.position(clean.find(kChunkInfo).at(0)), "at or past the index"},
      {clean.position(chunk + 1), "where an index data record is, not a chunk"},
      {chunk_pos + 20,
       "where no record begins (inside the chunk at byte " + std::to_string(chunk_pos) + ")"},
  };
  for (const auto& [pos, what] : cases) {
    RawBag b = clean;
    b.records[info].set_u64("chunk_pos", pos);
    const std::string e = saved_error(b, path);
    expect_contains(e, path.string() + ": the chunk info record " + at(b, info) +
                           " puts its chunk at byte " + std::to_string(pos) + ", " + what);
  }
}

TEST(BagCorruptIndex, ConnectionDeclaredTwiceWithDifferentTypes) {
  // Was "no sonar topic (...); topics: ..., /RosAria/sonar (nav_msgs/Odometry, 40 messages)":
  // rosbag keeps the first declaration, here an Odometry on /RosAria/sonar. The same declaration
  // twice is harmless and reads as before.
  for (const bool differ : {true, false}) {
    const fs::path path = chunked_bag("declared_twice");
    RawBag b(path.string());
    std::size_t sonar = 0;
    while (!(b.records[sonar].in_index && b.records[sonar].op() == kConnection &&
             b.records[sonar].field("topic") == "/RosAria/sonar")) {
      ++sonar;
    }
    RawRecord copy = b.records[sonar];
    auto header = bag::testing::parse_fields(copy.data);
    for (auto& [name, value] : header) {
      if (name == "type" && differ) value = "nav_msgs/Odometry";
    }
    copy.data = bag::testing::serialize_fields(header);
    b.records.insert(b.records.begin() + static_cast<std::ptrdiff_t>(sonar), copy);
    b.records[0].set_u32("conn_count", 3);
    if (!differ) {
      EXPECT_EQ(saved_frames(b, path), 39u);
      continue;
    }
    expect_contains(saved_error(b, path),
                    path.string() + ": connection 1 is declared twice: by the connection record " +
                        at(b, sonar) + " as /RosAria/sonar (nav_msgs/Odometry) and by the one " +
                        at(b, sonar + 1) + " as /RosAria/sonar (sensor_msgs/PointCloud)");
  }
}

TEST(BagCorruptIndex, ChunkWithAHugeSize) {
  // Was read without a word: rosbag ignores an uncompressed chunk's size, and for bz2 asked for
  // 4 GiB and unpacked into it; lz4 said "topic /RosAria/sonar, message 0: ROSLZ4_OUTPUT_SMALL:
  // output buffer is too small".
  for (const Compression c : {Compression::kNone, Compression::kBz2, Compression::kLz4}) {
    const fs::path path = chunked_bag("huge_chunk", c);
    RawBag b(path.string());
    const std::size_t chunk = b.find(kChunk).at(1);
    const std::uint32_t size = b.records[chunk].u32("size");
    if (c != Compression::kNone) {  // a size within the limit that the data does not unpack to
      b.records[chunk].set_u32("size", size + 10);
      expect_contains(saved_error(b, path),
                      path.string() + ": the " + (c == Compression::kBz2 ? "bz2" : "lz4") +
                          " chunk " + at(b, chunk) + " says it unpacks to " +
                          std::to_string(size + 10) + " bytes, but it unpacks to " +
                          std::to_string(size) + ": the chunk is damaged");
    }
    b.records[chunk].set_u32("size", 0xFFFFFF00u);
    const std::string e = saved_error(b, path);
    expect_contains(
        e, path.string() + ": the chunk " + at(b, chunk) + " says it unpacks to 4294967040 bytes");
    expect_contains(e, c == Compression::kNone
                           ? "but it is not compressed and holds " +
                                 std::to_string(b.records[chunk].data.size())
                           : "more than the 268435456 bytes a chunk may unpack to");
  }
}

// The chunk record's own data length, past the end of the file. Was "not a readable ROS 1 bag:
// Error reading from file: wanted 4 bytes, read 0 bytes".
TEST(BagCorruptIndex, ChunkWhoseDataRunsPastTheFile) {
  const fs::path path = chunked_bag("long_chunk");
  const RawBag b(path.string());
  const std::size_t chunk = b.find(kChunk).at(1);
  {
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(static_cast<std::streamoff>(b.data_position(chunk) - 4));
    const std::uint32_t huge = 0xFFFFFF00u;
    f.write(reinterpret_cast<const char*>(&huge), sizeof huge);
  }
  const std::string e = import_error(path, bag::testing::with_robot("p3dx"));
  expect_contains(e, path.string() + ": the chunk info record " + at(b, b.find(kChunkInfo).at(1)) +
                         " puts its chunk " + at(b, chunk) +
                         ", where the records no longer read (" + at(b, chunk).substr(3) +
                         " holds a record of 4294967040 bytes of data (");
}

TEST(BagCorruptIndex, DuplicateAndOverlappingChunkInfos) {
  // Was read with every message of the chunk twice (41 sonar messages of 40); overlapping,
  // "not a readable ROS 1 bag: Error reading from file: wanted 150994944 bytes, read 49660 bytes".
  for (const bool overlap : {false, true}) {
    const fs::path path = chunked_bag("duplicate_chunk");
    RawBag b(path.string());
    const std::size_t info = b.find(kChunkInfo).at(1);
    RawRecord copy = b.records[info];
    const std::uint64_t chunk_pos = copy.u64("chunk_pos");
    if (overlap) copy.set_u64("chunk_pos", chunk_pos + 50);
    b.records.push_back(copy);
    b.records[0].set_u32("chunk_count", b.records[0].u32("chunk_count") + 1);
    const std::string e = saved_error(b, path);
    expect_contains(e, path.string() + ": the chunk info record " + at(b, b.records.size() - 1) +
                           " puts its chunk at byte ");
    expect_contains(e, overlap ? "where no record begins (inside the chunk at byte " +
                                     std::to_string(chunk_pos) + ")"
                               : "a chunk the chunk info record " + at(b, info) + " names already");
  }
}

TEST(BagCorruptIndex, ChunkNamedByNoChunkInfo) {
  // Was read without a word, the chunk's messages skipped.
  const fs::path path = chunked_bag("unnamed_chunk");
  RawBag b(path.string());
  const std::size_t chunk = b.find(kChunk).at(1);
  b.records.erase(b.records.begin() + static_cast<std::ptrdiff_t>(b.find(kChunkInfo).at(1)));
  b.records[0].set_u32("chunk_count", b.records[0].u32("chunk_count") - 1);
  expect_contains(saved_error(b, path), path.string() + ": the chunk " + at(b, chunk) +
                                            " is named by no chunk info record: rosbag would "
                                            "skip its 1 message");
}

TEST(BagCorruptIndex, HeaderCountsDisagreeWithTheIndex) {
  // Was "not a readable ROS 1 bag: Expected CHUNK_INFO op not found", "Expected CONNECTION op not
  // found", "Error reading from file: wanted 4 bytes, read 0 bytes", and for one chunk too few
  // the last chunk skipped without a word.
  const fs::path path = chunked_bag("header_counts");
  const RawBag clean(path.string());
  const std::uint32_t chunks = clean.records[0].u32("chunk_count");
  ASSERT_GT(chunks, 10u);
  for (const auto& [conns, infos] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {1, chunks}, {3, chunks}, {2, chunks - 1}, {2, chunks + 1}}) {
    RawBag b = clean;
    b.records[0].set_u32("conn_count", conns);
    b.records[0].set_u32("chunk_count", infos);
    expect_contains(saved_error(b, path),
                    path.string() + ": the bag header record counts " + std::to_string(conns) +
                        (conns == 1 ? " connection and " : " connections and ") +
                        std::to_string(infos) + " chunks, but its index (from byte " +
                        std::to_string(clean.position(clean.find(kConnection).at(0))) +
                        " to the end of the file) holds 2 connection records and " +
                        std::to_string(chunks) + " chunk info records");
  }
}

// Taken apart and put together, an intact bag is the same file and reads the same, compressed
// or not.
TEST(BagCorruptIndex, UntouchedBagsReadAlike) {
  for (const Compression c : {Compression::kNone, Compression::kBz2, Compression::kLz4}) {
    const fs::path path = chunked_bag("untouched", c);
    const fs::path copy = fs::path(path).replace_extension(".copy.bag");
    RawBag(path.string()).save(copy.string());
    EXPECT_EQ(bytes_of(copy), bytes_of(path));
    EXPECT_EQ(saved_frames(RawBag(path.string()), path), 39u);
  }
}

}  // namespace
}  // namespace cogmap::hw
