// Taking a bag apart into records and putting it back together, for hand-made damage.
#include "test_raw_bag.h"

#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>

namespace cogmap::hw::bag::testing {
namespace {

std::uint32_t get32(const std::string& s, std::size_t at) {
  if (at + 4 > s.size()) throw std::runtime_error("raw bag: record cut short");
  std::uint32_t v;
  std::memcpy(&v, s.data() + at, 4);
  return v;
}

void put32(std::string& out, std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); }

std::string fields_bytes(const RawRecord& r) { return serialize_fields(r.fields); }

}  // namespace

std::vector<std::pair<std::string, std::string>> parse_fields(const std::string& bytes) {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t p = 0; p < bytes.size();) {
    const std::uint32_t len = get32(bytes, p);
    if (p + 4 + len > bytes.size()) throw std::runtime_error("raw bag: field cut short");
    const std::string field = bytes.substr(p + 4, len);
    const std::size_t eq = field.find('=');
    if (eq == std::string::npos) throw std::runtime_error("raw bag: field without '='");
    out.emplace_back(field.substr(0, eq), field.substr(eq + 1));
    p += 4 + len;
  }
  return out;
}

std::string serialize_fields(const std::vector<std::pair<std::string, std::string>>& fields) {
  std::string h;
  for (const auto& [name, value] : fields) {
    put32(h, static_cast<std::uint32_t>(name.size() + 1 + value.size()));
    h += name + "=" + value;
  }
  return h;
}

int RawRecord::op() const {
  for (const auto& [name, value] : fields) {
    if (name == "op" && value.size() == 1) return static_cast<unsigned char>(value[0]);
  }
  return -1;
}

const std::string& RawRecord::field(const std::string& name) const {
  for (const auto& f : fields) {
    if (f.first == name) return f.second;
  }
  throw std::runtime_error("raw bag: record at " + std::to_string(pos) + " has no field " + name);
}

void RawRecord::set_field(const std::string& name, const std::string& value) {
  for (auto& f : fields) {
    if (f.first == name) {
      f.second = value;
      return;
    }
  }
  fields.emplace_back(name, value);
}

std::uint32_t RawRecord::u32(const std::string& name) const { return get32(field(name), 0); }

std::uint64_t RawRecord::u64(const std::string& name) const {
  const std::string& v = field(name);
  if (v.size() != 8) throw std::runtime_error("raw bag: field " + name + " is not 8 bytes");
  std::uint64_t x;
  std::memcpy(&x, v.data(), 8);
  return x;
}

void RawRecord::set_u32(const std::string& name, std::uint32_t v) {
  set_field(name, std::string(reinterpret_cast<const char*>(&v), 4));
}

void RawRecord::set_u64(const std::string& name, std::uint64_t v) {
  set_field(name, std::string(reinterpret_cast<const char*>(&v), 8));
}

std::size_t RawRecord::size() const { return 8 + fields_bytes(*this).size() + data.size(); }

std::vector<RawRecord> parse_records(const std::string& bytes, std::uint64_t base) {
  std::vector<RawRecord> out;
  std::size_t at = 0;
  while (at < bytes.size()) {
    RawRecord r;
    r.pos = base + at;
    const std::uint32_t header_len = get32(bytes, at);
    const std::size_t header_end = at + 4 + header_len;
    if (header_end > bytes.size()) throw std::runtime_error("raw bag: header cut short");
    r.fields = parse_fields(bytes.substr(at + 4, header_len));
    const std::uint32_t data_len = get32(bytes, header_end);
    if (header_end + 4 + data_len > bytes.size()) throw std::runtime_error("raw bag: data cut");
    r.data = bytes.substr(header_end + 4, data_len);
    at = header_end + 4 + data_len;
    out.push_back(std::move(r));
  }
  return out;
}

std::string serialize_records(const std::vector<RawRecord>& records) {
  std::string out;
  for (const RawRecord& r : records) {
    const std::string h = fields_bytes(r);
    put32(out, static_cast<std::uint32_t>(h.size()));
    out += h;
    put32(out, static_cast<std::uint32_t>(r.data.size()));
    out += r.data;
  }
  return out;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> chunk_info_counts(const RawRecord& r) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (std::size_t at = 0; at + 8 <= r.data.size(); at += 8) {
    out.emplace_back(get32(r.data, at), get32(r.data, at + 4));
  }
  return out;
}

void set_chunk_info_counts(RawRecord& r,
                           const std::vector<std::pair<std::uint32_t, std::uint32_t>>& counts) {
  r.data.clear();
  for (const auto& [conn, count] : counts) {
    put32(r.data, conn);
    put32(r.data, count);
  }
  r.set_u32("count", static_cast<std::uint32_t>(counts.size()));
}

std::vector<RawIndexEntry> index_entries(const RawRecord& r) {
  std::vector<RawIndexEntry> out;
  for (std::size_t at = 0; at + 12 <= r.data.size(); at += 12) {
    out.push_back({get32(r.data, at), get32(r.data, at + 4), get32(r.data, at + 8)});
  }
  return out;
}

void set_index_entries(RawRecord& r, const std::vector<RawIndexEntry>& entries) {
  r.data.clear();
  for (const RawIndexEntry& e : entries) {
    put32(r.data, e.sec);
    put32(r.data, e.nsec);
    put32(r.data, e.offset);
  }
  r.set_u32("count", static_cast<std::uint32_t>(entries.size()));
}

RawBag::RawBag(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t nl = bytes.find('\n');
  if (nl == std::string::npos) throw std::runtime_error("raw bag: no version line in " + path);
  version_line = bytes.substr(0, nl + 1);
  records = parse_records(bytes.substr(nl + 1), nl + 1);
  if (records.empty() || records[0].op() != kOpBagHeader) {
    throw std::runtime_error("raw bag: no bag header record in " + path);
  }
  const std::uint64_t index_pos = records[0].u64("index_pos");
  for (RawRecord& r : records) r.in_index = index_pos != 0 && r.pos >= index_pos;
}

std::uint64_t RawBag::position(std::size_t i) const {
  std::uint64_t pos = version_line.size();
  for (std::size_t k = 0; k < i; ++k) pos += records[k].size();
  return pos;
}

std::uint64_t RawBag::data_position(std::size_t i) const {
  return position(i) + records[i].size() - records[i].data.size();
}

void RawBag::save(const std::string& path) const {
  std::vector<RawRecord> out = records;
  std::map<std::uint64_t, std::uint64_t> moved;  // old position -> new
  std::uint64_t pos = version_line.size();
  std::uint64_t index_pos = 0;
  for (const RawRecord& r : records) {
    if (r.pos != 0) moved.emplace(r.pos, pos);
    if (r.in_index && index_pos == 0) index_pos = pos;
    pos += r.size();
  }
  for (RawRecord& r : out) {
    if (r.op() != kOpChunkInfo) continue;
    const auto m = moved.find(r.u64("chunk_pos"));
    if (m != moved.end()) r.set_u64("chunk_pos", m->second);
  }
  if (index_pos != 0) out[0].set_u64("index_pos", index_pos);
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f << version_line << serialize_records(out);
  if (!f) throw std::runtime_error("raw bag: cannot write " + path);
}

std::vector<std::size_t> RawBag::find(int op) const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (records[i].op() == op) out.push_back(i);
  }
  return out;
}

const RawRecord& RawBag::connection(const std::string& topic) const {
  for (const RawRecord& r : records) {
    if (r.in_index && r.op() == kOpConnection && r.field("topic") == topic) return r;
  }
  throw std::runtime_error("raw bag: no connection record for " + topic);
}

std::vector<std::size_t> RawBag::index_records_of(std::size_t chunk) const {
  std::vector<std::size_t> out;
  for (std::size_t i = chunk + 1; i < records.size() && records[i].op() == kOpIndexData; ++i) {
    out.push_back(i);
  }
  return out;
}

}  // namespace cogmap::hw::bag::testing
