// Rooms on disk, one atomic JSON file each; only the id index is kept in RAM.

#include "cogmap/mapper/io/directory_asr_store.h"

#include <cstdio>
#include <stdexcept>
#include <string>
#include <system_error>

#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::mapper::io {
namespace {

/// The id in a file name "NNN.json" (three or more digits), or -1.
int id_of(const std::string& name) {
  constexpr std::string_view kExt = ".json";
  if (name.size() < 3 + kExt.size() || !name.ends_with(kExt)) return -1;
  const std::string digits = name.substr(0, name.size() - kExt.size());
  if (digits.size() > 9) return -1;
  for (const char c : digits) {
    if (c < '0' || c > '9') return -1;
  }
  const int id = std::stoi(digits);
  // Only the canonical spelling counts, so "0003.json" never shadows "003.json".
  char canonical[16];
  std::snprintf(canonical, sizeof canonical, "%03d", id);
  return digits == canonical ? id : -1;
}

}  // namespace

DirectoryAsrStore::DirectoryAsrStore(std::filesystem::path dir, Durability durability)
    : dir_(std::move(dir)), durability_(durability) {
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  if (ec) throw std::runtime_error(dir_.string() + ": cannot create directory: " + ec.message());
  for (const auto& entry : std::filesystem::directory_iterator(dir_, ec)) {
    if (!entry.is_regular_file()) continue;
    const int id = id_of(entry.path().filename().string());
    if (id >= 0) ids_.insert(id);
  }
  if (ec) throw std::runtime_error(dir_.string() + ": cannot list directory: " + ec.message());
}

std::filesystem::path DirectoryAsrStore::path_of(int id) const {
  char name[32];
  std::snprintf(name, sizeof name, "%03d.json", id);
  return dir_ / name;
}

void DirectoryAsrStore::save(const Asr& asr) {
  if (asr.id < 0)
    throw std::invalid_argument("ASR id must be non-negative, got " + std::to_string(asr.id));
  write_file_atomic(path_of(asr.id), asr_to_json_text(asr), durability_);
  ids_.insert(asr.id);
}

Asr DirectoryAsrStore::load(int id) const {
  const std::filesystem::path path = path_of(id);
  Asr asr = asr_from_json_text(read_file(path), path.string());
  if (asr.id != id) {
    throw std::runtime_error(path.string() + ": id: expected " + std::to_string(id) +
                             " (the file name), found " + std::to_string(asr.id));
  }
  return asr;
}

std::vector<int> DirectoryAsrStore::ids() const { return {ids_.begin(), ids_.end()}; }

}  // namespace cogmap::mapper::io
