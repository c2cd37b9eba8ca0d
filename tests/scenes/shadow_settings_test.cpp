// Shadow-settings name tables (parse / to_string / lists), technique-light compatibility and defaults.
#include <gtest/gtest.h>

#include "scenes/shadow_settings.h"

namespace {

template <typename Enum>
void expect_table_round_trips(std::span<const scenes::NamedEntry> table,
                              std::optional<Enum> (*parse)(std::string_view)) {
  ASSERT_FALSE(table.empty());
  for (size_t i = 0; i < table.size(); ++i) {
    const auto v = parse(table[i].name);
    ASSERT_TRUE(v.has_value()) << table[i].name;
    EXPECT_EQ(size_t(*v), i);
    EXPECT_EQ(to_string(*v), table[i].name);
    EXPECT_FALSE(table[i].description.empty());
  }
  EXPECT_FALSE(parse("no-such-name").has_value());
  EXPECT_FALSE(parse("").has_value());
}

TEST(ShadowSettings, NameTablesRoundTrip) {
  expect_table_round_trips<scenes::LightType>(scenes::light_type_names(), scenes::parse_light_type);
  expect_table_round_trips<scenes::ShadowTechnique>(scenes::technique_names(), scenes::parse_technique);
  expect_table_round_trips<scenes::ShadowFilter>(scenes::filter_names(), scenes::parse_filter);
  expect_table_round_trips<scenes::BiasMode>(scenes::bias_mode_names(), scenes::parse_bias_mode);
  expect_table_round_trips<scenes::DepthFormat>(scenes::depth_format_names(), scenes::parse_depth_format);
}

TEST(ShadowSettings, NamesAreTheDocumentedOnes) {
  EXPECT_EQ(scenes::join_names(scenes::technique_names()),
            "none, shadowmap, cube, paraboloid, pyramid, projective, cascades, lispsm, frustum-faces, esm, vsm, "
            "evsm2, evsm4, pcss, irregular");
  EXPECT_EQ(scenes::join_names(scenes::filter_names()), "hard, pcf, poisson, stratified, rotated, early-bail");
  EXPECT_EQ(scenes::join_names(scenes::bias_mode_names()), "none, constant, slope, offset, normal");
  EXPECT_EQ(scenes::join_names(scenes::depth_format_names()), "d16, d24, d32f");
  EXPECT_EQ(scenes::join_names(scenes::light_type_names()), "directional, spot, point, hemispherical");
}

TEST(ShadowSettings, DefaultsFollowTheTutorial) {
  const scenes::ShadowSettings s;
  EXPECT_EQ(s.map_size, 1024u);
  EXPECT_EQ(s.depth_format, scenes::DepthFormat::d16);
  EXPECT_FLOAT_EQ(s.bias.constant, 0.005f);
  EXPECT_FLOAT_EQ(s.bias.slope, 0.005f);
  EXPECT_FLOAT_EQ(s.bias.slope_max, 0.01f);
  EXPECT_EQ(s.poisson_taps, 4u);
  EXPECT_FLOAT_EQ(s.poisson_spread, 1.0f / 700.0f);
}

TEST(ShadowSettings, EveryLightTypeDefaultsToATechniqueItSupports) {
  using scenes::LightType;
  using scenes::ShadowTechnique;
  for (LightType t : {LightType::directional, LightType::spot, LightType::point, LightType::hemispherical})
    EXPECT_TRUE(scenes::technique_supports(scenes::default_shadow_settings(t).technique, t));
  EXPECT_EQ(scenes::default_shadow_settings(LightType::point).technique, ShadowTechnique::cube);
  EXPECT_EQ(scenes::default_shadow_settings(LightType::hemispherical).technique, ShadowTechnique::pyramid);
  EXPECT_FALSE(scenes::technique_supports(ShadowTechnique::cube, LightType::directional));
  EXPECT_FALSE(scenes::technique_supports(ShadowTechnique::pyramid, LightType::point));
  EXPECT_TRUE(scenes::technique_supports(ShadowTechnique::paraboloid, LightType::point));
  EXPECT_TRUE(scenes::technique_supports(ShadowTechnique::projective, LightType::directional));
  EXPECT_TRUE(scenes::technique_supports(ShadowTechnique::none, LightType::spot));
}

}  // namespace
