// Each chunk against the index data records after it (bag_index_check.h).
#include "bag_index_check.h"

#include <bzlib.h>
#include <roslz4/lz4s.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "bag_index.h"
#include "ros_bag_reader.h"

namespace cogmap::hw::bag {
namespace {

// "topic T, message K" for every entry of every chunk's index, K counted in the order
// rosbag::View reads a topic: by index time, ties in the order the index lists them.
class MessageNames {
 public:
  explicit MessageNames(const BagIndex& index) : index_(index) {
    using Entry = std::tuple<std::uint64_t, std::size_t, std::size_t, std::size_t>;
    std::map<std::string, std::vector<Entry>> topics;
    number_.resize(index.chunks.size());
    for (std::size_t c = 0; c < index.chunks.size(); ++c) {
      const auto& records = index.chunks[c].index;
      number_[c].resize(records.size());
      for (std::size_t r = 0; r < records.size(); ++r) {
        number_[c][r].resize(records[r].entries.size());
        for (std::size_t e = 0; e < records[r].entries.size(); ++e) {
          const BagIndexEntry& x = records[r].entries[e];
          const std::uint64_t t = std::uint64_t{x.sec} * 1000000000u + x.nsec;
          topics[index.connections.at(records[r].conn).topic].emplace_back(t, c, r, e);
        }
      }
    }
    for (auto& [topic, entries] : topics) {
      std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
        return std::get<0>(a) < std::get<0>(b);
      });
      for (std::size_t k = 0; k < entries.size(); ++k) {
        number_[std::get<1>(entries[k])][std::get<2>(entries[k])][std::get<3>(entries[k])] = k;
      }
    }
  }

  std::string of(std::size_t chunk, std::size_t record, std::size_t entry) const {
    const std::uint32_t conn = index_.chunks[chunk].index[record].conn;
    return "topic " + index_.connections.at(conn).topic + ", message " +
           std::to_string(number_[chunk][record][entry]);
  }

 private:
  const BagIndex& index_;
  std::vector<std::vector<std::vector<std::size_t>>> number_;
};

// A chunk's data, unpacked.
struct ChunkData {
  std::unique_ptr<char[]> bytes;  // not zero-filled: only what is unpacked is touched
  std::size_t size = 0;
};

std::string the_chunk(const BagChunk& c) {
  return std::string(c.compression == "none" ? "" : c.compression + " ") + "chunk at " +
         byte_name(c.record.pos);
}

ChunkData unpack(const records::Bytes& file, const BagChunk& chunk) {
  ChunkData out;
  out.size = chunk.size;
  out.bytes.reset(new char[std::max<std::size_t>(out.size, 1)]);
  if (chunk.compression == "none") {
    file.read(chunk.record.data_pos, out.bytes.get(), out.size);
    return out;
  }
  std::string packed = records::read_data(file, chunk.record);
  unsigned int got = chunk.size;
  int rc = 0;
  bool full = false;
  if (chunk.compression == "bz2") {
    rc = BZ2_bzBuffToBuffDecompress(out.bytes.get(), &got, packed.data(),
                                    static_cast<unsigned int>(packed.size()), 0, 0);
    full = rc == BZ_OUTBUFF_FULL;
    rc = rc == BZ_OK ? 0 : rc;
  } else {
    rc = roslz4_buffToBuffDecompress(packed.data(), static_cast<unsigned int>(packed.size()),
                                     out.bytes.get(), &got);
    full = rc == ROSLZ4_OUTPUT_SMALL;
    rc = rc == ROSLZ4_OK ? 0 : rc;
  }
  const std::string says = "the " + the_chunk(chunk) + " says it unpacks to " +
                           std::to_string(chunk.size) + " bytes, but ";
  if (full) throw BagReadError(says + "it unpacks to more: the chunk is damaged");
  if (rc != 0) {
    throw BagReadError("the " + the_chunk(chunk) + " does not unpack (" + chunk.compression +
                       " error " + std::to_string(rc) + "): the chunk is damaged");
  }
  if (got != chunk.size) {
    throw BagReadError(says + "it unpacks to " + std::to_string(got) + ": the chunk is damaged");
  }
  return out;
}

class ChunkCheck {
 public:
  ChunkCheck(const BagIndex& index, const BagChunk& chunk, std::size_t number,
             const MessageNames& names)
      : index_(index), chunk_(chunk), number_(number), names_(names) {}

  void run(const ChunkData& data) {
    walk(data);
    for (std::size_t r = 0; r < chunk_.index.size(); ++r) {
      for (std::size_t e = 0; e < chunk_.index[r].entries.size(); ++e) entry(r, e);
    }
    unlisted();
  }

 private:
  struct Inner {
    std::uint64_t offset = 0;
    records::Brief record;
    std::size_t listed_by_record = 0, listed_by_entry = 0;
    bool listed = false;
  };

  // "at byte B (offset O in the chunk at byte P)", or "at offset O of the bz2 chunk at ...".
  std::string at(std::uint64_t offset) const {
    if (chunk_.compression == "none") {
      return "at " + byte_name(chunk_.record.data_pos + offset) + " (offset " +
             std::to_string(offset) + " in the " + the_chunk(chunk_) + ")";
    }
    return "at offset " + std::to_string(offset) + " of the " + the_chunk(chunk_) + " (unpacked)";
  }

  [[noreturn]] void damaged(const std::string& what) const {
    throw BagReadError(what + ": the bag's index is damaged");
  }

  void walk(const ChunkData& data) {
    std::uint64_t pos = 0;
    while (pos < data.size) {
      std::string why;
      const auto r = records::scan_record(data.bytes.get(), data.size, pos, why);
      if (!r) {
        // Damage inside the chunk: name the message whose record it is, where the index has one.
        std::string name;
        for (std::size_t i = 0; i < chunk_.index.size(); ++i) {
          for (std::size_t e = 0; e < chunk_.index[i].entries.size(); ++e) {
            if (chunk_.index[i].entries[e].offset == pos) name = names_.of(number_, i, e) + ": ";
          }
        }
        throw BagReadError(name + "the record " + at(pos) + " does not read: " + why +
                           ": the chunk is damaged");
      }
      inner_.push_back({pos, *r});
      pos = r->end;
    }
  }

  void entry(std::size_t r, std::size_t e) {
    const BagIndexData& index = chunk_.index[r];
    const std::uint32_t offset = index.entries[e].offset;
    // The messages are built only for an error: a chunk lists thousands of messages.
    const auto puts = [&] {
      return names_.of(number_, r, e) + ": the index data record at " + byte_name(index.pos) +
             " puts it at offset " + std::to_string(offset) + " of the " + the_chunk(chunk_) + ", ";
    };
    if (offset >= chunk_.size) {
      damaged(puts() + "whose data is " + std::to_string(chunk_.size) + " bytes long" +
              (chunk_.compression == "none" ? "" : " unpacked"));
    }
    auto it = std::lower_bound(inner_.begin(), inner_.end(), offset,
                               [](const Inner& x, std::uint64_t o) { return x.offset < o; });
    if (it == inner_.end() || it->offset != offset) {
      const Inner& around = *std::prev(it);
      damaged(puts() + "where no record begins (inside " + records::op_name(around.record.op) +
              " at offset " + std::to_string(around.offset) + ")");
    }
    // As rosbag does, step over connection (and old message definition) records to the message.
    while (it != inner_.end() && (it->record.op == records::kConnection ||
                                  it->record.op == records::kMessageDefinition)) {
      ++it;
    }
    if (it == inner_.end() || it->record.op != records::kMessageData) {
      damaged(puts() + "where " +
              (it == inner_.end() ? std::string("the chunk ends")
                                  : records::op_name(it->record.op) + " is") +
              ", not a message data record");
    }
    const auto message = [&] {
      return names_.of(number_, r, e) + ": its message data record " + at(it->offset);
    };
    const std::optional<std::uint32_t> conn = it->record.conn;
    if (!conn) damaged(message() + " has no 4-byte conn field");
    if (*conn != index.conn && index_.connections.count(*conn) == 0) {
      damaged(message() + " names connection " + std::to_string(*conn) +
              ", which no connection record declares (the index lists it under " +
              index_.describe(index.conn) + ")");
    }
    if (*conn != index.conn) {
      damaged(puts() + "where the message data record is connection " + std::to_string(*conn) +
              "'s (" + index_.connections.at(*conn).topic + "), not connection " +
              std::to_string(index.conn) + "'s");
    }
    if (it->listed) {
      damaged(puts() + "where the index lists " +
              names_.of(number_, it->listed_by_record, it->listed_by_entry) + " already");
    }
    it->listed = true;
    it->listed_by_record = r;
    it->listed_by_entry = e;
  }

  void unlisted() const {
    for (const Inner& x : inner_) {
      if (x.record.op != records::kMessageData || x.listed) continue;
      std::size_t held = 0, lists = 0;
      for (const Inner& other : inner_) {
        if (other.record.op == records::kMessageData && other.record.conn == x.record.conn) {
          ++held;
          lists += other.listed ? 1 : 0;
        }
      }
      const std::string conn = x.record.conn ? index_.describe(*x.record.conn)
                                             : std::string("no connection (no conn field)");
      damaged("the " + the_chunk(chunk_) + " holds a message data record of " + conn +
              " at offset " + std::to_string(x.offset) +
              (chunk_.compression == "none"
                   ? " (" + byte_name(chunk_.record.data_pos + x.offset) + ")"
                   : std::string()) +
              " that its index does not list (it lists " + std::to_string(lists) +
              " of the chunk's " + std::to_string(held) + ")");
    }
  }

  const BagIndex& index_;
  const BagChunk& chunk_;
  std::size_t number_;
  const MessageNames& names_;
  std::vector<Inner> inner_;  // the chunk's records, by offset
};

}  // namespace

void check_bag_index(const std::string& path) {
  std::unique_ptr<records::FileBytes> file;
  try {
    file = std::make_unique<records::FileBytes>(path);
  } catch (const BagReadError&) {
    return;  // rosbag says why it cannot open it
  }
  const std::optional<BagIndex> index = read_bag_index(*file);
  if (!index) return;
  const MessageNames names(*index);
  for (std::size_t c = 0; c < index->chunks.size(); ++c) {
    ChunkCheck(*index, index->chunks[c], c, names).run(unpack(*file, index->chunks[c]));
  }
}

}  // namespace cogmap::hw::bag
