// Temporary names and the rename of write_atomically.
#include "scenes/io/atomic_write.h"

#include <unistd.h>

#include <atomic>
#include <string>
#include <system_error>

#include "scenes/io/io_error.h"

namespace scenes::io {

namespace {

std::filesystem::path temporary_name(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  // Built by appending (GCC 12 warns falsely about `"." + std::string`).
  std::string name(1, '.');
  name.append(path.stem().string());
  name.append(".tmp-").append(std::to_string(::getpid())).append("-").append(std::to_string(counter.fetch_add(1)));
  name.append(path.extension().string());
  return path.parent_path() / name;
}

}  // namespace

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temporary)>& write) {
  namespace fs = std::filesystem;
  if (path.filename().empty()) throw IoError(path, "not a file name");
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw IoError(path, "directory " + dir.string() + " does not exist");
  const fs::path tmp = temporary_name(path);
  try {
    write(tmp);
  } catch (const IoError& e) {
    fs::remove(tmp, ec);
    throw IoError(path, e.reason());
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw IoError(path, "cannot rename the temporary file into place: " + ec.message());
  }
}

}  // namespace scenes::io
