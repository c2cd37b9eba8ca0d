// The key-path-aware JSON read cursor (see json_in.h).
#include "scenes/json_in.h"

#include <cmath>
#include <limits>

#include "scenes/scene_error.h"

namespace scenes {
namespace {

std::string join(std::string_view path, std::string_view key) {
  return path.empty() ? std::string(key) : std::string(path) + "." + std::string(key);
}

const char* plural(size_t n) { return n == 1 ? "" : "s"; }

bool fits_float(double d) { return std::isfinite(d) && std::fabs(d) <= double(std::numeric_limits<float>::max()); }

}  // namespace

void JsonIn::fail(const std::string& message) const { throw SceneError(*file_, path_, message); }

void JsonIn::fail_at(std::string_view key, const std::string& message) const {
  throw SceneError(*file_, key.empty() ? path_ : join(path_, key), message);
}

void JsonIn::allow_only(std::initializer_list<std::string_view> keys, std::string_view context) const {
  if (!value_->is_object()) fail("expected an object");
  for (const auto& [key, v] : value_->items()) {
    bool known = false;
    for (std::string_view k : keys) known = known || k == key;
    if (!known) {
      std::string message = "unknown key";
      if (!context.empty()) message += " (" + std::string(context) + ")";
      throw SceneError(*file_, join(path_, key), message);
    }
  }
}

bool JsonIn::has(std::string_view key) const { return value_->is_object() && value_->contains(key); }

JsonIn JsonIn::member(std::string_view key) const {
  if (!value_->is_object()) fail("expected an object");
  if (!value_->contains(key)) fail("missing key '" + std::string(key) + "'");
  return at(key);
}

std::optional<JsonIn> JsonIn::optional(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return at(key);
}

std::vector<std::string> JsonIn::keys() const {
  if (!value_->is_object()) fail("expected an object");
  std::vector<std::string> out;
  for (const auto& [key, v] : value_->items()) out.push_back(key);
  return out;
}

JsonIn JsonIn::at(std::string_view key) const {
  return JsonIn(value_->find(key).value(), join(path_, key), *file_);
}

JsonIn JsonIn::at(size_t index) const {
  return JsonIn((*value_)[index], path_ + "[" + std::to_string(index) + "]", *file_);
}

std::vector<JsonIn> JsonIn::items() const {
  if (!value_->is_array()) fail("expected an array");
  std::vector<JsonIn> out;
  out.reserve(value_->size());
  for (size_t i = 0; i < value_->size(); ++i) out.push_back(at(i));
  return out;
}

float JsonIn::number() const {
  if (!value_->is_number()) fail("expected a number");
  const double d = value_->get<double>();
  if (!fits_float(d)) fail("expected a finite number that fits in a float");
  return float(d);
}

uint32_t JsonIn::integer(uint32_t lo, uint32_t hi) const {
  const std::string expected =
      "expected an integer between " + std::to_string(lo) + " and " + std::to_string(hi);
  if (!value_->is_number()) fail(expected);
  const double d = value_->get<double>();
  if (!(d >= double(lo) && d <= double(hi)) || std::floor(d) != d) fail(expected);
  return uint32_t(d);
}

bool JsonIn::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false");
  return value_->get<bool>();
}

std::string JsonIn::string() const {
  if (!value_->is_string()) fail("expected a string");
  return value_->get<std::string>();
}

std::string JsonIn::nonempty_string() const {
  std::string s = string();
  if (s.empty()) fail("expected a non-empty string");
  return s;
}

std::vector<float> JsonIn::fixed_numbers(size_t n) const {
  const std::string expected = "expected an array of " + std::to_string(n) + " number" + plural(n);
  if (!value_->is_array() || value_->size() != n) fail(expected);
  for (const auto& e : *value_)
    if (!e.is_number()) fail(expected);
  return numbers();
}

std::vector<float> JsonIn::numbers() const {
  if (!value_->is_array()) fail("expected an array of numbers");
  std::vector<float> out(value_->size());
  for (size_t i = 0; i < out.size(); ++i) {
    const nlohmann::json& e = (*value_)[i];
    if (!e.is_number() || !fits_float(e.get<double>())) at(i).number();  // throws with the element's path
    out[i] = float(e.get<double>());
  }
  return out;
}

glm::vec2 JsonIn::vec2() const {
  const auto v = fixed_numbers(2);
  return {v[0], v[1]};
}

glm::vec3 JsonIn::vec3() const {
  const auto v = fixed_numbers(3);
  return {v[0], v[1], v[2]};
}

glm::vec4 JsonIn::vec4() const {
  const auto v = fixed_numbers(4);
  return {v[0], v[1], v[2], v[3]};
}

glm::mat4 JsonIn::mat4() const {
  const auto v = fixed_numbers(16);
  glm::mat4 m;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) m[c][r] = v[size_t(c * 4 + r)];
  return m;
}

}  // namespace scenes
