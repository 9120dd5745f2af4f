#include <stdexcept>
#include <string>

#include "cogmap/mapper/graph/asr_store.h"

namespace cogmap::mapper {

Asr MemoryAsrStore::load(int id) const {
  const auto it = rooms_.find(id);
  if (it == rooms_.end()) throw std::out_of_range("no ASR with id " + std::to_string(id));
  return it->second;
}

std::vector<int> MemoryAsrStore::ids() const {
  std::vector<int> out;
  for (const auto& [id, asr] : rooms_) out.push_back(id);
  return out;
}

}  // namespace cogmap::mapper
