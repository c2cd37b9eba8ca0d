// Writes that leave either the complete new file or nothing: the writer fills a temporary file in the same
// directory (same extension, so format-by-extension libraries still recognise it), which is then renamed over
// the destination. A failed write removes the temporary file and leaves any previous file untouched.
#pragma once
#include <filesystem>
#include <functional>
#include <vector>
#include "raster/simd/isa.h"

namespace scenes::io {
SHADOWLAB_ISA_BEGIN

// Calls write(temporary path), then renames the temporary file to `path`. Temporary files are named
// `.STEM.tmp-PID-N.EXT`; ones left beside `path` by a process that no longer runs (a killed run) are removed
// first. Throws IoError naming `path` when the
// directory does not exist or the rename fails; an exception from `write` is rethrown after cleanup (an
// IoError about the temporary name is rethrown as one about `path`).
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temporary)>& write);

// Several files written as one: each is written under its temporary name when it is staged, and commit()
// renames them all into place. A batch destroyed without commit() removes its temporaries and the folders it
// made, so a run that fails part way (a bad option found late, a full disk on the last file, the third scene of
// three) leaves none of its new files.
class WriteBatch {
 public:
  WriteBatch() = default;
  WriteBatch(const WriteBatch&) = delete;
  WriteBatch& operator=(const WriteBatch&) = delete;
  ~WriteBatch();
  // Calls write(temporary path) now; the file replaces `path` at commit(). Throws as write_atomically. A path
  // staged again replaces its earlier staging (the last content wins, as two writes in a row would leave it).
  void stage(const std::filesystem::path& path, const std::function<void(const std::filesystem::path&)>& write);
  // Makes `dir` and any missing parents now (files are staged into them); those this call made are removed again,
  // when empty, if the batch is destroyed without commit(). Throws IoError naming `dir`.
  void create_directories(const std::filesystem::path& dir);
  // Renames every staged file into place in staging order, after checking that no target is a directory (then
  // nothing moves). Throws IoError naming the file whose rename fails (the files before it are in place; its
  // temporary and the later ones are removed).
  void commit();

 private:
  struct Staged {
    std::filesystem::path temporary, path;
  };
  std::vector<Staged> staged_;
  std::vector<std::filesystem::path> created_;  // folders made, parents first
};

// Writes `bytes` to `path` (created or truncated), checking every write, flushing to the device (fsync) and
// checking the close: a full disk, a quota or an I/O error throws IoError naming `path` with the system's
// reason. For writers that encode to memory first (PNG), so no failure can go unseen.
void write_bytes(const std::filesystem::path& path, const void* bytes, size_t size);

SHADOWLAB_ISA_END
}  // namespace scenes::io
