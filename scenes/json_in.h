// A read cursor over a parsed JSON document that knows its key path, so every type or value error and every
// unknown key becomes a SceneError `file: objects[2].transform.scale: expected an array of 3 numbers`.
// Used by the scenes module's JSON reader and by the CLI's readers of its own documents (the merge commands).
#pragma once
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace scenes {

class JsonIn {
 public:
  JsonIn(const nlohmann::json& value, std::string path, const std::string& file)
      : value_(&value), path_(std::move(path)), file_(&file) {}

  const nlohmann::json& value() const { return *value_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& message) const;
  // Fails at `key` below this value (a dotted sub-path; empty: here), whether or not the key is present.
  [[noreturn]] void fail_at(std::string_view key, const std::string& message) const;

  // Objects. allow_only() also requires an object; `context` is appended to the unknown-key message.
  void allow_only(std::initializer_list<std::string_view> keys, std::string_view context = {}) const;
  bool has(std::string_view key) const;
  JsonIn member(std::string_view key) const;                  // fails "missing key 'key'" when absent
  std::optional<JsonIn> optional(std::string_view key) const;  // absent (or not an object): nothing
  std::vector<std::string> keys() const;

  // Arrays.
  std::vector<JsonIn> items() const;  // fails "expected an array"

  // Scalars. Numbers must be finite and fit in a float; integers must be whole and within [lo, hi].
  float number() const;
  uint32_t integer(uint32_t lo, uint32_t hi) const;
  bool boolean() const;
  std::string string() const;
  std::string nonempty_string() const;
  glm::vec2 vec2() const;
  glm::vec3 vec3() const;
  glm::vec4 vec4() const;
  glm::mat4 mat4() const;  // 16 numbers in glm::value_ptr (column-major) order
  std::vector<float> numbers() const;

  // Child cursors.
  JsonIn at(std::string_view key) const;
  JsonIn at(size_t index) const;

 private:
  std::vector<float> fixed_numbers(size_t n) const;

  const nlohmann::json* value_;
  std::string path_;
  const std::string* file_;
};

// Reads an optional member into `field` when present, leaving the default otherwise.
inline void read_opt(const JsonIn& j, std::string_view key, float& field) {
  if (auto m = j.optional(key)) field = m->number();
}
inline void read_opt(const JsonIn& j, std::string_view key, bool& field) {
  if (auto m = j.optional(key)) field = m->boolean();
}
inline void read_opt(const JsonIn& j, std::string_view key, std::string& field) {
  if (auto m = j.optional(key)) field = m->string();
}
inline void read_opt(const JsonIn& j, std::string_view key, glm::vec2& field) {
  if (auto m = j.optional(key)) field = m->vec2();
}
inline void read_opt(const JsonIn& j, std::string_view key, glm::vec3& field) {
  if (auto m = j.optional(key)) field = m->vec3();
}
inline void read_opt(const JsonIn& j, std::string_view key, uint32_t& field, uint32_t lo, uint32_t hi) {
  if (auto m = j.optional(key)) field = m->integer(lo, hi);
}

}  // namespace scenes
