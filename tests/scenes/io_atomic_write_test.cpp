// WriteBatch (scenes/io/atomic_write.h): staged files appear together at commit; a batch dropped without commit
// leaves neither its files nor the folders it made; a path staged twice keeps the later content.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "scenes/io/atomic_write.h"
#include "scenes/io/io_error.h"
#include "tests/support.h"

namespace {

namespace fs = std::filesystem;

void stage_text(scenes::io::WriteBatch& batch, const fs::path& path, const std::string& text) {
  batch.stage(path, [&](const fs::path& tmp) { std::ofstream(tmp) << text; });
}

size_t entries(const fs::path& dir) {
  return size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(IoAtomicWrite, ADroppedBatchRemovesItsFilesAndTheFoldersItMade) {
  const fs::path dir = testsupport::temp_dir("atomic_drop");
  fs::create_directory(dir / "kept");
  {
    scenes::io::WriteBatch batch;
    batch.create_directories(dir / "a" / "b");
    batch.create_directories(dir / "kept");  // there already: not the batch's to remove
    stage_text(batch, dir / "a" / "b" / "x.txt", "x");
    stage_text(batch, dir / "kept" / "y.txt", "y");
    stage_text(batch, dir / "z.txt", "z");
    EXPECT_TRUE(fs::is_directory(dir / "a" / "b"));
    EXPECT_FALSE(fs::exists(dir / "z.txt"));  // only its temporary so far
  }
  EXPECT_EQ(entries(dir), 1u);  // `kept` alone, and empty
  EXPECT_EQ(entries(dir / "kept"), 0u);
}

TEST(IoAtomicWrite, ACommittedBatchKeepsItsFoldersAndAPathStagedTwiceKeepsTheLastContent) {
  const fs::path dir = testsupport::temp_dir("atomic_commit");
  {
    scenes::io::WriteBatch batch;
    batch.create_directories(dir / "maps");
    stage_text(batch, dir / "maps" / "m.txt", "first");
    stage_text(batch, dir / "maps" / "m.txt", "second");
    batch.commit();
  }
  std::ifstream in(dir / "maps" / "m.txt");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "second");
  EXPECT_EQ(entries(dir / "maps"), 1u);  // the first staging's temporary is gone
}

TEST(IoAtomicWrite, AFolderInTheWayIsAnErrorNamingIt) {
  const fs::path dir = testsupport::temp_dir("atomic_in_way");
  std::ofstream(dir / "file") << "not a folder";
  scenes::io::WriteBatch batch;
  try {
    batch.create_directories(dir / "file");
    FAIL() << "no exception";
  } catch (const scenes::io::IoError& e) {
    EXPECT_EQ(e.file(), dir / "file");
  }
  EXPECT_THROW(batch.create_directories(dir / "file" / "below"), scenes::io::IoError);
}

}  // namespace
