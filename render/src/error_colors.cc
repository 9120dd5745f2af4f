#include "error_colors.h"

#include <algorithm>
#include <cmath>

namespace cogmap::render {
namespace {

Rgb mix_clamped(Rgb a, Rgb b, double t) {
  const auto f = static_cast<float>(std::clamp(t, 0.0, 1.0));
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

}  // namespace

Rgb error_color(double error_m, const Style& style) {
  // A NaN error (nothing to measure against) is drawn as bad rather than as good.
  if (std::isnan(error_m)) return style.error_bad;
  if (error_m <= style.error_good_m) return style.error_good;
  if (error_m >= style.error_bad_m) return style.error_bad;  // exact, not a float mix
  if (error_m < style.error_mid_m) {
    return mix_clamped(style.error_good, style.error_mid,
                       (error_m - style.error_good_m) / (style.error_mid_m - style.error_good_m));
  }
  return mix_clamped(style.error_mid, style.error_bad,
                     (error_m - style.error_mid_m) / (style.error_bad_m - style.error_mid_m));
}

}  // namespace cogmap::render
