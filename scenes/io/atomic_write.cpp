// Temporary names and the rename of write_atomically.
#include "scenes/io/atomic_write.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "scenes/io/io_error.h"
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

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

// Removes `.STEM.tmp-PID-N.EXT` files beside `path` whose process no longer runs.
void remove_stale_temporaries(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::string prefix(1, '.');  // built by appending, as temporary_name
  prefix.append(path.stem().string()).append(".tmp-");
  const std::string ext = path.extension().string();
  std::error_code ec;
  fs::directory_iterator it(path.parent_path().empty() ? fs::path(".") : path.parent_path(), ec);
  if (ec) return;
  for (const fs::directory_entry& e : it) {
    const std::string name = e.path().filename().string();
    if (name.size() <= prefix.size() + ext.size() || name.rfind(prefix, 0) != 0 ||
        name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
      continue;
    const std::string mid = name.substr(prefix.size(), name.size() - prefix.size() - ext.size());  // PID-N
    const size_t dash = mid.find('-');
    if (dash == std::string::npos || dash == 0 || mid.find_first_not_of("0123456789-") != std::string::npos) continue;
    const long pid = std::strtol(mid.substr(0, dash).c_str(), nullptr, 10);
    if (pid <= 0 || pid == long(::getpid())) continue;
    if (::kill(pid_t(pid), 0) != 0 && errno == ESRCH) fs::remove(e.path(), ec);
  }
}

}  // namespace

void write_bytes(const std::filesystem::path& path, const void* bytes, size_t size) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw IoError(path, std::string("cannot create file (") + std::strerror(errno) + ")");
  const auto* p = static_cast<const unsigned char*>(bytes);
  size_t left = size;
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      throw IoError(path, std::string("write failed (") + std::strerror(err) + ")");
    }
    p += n;
    left -= size_t(n);
  }
  // EINVAL: the file does not support syncing (a device such as /dev/null); nothing is lost by skipping it.
  if (::fsync(fd) != 0 && errno != EINVAL) {
    const int err = errno;
    ::close(fd);
    throw IoError(path, std::string("flush to disk failed (") + std::strerror(err) + ")");
  }
  if (::close(fd) != 0) throw IoError(path, std::string("close failed (") + std::strerror(errno) + ")");
}

void WriteBatch::stage(const std::filesystem::path& path,
                       const std::function<void(const std::filesystem::path& temporary)>& write) {
  namespace fs = std::filesystem;
  if (path.filename().empty()) throw IoError(path, "not a file name");
  const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw IoError(path, "directory " + dir.string() + " does not exist");
  remove_stale_temporaries(path);
  for (size_t i = 0; i < staged_.size(); ++i)
    if (staged_[i].path == path) {  // staged again: the earlier temporary goes
      fs::remove(staged_[i].temporary, ec);
      staged_.erase(staged_.begin() + std::ptrdiff_t(i));
      break;
    }
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
  staged_.push_back({tmp, path});
}

void WriteBatch::commit() {
  namespace fs = std::filesystem;
  // What would make a rename fail is looked for before any file moves: each temporary sits in its target's
  // directory already, so what is left is a target that is a directory.
  for (const Staged& s : staged_) {
    std::error_code ec;
    if (fs::is_directory(s.path, ec)) throw IoError(s.path, "is a directory");
  }
  for (size_t i = 0; i < staged_.size(); ++i) {
    std::error_code ec;
    fs::rename(staged_[i].temporary, staged_[i].path, ec);
    if (ec) {
      const Staged failed = staged_[i];
      staged_.erase(staged_.begin(), staged_.begin() + std::ptrdiff_t(i));  // the destructor removes the rest
      throw IoError(failed.path, "cannot rename the temporary file into place: " + ec.message());
    }
  }
  staged_.clear();
  created_.clear();
}

void WriteBatch::create_directories(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  if (dir.empty()) return;
  std::vector<fs::path> missing;  // innermost first
  std::error_code ec;
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    missing.push_back(p);
    if (p == p.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && ec)
      throw IoError(dir, "cannot create the folder " + it->string() + " (" + ec.message() + ")");
    created_.push_back(*it);
  }
  if (!fs::is_directory(dir, ec)) throw IoError(dir, "exists and is not a folder");
}

WriteBatch::~WriteBatch() {
  std::error_code ec;
  for (const Staged& s : staged_) std::filesystem::remove(s.temporary, ec);
  // Innermost first; remove() leaves a folder that is not empty (something else was put there).
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) std::filesystem::remove(*it, ec);
}

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temporary)>& write) {
  WriteBatch batch;
  batch.stage(path, write);
  batch.commit();
}

SHADOWLAB_ISA_END
}  // namespace scenes::io
