// The one exception the scenes module throws for bad input: what() reads `WHERE: what is wrong`, where WHERE is
// the file (or built-in scene name) followed by the key path inside it when there is one, e.g.
// `scene.json: objects[2].transform.scale: expected an array of 3 numbers`.
#pragma once
#include <stdexcept>
#include <string>

namespace scenes {

class SceneError : public std::runtime_error {
 public:
  // `file` names the input (a path as given, or a built-in scene's name); `key_path` may be empty.
  SceneError(std::string file, std::string key_path, std::string message)
      : std::runtime_error(compose(file, key_path, message)),
        file_(std::move(file)),
        key_path_(std::move(key_path)),
        message_(std::move(message)) {}

  const std::string& file() const { return file_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& message() const { return message_; }

 private:
  static std::string compose(const std::string& file, const std::string& key_path, const std::string& message) {
    std::string where = file;
    if (!key_path.empty()) where += (where.empty() ? "" : ": ") + key_path;
    return where.empty() ? message : where + ": " + message;
  }

  std::string file_, key_path_, message_;
};

}  // namespace scenes
