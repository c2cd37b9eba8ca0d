// Writes that leave either the complete new file or nothing: the writer fills a temporary file in the same
// directory (same extension, so format-by-extension libraries still recognise it), which is then renamed over
// the destination. A failed write removes the temporary file and leaves any previous file untouched.
#pragma once
#include <filesystem>
#include <functional>

namespace scenes::io {

// Calls write(temporary path), then renames the temporary file to `path`. Throws IoError naming `path` when the
// directory does not exist or the rename fails; an exception from `write` is rethrown after cleanup (an
// IoError about the temporary name is rethrown as one about `path`).
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(const std::filesystem::path& temporary)>& write);

}  // namespace scenes::io
