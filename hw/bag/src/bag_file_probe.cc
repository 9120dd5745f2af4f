#include "bag_file_probe.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string_view>
#include <system_error>
#include <vector>

#include "bag_index.h"
#include "bag_records.h"

namespace cogmap::hw::bag {
namespace {

constexpr std::string_view kMagic = "#ROSBAG V2.0\n";
// The bag header record is padded to 4096 bytes by rosbag; its header fields come first.
constexpr std::size_t kProbeBytes = 4096;

std::uint64_t little_endian(const unsigned char* p, std::size_t bytes) {
  std::uint64_t v = 0;
  for (std::size_t i = bytes; i-- > 0;) v = (v << 8) | p[i];
  return v;
}

std::string cut_short(std::uintmax_t size, const std::string& what) {
  return "the file is " + std::to_string(size) + " bytes long, but " + what +
         ": it was cut short (an incomplete copy or download?)";
}

}  // namespace

std::optional<std::string> describe_truncation(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::vector<unsigned char> head(kProbeBytes);
  in.read(reinterpret_cast<char*>(head.data()), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  if (head.size() < kMagic.size() || std::memcmp(head.data(), kMagic.data(), kMagic.size()) != 0) {
    return std::nullopt;  // not a bag: rosbag's own message says so
  }
  std::size_t at = kMagic.size();
  if (head.size() < at + 4) return cut_short(size, "it ends inside its bag header record");
  const std::uint64_t header_len = little_endian(&head[at], 4);
  at += 4;
  const std::size_t header_end =
      at + static_cast<std::size_t>(std::min<std::uint64_t>(header_len, kProbeBytes));
  if (header_end > head.size()) return cut_short(size, "it ends inside its bag header record");
  // Fields: a 4-byte length, then "name=value" with a binary value.
  while (at + 4 <= header_end) {
    const std::size_t field_len = static_cast<std::size_t>(little_endian(&head[at], 4));
    at += 4;
    if (field_len > header_end - at) break;
    const std::string_view field(reinterpret_cast<const char*>(&head[at]), field_len);
    const std::string_view name = "index_pos=";
    if (field.substr(0, name.size()) == name && field.size() == name.size() + 8) {
      const std::uint64_t index_pos = little_endian(&head[at + name.size()], 8);
      // 0: the recording was never closed, which rosbag reports itself ("no index").
      if (index_pos == 0 || index_pos < size) return std::nullopt;
      return cut_short(size, "its header puts the index at byte " + std::to_string(index_pos));
    }
    at += field_len;
  }
  return std::nullopt;
}

std::uint64_t bag_content_bytes(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) return 0;
  try {
    const records::FileBytes file(path.string());
    std::string why;
    const auto header = records::read_record(file, kMagic.size(), size, why);
    if (!header || header->op != records::kBagHeader) return size;
    const std::uint64_t index_pos = records::u64(header->fields, "index_pos").value_or(0);
    const std::uint64_t end = index_pos > 0 && index_pos <= size ? index_pos : size;
    std::uint64_t unpacked = 0;
    for (std::uint64_t pos = header->end(); pos < end;) {
      const auto r = records::read_record(file, pos, end, why);
      if (!r) break;
      const auto compression = r->fields.find("compression");
      if (r->op == records::kChunk && compression != r->fields.end() &&
          compression->second != "none") {
        const std::uint64_t chunk =
            std::min<std::uint64_t>(records::u32(r->fields, "size").value_or(0), kMaxChunkBytes);
        if (chunk > r->data_len) unpacked += chunk - r->data_len;
      }
      pos = r->end();
    }
    return size + unpacked;
  } catch (const std::exception&) {
    return size;  // a read that failed midway: the reader says why
  }
}

}  // namespace cogmap::hw::bag
