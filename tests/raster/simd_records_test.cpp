// simd::load_records6 (raster/simd/vec_avx2.h; vec_scalar.h's where the scalar set is the one tests are built
// for, see CMakeLists.txt): eight six-field records picked by index, split
// into lanes, must give what a gather of each field gives, for any indices (repeated, first, last, in any
// order), and must read nothing outside the records it picks: the last record of the array ends where an
// unreadable page begins, so a load one field too long faults.
#include <gtest/gtest.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstring>
#include <random>
#include <stdexcept>
#include <vector>

#include "raster/primitive.h"
#include "raster/simd/vec.h"

using namespace raster;

namespace {

// `count` WindowVertex records whose last one ends at an unreadable page.
class GuardedRecords {
 public:
  explicit GuardedRecords(size_t count) : count_(count) {
    const size_t page = size_t(sysconf(_SC_PAGESIZE)), bytes = count * sizeof(WindowVertex);
    size_ = (bytes + page - 1) / page * page + page;
    void* p = mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::runtime_error("mmap failed");
    base_ = static_cast<std::byte*>(p);
    if (mprotect(base_ + size_ - page, page, PROT_NONE) != 0) {
      munmap(base_, size_);
      throw std::runtime_error("mprotect failed");
    }
    records_ = reinterpret_cast<WindowVertex*>(base_ + size_ - page - bytes);
  }
  ~GuardedRecords() { munmap(base_, size_); }
  GuardedRecords(const GuardedRecords&) = delete;
  GuardedRecords& operator=(const GuardedRecords&) = delete;
  WindowVertex* data() { return records_; }
  size_t size() const { return count_; }

 private:
  size_t count_, size_;
  std::byte* base_;
  WindowVertex* records_;
};

}  // namespace

TEST(SimdRecords, LoadRecords6EqualsAGatherOfEachField) {
  std::mt19937 rng(61);
  for (const size_t count : {size_t(1), size_t(2), size_t(7), size_t(170), size_t(4096)}) {
    GuardedRecords r(count);
    std::uniform_real_distribution<float> f(-1e6f, 1e6f);
    std::uniform_int_distribution<int32_t> i(INT32_MIN, INT32_MAX);
    for (size_t k = 0; k < count; ++k) r.data()[k] = {f(rng), f(rng), f(rng), f(rng), i(rng), i(rng)};
    std::uniform_int_distribution<int32_t> pick(0, int32_t(count) - 1);
    const float* base = reinterpret_cast<const float*>(r.data());
    const int32_t* ibase = reinterpret_cast<const int32_t*>(r.data());
    for (int trial = 0; trial < 200; ++trial) {
      alignas(32) int32_t idx[8];
      for (int l = 0; l < 8; ++l) idx[l] = pick(rng);
      if (trial % 4 == 0) idx[trial / 4 % 8] = int32_t(count) - 1;  // the record at the guard page, in every lane
      if (trial % 4 == 1) idx[trial / 4 % 8] = 0;
      simd::VecF32 x, y, z;
      simd::VecI32 sx, sy;
      simd::load_records6(base, idx, x, y, z, sx, sy);
      const simd::VecI32 six = simd::VecI32::load(idx) * simd::VecI32::splat(6);
      alignas(32) float got[3][8], want[3][8];
      alignas(32) uint32_t got_i[2][8], want_i[2][8];
      x.store(got[0]), y.store(got[1]), z.store(got[2]);
      for (int k = 0; k < 3; ++k) simd::gather(base + k, six).store(want[k]);
      sx.store_u32(got_i[0]), sy.store_u32(got_i[1]);
      simd::gather(ibase + 4, six).store_u32(want_i[0]), simd::gather(ibase + 5, six).store_u32(want_i[1]);
      for (int l = 0; l < 8; ++l) {
        const WindowVertex& v = r.data()[idx[l]];
        SCOPED_TRACE(testing::Message() << count << " records, trial " << trial << ", lane " << l);
        EXPECT_EQ(std::memcmp(&got[0][l], &v.x, 4), 0);
        EXPECT_EQ(std::memcmp(&got[1][l], &v.y, 4), 0);
        EXPECT_EQ(std::memcmp(&got[2][l], &v.z, 4), 0);
        EXPECT_EQ(int32_t(got_i[0][l]), v.sx);
        EXPECT_EQ(int32_t(got_i[1][l]), v.sy);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(std::memcmp(&got[k][l], &want[k][l], 4), 0);
        EXPECT_EQ(got_i[0][l], want_i[0][l]);
        EXPECT_EQ(got_i[1][l], want_i[1][l]);
      }
    }
  }
}
