// Reading a bag's layout and index, in the order rosbag_storage's Bag::open reads them, and
// refusing each disagreement before rosbag meets it (bag_index.h).
#include "bag_index.h"

#include <cstring>
#include <set>

#include "ros_bag_reader.h"

namespace cogmap::hw::bag {
namespace {

using records::Record;

constexpr char kMagic[] = "#ROSBAG V2.0\n";
constexpr std::size_t kMagicBytes = sizeof kMagic - 1;
// A connection header holds the message definition: tens of kilobytes at most.
constexpr std::uint32_t kMaxConnectionHeaderBytes = 16u << 20;

[[noreturn]] void damaged(const std::string& what) {
  throw BagReadError(what + ": the bag's index is damaged");
}

// "a chunk" -> "the chunk at byte 123".
std::string the(const Record& r) {
  std::string name = records::op_name(r.op);
  name = "the " + name.substr(name.find(' ') + 1);
  return name + " at " + byte_name(r.pos);
}

// The records between the bag header record and the index: chunks, each followed by its index
// data records. `stop` is where they stop reading (index_pos when all do).
struct Layout {
  std::map<std::uint64_t, Record> records;
  std::uint64_t header_end = 0, stop = 0;
  std::string why;  // why they stop before index_pos

  // What is at `pos` for a record that should begin there.
  std::string what_is_at(std::uint64_t pos, std::uint64_t index_pos) const {
    if (pos == index_pos) return "the index";
    const auto it = records.find(pos);
    if (it != records.end()) return records::op_name(it->second.op);
    if (pos >= stop) return "nothing readable (" + why + ")";
    return "no record";
  }
};

Layout walk_chunks(const records::Bytes& file, const Record& bag_header, std::uint64_t index_pos) {
  Layout layout;
  layout.header_end = bag_header.end();
  std::uint64_t pos = layout.header_end;
  while (pos < index_pos) {
    std::string why;
    const auto r = records::read_record(file, pos, index_pos, why);
    if (!r) {
      layout.why = byte_name(pos) + " holds " + why;
      break;
    }
    layout.records.emplace(pos, *r);
    pos = r->end();
  }
  layout.stop = pos;
  return layout;
}

std::string declared_list(const BagIndex& index) {
  if (index.connections.empty()) return "none";
  std::string out;
  std::size_t n = 0;
  for (const auto& [id, c] : index.connections) {
    if (++n > 8) return out + " and " + std::to_string(index.connections.size() - 8) + " more";
    out += (out.empty() ? "" : ", ") + std::to_string(id) + " " + c.topic;
  }
  return out;
}

// "<prefix>connection 7<middle>, but no connection record declares connection 7 (...)".
void require_declared(const BagIndex& index, std::uint32_t conn, const std::string& prefix,
                      const std::string& middle = "") {
  if (index.connections.count(conn) > 0) return;
  const std::string c = "connection " + std::to_string(conn);
  damaged(prefix + c + middle + ", but no connection record declares " + c +
          " (the index declares " + declared_list(index) + ")");
}

std::uint32_t need32(const Record& r, const char* name) {
  const auto v = records::u32(r.fields, name);
  if (!v) damaged(the(r) + " has no 4-byte " + name + " field");
  return *v;
}

std::uint64_t need64(const Record& r, const char* name) {
  const auto v = records::u64(r.fields, name);
  if (!v) damaged(the(r) + " has no 8-byte " + name + " field");
  return *v;
}

void read_connections(const records::Bytes& file, const std::vector<Record>& recs,
                      BagIndex& index) {
  for (const Record& r : recs) {
    BagConnection c;
    c.id = need32(r, "conn");
    c.pos = r.pos;
    const auto topic = r.fields.find("topic");
    if (topic == r.fields.end() || topic->second.empty()) damaged(the(r) + " names no topic");
    c.topic = topic->second;
    if (r.data_len > kMaxConnectionHeaderBytes) {
      damaged(the(r) + " holds a connection header of " + std::to_string(r.data_len) + " bytes");
    }
    c.header = records::read_data(file, r);
    records::Fields header;
    if (const std::string bad = records::parse_fields(c.header.data(), c.header.size(), header);
        !bad.empty()) {
      damaged(the(r) + " holds a connection header that does not parse: " + bad);
    }
    c.type = header["type"];
    const auto [it, fresh] = index.connections.emplace(c.id, c);
    const BagConnection& first = it->second;
    if (fresh || (first.topic == c.topic && first.header == c.header)) continue;
    const bool same = first.topic == c.topic && first.type == c.type;
    damaged("connection " + std::to_string(c.id) +
            " is declared twice: by the connection record at " + byte_name(first.pos) + " as " +
            first.topic + " (" + first.type + ") and by the one at " + byte_name(c.pos) + " as " +
            c.topic + " (" + c.type + (same ? ", another connection header" : "") + ")");
  }
}

BagChunkInfo read_chunk_info(const records::Bytes& file, const Record& r) {
  BagChunkInfo info;
  info.pos = r.pos;
  const std::uint32_t ver = need32(r, "ver");
  if (ver != 1) damaged(the(r) + " is of version " + std::to_string(ver) + " (rosbag reads 1)");
  info.chunk_pos = need64(r, "chunk_pos");
  need64(r, "start_time");
  need64(r, "end_time");
  const std::uint32_t count = need32(r, "count");
  // rosbag reads `count` pairs and goes on from there, whatever the data length says.
  if (std::uint64_t{count} * 8 != r.data_len) {
    damaged(the(r) + " counts " + std::to_string(count) + " connections (" +
            std::to_string(std::uint64_t{count} * 8) + " bytes), but its data is " +
            std::to_string(r.data_len) + " bytes");
  }
  const std::string data = records::read_data(file, r);
  std::set<std::uint32_t> seen;  // rosbag keeps them in a map: one per connection
  for (std::uint32_t i = 0; i < count; ++i) {
    info.counts.emplace_back(records::le32(&data[8 * i]), records::le32(&data[8 * i + 4]));
    if (!seen.insert(info.counts.back().first).second) {
      damaged(the(r) + " lists connection " + std::to_string(info.counts.back().first) + " twice");
    }
  }
  return info;
}

BagIndexData read_index_data(const records::Bytes& file, const Record& r, const BagIndex& index,
                             const Record& chunk) {
  BagIndexData d;
  d.pos = r.pos;
  const std::uint32_t ver = need32(r, "ver");
  if (ver != 1) damaged(the(r) + " is of version " + std::to_string(ver) + " (rosbag reads 1)");
  d.conn = need32(r, "conn");
  const std::uint32_t count = need32(r, "count");
  const std::string where =
      the(r) + " (after " + the(chunk) + ") lists " + count_of(count, "message") + " of ";
  require_declared(index, d.conn, where);
  if (std::uint64_t{count} * 12 != r.data_len) {
    damaged(where + "connection " + std::to_string(d.conn) + " (" +
            std::to_string(std::uint64_t{count} * 12) + " bytes), but its data is " +
            std::to_string(r.data_len) + " bytes");
  }
  const std::string data = records::read_data(file, r);
  for (std::uint32_t i = 0; i < count; ++i) {
    const char* e = &data[12 * std::size_t{i}];
    BagIndexEntry entry{records::le32(e), records::le32(e + 4), records::le32(e + 8)};
    // Time 0 is before ros::TIME_MIN: rosbag drops the entry, and with it the message. No writer
    // stores a second's worth of nanoseconds (rosbag carries them into the seconds, or throws).
    if ((entry.sec == 0 && entry.nsec == 0) || entry.nsec > 999999999u) {
      damaged(the(r) + " lists entry " + std::to_string(i) + " of " + index.describe(d.conn) +
              " at " + std::to_string(entry.sec) + " s " + std::to_string(entry.nsec) + " ns" +
              (entry.nsec == 0 ? ", a time rosbag skips the message at"
                               : ": nanoseconds past a second"));
    }
    d.entries.push_back(entry);
  }
  return d;
}

// Where a chunk info's chunk_pos leads: the chunk record there, or an error.
const Record& chunk_at(const BagChunkInfo& info, const Layout& layout, const BagIndex& index) {
  const std::uint64_t p = info.chunk_pos;
  const std::string where = "the chunk info record at " + byte_name(info.pos) +
                            " puts its chunk at " + byte_name(p) + ", ";
  if (p >= index.file_size) {
    damaged(where + "past the end of the file (" + std::to_string(index.file_size) + " bytes)");
  }
  if (p >= index.index_pos)
    damaged(where + "at or past the index (" + byte_name(index.index_pos) + ")");
  const auto it = layout.records.find(p);
  if (it == layout.records.end()) {
    if (p >= layout.stop) damaged(where + "where the records no longer read (" + layout.why + ")");
    auto before = layout.records.upper_bound(p);
    const std::string inside = p < layout.header_end || before == layout.records.begin()
                                   ? "the bag header record"
                                   : the((--before)->second);
    damaged(where + "where no record begins (inside " + inside + ")");
  }
  if (it->second.op != records::kChunk) {
    damaged(where + "where " + records::op_name(it->second.op) + " is, not a chunk");
  }
  return it->second;
}

BagChunk read_chunk(const records::Bytes& file, const BagChunkInfo& info, const Layout& layout,
                    const BagIndex& index) {
  BagChunk chunk;
  chunk.record = chunk_at(info, layout, index);
  chunk.info = &info;
  const Record& r = chunk.record;
  const auto compression = r.fields.find("compression");
  chunk.compression = compression == r.fields.end() ? "" : compression->second;
  if (chunk.compression != "none" && chunk.compression != "bz2" && chunk.compression != "lz4") {
    damaged(the(r) + " is compressed with '" + chunk.compression +
            "', which rosbag does not read (none, bz2, lz4)");
  }
  chunk.size = need32(r, "size");
  const std::string says = the(r) + " says it unpacks to " + std::to_string(chunk.size) + " bytes";
  if (chunk.compression == "none" && chunk.size != r.data_len) {
    damaged(says + ", but it is not compressed and holds " + std::to_string(r.data_len));
  }
  if (chunk.compression != "none" && chunk.size > kMaxChunkBytes) {
    damaged(says + " (" + chunk.compression + ", " + std::to_string(r.data_len) +
            " bytes packed), more than the " + std::to_string(kMaxChunkBytes) +
            " bytes a chunk may unpack to");
  }
  for (const auto& [conn, n] : info.counts) {
    require_declared(index, conn, "the chunk info record at " + byte_name(info.pos) + " names ",
                     " (" + count_of(n, "message") + " in " + the(r) + ")");
  }
  // rosbag reads as many index data records after the chunk as its chunk info lists connections.
  std::uint64_t next = r.end();
  for (std::size_t i = 0; i < info.counts.size(); ++i) {
    const auto it = layout.records.find(next);
    if (it == layout.records.end() || it->second.op != records::kIndexData) {
      damaged("the chunk info record at " + byte_name(info.pos) + " lists " +
              count_of(info.counts.size(), "connection") + " for " + the(r) + ", but " +
              (i == 0 ? "no index data record follows it"
                      : "only " + count_of(i, "index data record") + " follow it") +
              " (" + byte_name(next) + " holds " + layout.what_is_at(next, index.index_pos) + ")");
    }
    chunk.index.push_back(read_index_data(file, it->second, index, r));
    next = it->second.end();
  }
  return chunk;
}

}  // namespace

std::string count_of(std::uint64_t n, const std::string& what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

std::string BagIndex::describe(std::uint32_t conn) const {
  const auto it = connections.find(conn);
  return "connection " + std::to_string(conn) +
         (it == connections.end() ? " (which no connection record declares)"
                                  : " (" + it->second.topic + ")");
}

std::optional<BagIndex> read_bag_index(const records::Bytes& file) {
  BagIndex index;
  index.file_size = file.size();
  if (index.file_size < kMagicBytes) return std::nullopt;
  char magic[kMagicBytes];
  file.read(0, magic, kMagicBytes);
  if (std::memcmp(magic, kMagic, kMagicBytes) != 0) return std::nullopt;
  std::string why;
  const auto header = records::read_record(file, kMagicBytes, index.file_size, why);
  if (!header || header->op != records::kBagHeader) return std::nullopt;
  const auto index_pos = records::u64(header->fields, "index_pos");
  const auto conn_count = records::u32(header->fields, "conn_count");
  const auto chunk_count = records::u32(header->fields, "chunk_count");
  const auto encryptor = header->fields.find("encryptor");
  if (!index_pos || !conn_count || !chunk_count || *index_pos == 0 ||
      *index_pos >= index.file_size ||
      (encryptor != header->fields.end() && !encryptor->second.empty())) {
    return std::nullopt;
  }
  index.index_pos = *index_pos;
  if (index.index_pos < header->end()) {
    damaged("the bag header record puts the index at " + byte_name(index.index_pos) +
            ", inside the bag header record (it ends at " + byte_name(header->end()) + ")");
  }
  const Layout layout = walk_chunks(file, *header, index.index_pos);

  // The index: conn_count connection records, then chunk_count chunk info records.
  std::vector<Record> connections, infos;
  std::uint64_t pos = index.index_pos;
  std::string then;
  while (pos < index.file_size) {
    const auto r = records::read_record(file, pos, index.file_size, why);
    if (r && r->op == records::kConnection && infos.empty()) {
      connections.push_back(*r);
    } else if (r && r->op == records::kChunkInfo) {
      infos.push_back(*r);
    } else {
      then = ", then " + byte_name(pos) + " holds " + (r ? records::op_name(r->op) : why);
      break;
    }
    pos = r->end();
  }
  if (connections.size() != *conn_count || infos.size() != *chunk_count) {
    damaged("the bag header record counts " + count_of(*conn_count, "connection") + " and " +
            count_of(*chunk_count, "chunk") + ", but its index (from " +
            byte_name(index.index_pos) + (then.empty() ? " to the end of the file" : "") +
            ") holds " + count_of(connections.size(), "connection record") + " and " +
            count_of(infos.size(), "chunk info record") + then);
  }
  read_connections(file, connections, index);
  for (const Record& r : infos) index.chunk_infos.push_back(read_chunk_info(file, r));

  std::map<std::uint64_t, std::uint64_t> named;  // chunk position -> its chunk info record
  for (const BagChunkInfo& info : index.chunk_infos) {
    const auto [it, fresh] = named.emplace(info.chunk_pos, info.pos);
    if (!fresh) {
      damaged("the chunk info record at " + byte_name(info.pos) + " puts its chunk at " +
              byte_name(info.chunk_pos) + ", a chunk the chunk info record at " +
              byte_name(it->second) + " names already");
    }
    index.chunks.push_back(read_chunk(file, info, layout, index));
  }
  for (const auto& [p, r] : layout.records) {
    if (r.op != records::kChunk || named.count(p) > 0) continue;
    std::uint64_t messages = 0;
    for (auto it = layout.records.find(r.end());
         it != layout.records.end() && it->second.op == records::kIndexData;
         it = layout.records.find(it->second.end())) {
      messages += records::u32(it->second.fields, "count").value_or(0);
    }
    damaged(the(r) + " is named by no chunk info record: rosbag would skip its " +
            count_of(messages, "message"));
  }
  return index;
}

}  // namespace cogmap::hw::bag
