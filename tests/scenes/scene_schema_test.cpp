// docs/scene.schema.json against the technique table (shading/techniques/vocabulary.h): every parameter a
// technique declares is in the schema's shadow.params with the same type, range and choices, and the schema holds
// no other key, so that a file the schema accepts is not refused by the loader for a parameter's value.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "shading/techniques/vocabulary.h"

namespace {

namespace tech = shading::tech;

nlohmann::json read_json(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

// The schema's shadow.params properties.
const nlohmann::json& schema_params(const nlohmann::json& schema) {
  return schema.at("$defs").at("shadow").at("properties").at("params").at("properties");
}

}  // namespace

TEST(SceneSchema, ParamsMatchTheTechniqueTable) {
  const nlohmann::json schema =
      read_json(std::filesystem::path(SHADOWLAB_SOURCE_DIR) / "docs/scene.schema.json");
  const nlohmann::json& props = schema_params(schema);
  std::map<std::string, const tech::ParamSpec*> specs;
  for (const tech::ParamSpec& p : tech::kFilterParams) specs[std::string(p.key)] = &p;
  for (const tech::TechniqueInfo& t : tech::kTechniques)
    for (const tech::ParamSpec& p : t.params) specs[std::string(p.key)] = &p;
  for (const auto& [key, spec] : specs) {
    SCOPED_TRACE(key);
    ASSERT_TRUE(props.contains(key)) << "missing from the schema";
    const nlohmann::json& s = props.at(key);
    switch (spec->kind) {
      case tech::ParamKind::flag: EXPECT_EQ(s.value("type", ""), "boolean"); break;
      case tech::ParamKind::text: EXPECT_EQ(s.value("type", ""), "string"); break;
      case tech::ParamKind::choice: {
        std::set<std::string> choices;
        for (std::string_view c : spec->choices)
          if (!c.empty()) choices.insert(std::string(c));
        EXPECT_EQ(s.at("enum").get<std::set<std::string>>(), choices);
        break;
      }
      case tech::ParamKind::number:
      case tech::ParamKind::integer:
        if (s.contains("enum")) {  // a few values the technique checks itself, all inside the range
          for (const auto& v : s.at("enum")) {
            EXPECT_GE(v.get<double>(), spec->lo);
            EXPECT_LE(v.get<double>(), spec->hi);
          }
          break;
        }
        EXPECT_EQ(s.value("type", ""), spec->kind == tech::ParamKind::integer ? "integer" : "number");
        EXPECT_EQ(s.value("minimum", std::nan("")), spec->lo);
        EXPECT_EQ(s.value("maximum", std::nan("")), spec->hi);
        break;
    }
  }
  for (const auto& [key, value] : props.items()) EXPECT_TRUE(specs.count(key)) << key << " is no technique's";
}
