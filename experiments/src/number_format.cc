#include "cogmap/experiments/number_format.h"

#include <charconv>
#include <cmath>

namespace cogmap::experiments {

std::string format_double(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof(buf), value);
  return std::string(buf, result.ptr);
}

}  // namespace cogmap::experiments
