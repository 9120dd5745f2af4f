#include "cogmap/mapper/grid/grid_updater.h"

namespace cogmap::mapper {

std::optional<GridKind> parse_grid_kind(std::string_view name) {
  if (name == "himm") return GridKind::kHimm;
  if (name == "mhimm") return GridKind::kMhimm;
  if (name == "bayes") return GridKind::kBayes;
  if (name == "dempster_shafer") return GridKind::kDempsterShafer;
  return std::nullopt;
}

std::string_view to_string(GridKind kind) {
  switch (kind) {
    case GridKind::kHimm:
      return "himm";
    case GridKind::kMhimm:
      return "mhimm";
    case GridKind::kBayes:
      return "bayes";
    case GridKind::kDempsterShafer:
      return "dempster_shafer";
  }
  return "unknown";
}

}  // namespace cogmap::mapper
