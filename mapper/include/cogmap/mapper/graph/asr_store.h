#pragma once
/// Where finished rooms live. The mapper keeps only the current room and its neighbours in
/// RAM; everything else is saved here as it finishes and loaded back on demand.

#include <map>
#include <vector>

#include "cogmap/mapper/asr/asr.h"

namespace cogmap::mapper {

class AsrStore {
 public:
  virtual ~AsrStore() = default;
  /// Saves (or replaces) a room. File-backed stores replace atomically.
  virtual void save(const Asr& asr) = 0;
  /// Loads a room; throws std::runtime_error naming the file and field on a bad record.
  virtual Asr load(int id) const = 0;
  /// Ids of all stored rooms, ascending.
  virtual std::vector<int> ids() const = 0;
};

/// An AsrStore in RAM, for tests and for runs that write nothing to disk.
class MemoryAsrStore final : public AsrStore {
 public:
  void save(const Asr& asr) override { rooms_[asr.id] = asr; }
  Asr load(int id) const override;
  std::vector<int> ids() const override;

 private:
  std::map<int, Asr> rooms_;
};

}  // namespace cogmap::mapper
