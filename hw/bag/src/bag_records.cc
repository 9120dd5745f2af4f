#include "bag_records.h"

#include <cstring>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "ros_bag_reader.h"

namespace cogmap::hw::bag::records {

std::string op_name(int op) {
  switch (op) {
    case kMessageDefinition:
      return "a message definition record";
    case kMessageData:
      return "a message data record";
    case kBagHeader:
      return "a bag header record";
    case kIndexData:
      return "an index data record";
    case kChunk:
      return "a chunk";
    case kChunkInfo:
      return "a chunk info record";
    case kConnection:
      return "a connection record";
    case -1:
      return "a record without an op";
    default:
      return "a record of op " + std::to_string(op);
  }
}

std::uint32_t le32(const char* p) {
  std::uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

namespace {

// Calls f(name, value) for each field; returns "" or what is wrong with the block.
template <typename F>
std::string for_each_field(const char* p, std::size_t n, F&& f) {
  std::size_t at = 0;
  while (at < n) {
    if (n - at < 4) return "a field length cut short";
    const std::uint32_t len = le32(p + at);
    at += 4;
    if (len > n - at) {
      return "a field of " + std::to_string(len) + " bytes where " + std::to_string(n - at) +
             " are left";
    }
    const std::string_view field(p + at, len);
    const std::size_t eq = field.find('=');
    if (eq == std::string_view::npos) return "a field without '='";
    f(field.substr(0, eq), field.substr(eq + 1));
    at += len;
  }
  return "";
}

std::uint64_t room(std::uint64_t at, std::uint64_t limit) { return at <= limit ? limit - at : 0; }

std::string left(std::uint64_t at, std::uint64_t limit) {
  return " (" + std::to_string(room(at, limit)) + " bytes are left)";
}

// "" when a record whose header is `header_len` bytes fits at `pos`, else why not.
std::string header_fits(std::uint64_t pos, std::uint64_t limit, std::uint32_t header_len) {
  if (header_len > kMaxHeaderBytes) {
    return "a record header of " + std::to_string(header_len) + " bytes (none is over " +
           std::to_string(kMaxHeaderBytes) + ")";
  }
  if (room(pos + 4, limit) < std::uint64_t{header_len} + 4) {
    return "a record header of " + std::to_string(header_len) + " bytes" + left(pos, limit);
  }
  return "";
}

std::string data_fits(std::uint64_t data_pos, std::uint64_t limit, std::uint32_t data_len) {
  if (room(data_pos, limit) >= data_len) return "";
  return "a record of " + std::to_string(data_len) + " bytes of data" + left(data_pos, limit);
}

}  // namespace

std::string parse_fields(const char* p, std::size_t n, Fields& out) {
  return for_each_field(p, n, [&out](std::string_view name, std::string_view value) {
    out[std::string(name)] = std::string(value);
  });
}

FileBytes::FileBytes(const std::string& path) : in_(path, std::ios::binary) {
  std::error_code ec;
  size_ = std::filesystem::file_size(path, ec);
  if (!in_ || ec) throw BagReadError("cannot open the file");
}

void FileBytes::read(std::uint64_t pos, void* out, std::size_t n) const {
  in_.clear();
  in_.seekg(static_cast<std::streamoff>(pos));
  in_.read(static_cast<char*>(out), static_cast<std::streamsize>(n));
  if (!in_ || static_cast<std::size_t>(in_.gcount()) != n) {
    throw BagReadError("cannot read " + std::to_string(n) + " bytes at byte " +
                       std::to_string(pos));
  }
}

std::optional<Record> read_record(const Bytes& bytes, std::uint64_t pos, std::uint64_t limit,
                                  std::string& why) {
  if (room(pos, limit) < 4) {
    why = "no room for a record" + left(pos, limit);
    return std::nullopt;
  }
  char len[4];
  bytes.read(pos, len, 4);
  const std::uint32_t header_len = le32(len);
  why = header_fits(pos, limit, header_len);
  if (!why.empty()) return std::nullopt;
  std::string header(header_len, '\0');
  bytes.read(pos + 4, header.data(), header_len);
  Record r;
  r.pos = pos;
  if (std::string bad = parse_fields(header.data(), header.size(), r.fields); !bad.empty()) {
    why = "a record header that does not parse: " + bad;
    return std::nullopt;
  }
  bytes.read(pos + 4 + header_len, len, 4);
  r.data_len = le32(len);
  r.data_pos = pos + 8 + header_len;
  why = data_fits(r.data_pos, limit, r.data_len);
  if (!why.empty()) return std::nullopt;
  const auto op = r.fields.find("op");
  if (op != r.fields.end() && op->second.size() == 1) {
    r.op = static_cast<unsigned char>(op->second[0]);
  }
  return r;
}

std::optional<Brief> scan_record(const char* data, std::uint64_t size, std::uint64_t pos,
                                 std::string& why) {
  if (room(pos, size) < 4) {
    why = "no room for a record" + left(pos, size);
    return std::nullopt;
  }
  const std::uint32_t header_len = le32(data + pos);
  why = header_fits(pos, size, header_len);
  if (!why.empty()) return std::nullopt;
  Brief b;
  why = for_each_field(data + pos + 4, header_len, [&b](std::string_view name, std::string_view v) {
    if (name == "op") b.op = v.size() == 1 ? static_cast<unsigned char>(v[0]) : -1;
    if (name == "conn") b.conn = v.size() == 4 ? std::optional(le32(v.data())) : std::nullopt;
  });
  if (!why.empty()) {
    why = "a record header that does not parse: " + why;
    return std::nullopt;
  }
  const std::uint64_t data_pos = pos + 8 + header_len;
  const std::uint32_t data_len = le32(data + pos + 4 + header_len);
  why = data_fits(data_pos, size, data_len);
  if (!why.empty()) return std::nullopt;
  b.end = data_pos + data_len;
  return b;
}

std::string read_data(const Bytes& bytes, const Record& r) {
  std::string data(r.data_len, '\0');
  bytes.read(r.data_pos, data.data(), data.size());
  return data;
}

std::optional<std::uint32_t> u32(const Fields& f, const std::string& name) {
  const auto it = f.find(name);
  if (it == f.end() || it->second.size() != 4) return std::nullopt;
  return le32(it->second.data());
}

std::optional<std::uint64_t> u64(const Fields& f, const std::string& name) {
  const auto it = f.find(name);
  if (it == f.end() || it->second.size() != 8) return std::nullopt;
  return std::uint64_t{le32(it->second.data())} |
         (std::uint64_t{le32(it->second.data() + 4)} << 32);
}

}  // namespace cogmap::hw::bag::records
