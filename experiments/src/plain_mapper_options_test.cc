#include "cogmap/experiments/plain_mapper_options.h"

#include <gtest/gtest.h>

namespace cogmap::experiments {
namespace {

/// Options with every map-only refinement on and the rest away from the library's defaults.
mapper::MapperOptions refined() {
  mapper::MapperOptions o;
  o.scan_match.enabled = true;
  o.scan_match.shift = false;
  o.glimpse.enabled = true;
  o.odometry_calibration.curvature_gain = 0.066;
  o.translation.moves_estimate = true;
  o.localizer.echo_refit.band_m = 0.12;
  o.localizer.echo_refit.min_echoes = 40;
  o.localizer.measurement_sd_rad_m = 0.077;
  o.translation.max_offset_m = 0.7;
  o.max_room_travel_m = 4.5;
  o.builder.occupied_threshold = 5.0;
  o.door_fix.enabled = !o.door_fix.enabled;
  o.localization = mapper::LocalizationKind::kNone;
  return o;
}

TEST(PlainMapperOptions, TheMapOnlyRefinementsGoBackToTheLibrarysDefaults) {
  const mapper::MapperOptions library;
  const mapper::MapperOptions plain = plain_mapper_options(refined());
  EXPECT_EQ(plain.scan_match.enabled, library.scan_match.enabled);
  EXPECT_EQ(plain.scan_match.shift, library.scan_match.shift);
  EXPECT_EQ(plain.glimpse.enabled, library.glimpse.enabled);
  EXPECT_EQ(plain.odometry_calibration.curvature_gain, 0.0);
  EXPECT_EQ(plain.translation.moves_estimate, library.translation.moves_estimate);
  EXPECT_EQ(plain.localizer.echo_refit.band_m, library.localizer.echo_refit.band_m);
  EXPECT_EQ(plain.localizer.echo_refit.min_echoes, library.localizer.echo_refit.min_echoes);
  EXPECT_EQ(plain.localizer.echo_refit.band_m, 0.0);
  EXPECT_EQ(plain.localizer.measurement_sd_rad_m, 0.0);  // the steering keeps EM's own sd
  EXPECT_FALSE(plain.scan_match.enabled);
  EXPECT_FALSE(plain.glimpse.enabled);
  EXPECT_FALSE(plain.translation.moves_estimate);
}

TEST(PlainMapperOptions, WhatDecidesRoomsAndCorrectionsIsKept) {
  const mapper::MapperOptions in = refined();
  const mapper::MapperOptions plain = plain_mapper_options(in);
  EXPECT_EQ(plain.translation.max_offset_m, 0.7);  // the map's translation itself stays
  EXPECT_EQ(plain.max_room_travel_m, 4.5);
  EXPECT_EQ(plain.builder.occupied_threshold, 5.0);
  EXPECT_EQ(plain.door_fix.enabled, in.door_fix.enabled);
  EXPECT_EQ(plain.localization, mapper::LocalizationKind::kNone);
}

TEST(PlainMapperOptions, EachRefinementCountsAndNothingElseDoes) {
  const mapper::MapperOptions library;
  EXPECT_FALSE(has_map_only_refinements(library));
  EXPECT_TRUE(has_map_only_refinements(refined()));
  EXPECT_FALSE(has_map_only_refinements(plain_mapper_options(refined())));
  mapper::MapperOptions o = library;
  o.scan_match.enabled = true;
  EXPECT_TRUE(has_map_only_refinements(o));
  o = library;
  o.glimpse.enabled = true;
  EXPECT_TRUE(has_map_only_refinements(o));
  o = library;
  o.odometry_calibration.curvature_gain = 0.066;
  EXPECT_TRUE(has_map_only_refinements(o));
  o = library;
  o.translation.moves_estimate = true;
  EXPECT_TRUE(has_map_only_refinements(o));
  o = library;
  o.localizer.echo_refit.band_m = 0.12;
  EXPECT_TRUE(has_map_only_refinements(o));
  o = library;
  o.localizer.measurement_sd_rad_m = 0.077;
  EXPECT_TRUE(has_map_only_refinements(o));
  // A switched-off matcher's settings, and what both mappers share, are no refinement.
  o = library;
  o.scan_match.shift = false;
  o.localizer.echo_refit.min_echoes = 40;  // its settings while off
  o.max_room_travel_m = 4.5;
  o.builder.occupied_threshold = 5.0;
  EXPECT_FALSE(has_map_only_refinements(o));
}

}  // namespace
}  // namespace cogmap::experiments
