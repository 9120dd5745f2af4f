#pragma once
/// An AsrStore on disk: one JSON file per room, `dir/NNN.json` (id zero-padded to 3 digits).

#include <filesystem>
#include <set>
#include <vector>

#include "cogmap/mapper/graph/asr_store.h"
#include "cogmap/mapper/io/asr_json.h"

namespace cogmap::mapper::io {

/// Finished rooms as files. Only the set of ids lives in RAM; rooms are read back on demand.
class DirectoryAsrStore final : public AsrStore {
 public:
  /// Opens (creating if needed) `dir` and indexes the NNN.json files already in it.
  /// Throws std::runtime_error naming the directory when it cannot be created or listed.
  /// `durability`: whether each room is fsynced as it is saved (write_file_atomic).
  explicit DirectoryAsrStore(std::filesystem::path dir,
                             Durability durability = Durability::kSynced);
  /// Writes `dir/NNN.json` atomically (write_file_atomic). Throws std::invalid_argument for a
  /// negative id or a non-finite number, std::runtime_error on an I/O failure.
  void save(const Asr& asr) override;
  /// Reads and validates `dir/NNN.json`; throws std::runtime_error naming file and field.
  Asr load(int id) const override;
  /// Ids saved or found on disk, ascending.
  std::vector<int> ids() const override;
  /// The file that holds room `id`.
  std::filesystem::path path_of(int id) const;

 private:
  std::filesystem::path dir_;
  Durability durability_;
  std::set<int> ids_;
};

}  // namespace cogmap::mapper::io
