// Reusable per-draw memory: buffers that keep their capacity from one draw to the next, so a frame of many
// draws (or a benchmark loop) does not pay for fresh pages each time. Owned by a Renderer, never shared.
#pragma once
#include <cstddef>
#include <cstring>
#include <memory>
#include <type_traits>
#include "raster/simd/isa.h"

namespace raster {
SHADOWLAB_ISA_BEGIN

// An uninitialised, growable array of bytes viewed as trivially copyable T.
class ScratchBuffer {
 public:
  template <class T>
  T* get(size_t n) {
    static_assert(std::is_trivially_copyable_v<T>);
    reserve_bytes(n * sizeof(T), false);
    return reinterpret_cast<T*>(data_.get());
  }

  // push_back for a typed view of `count` elements already stored; returns the new count.
  template <class T>
  size_t append(size_t count, const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    reserve_bytes((count + 1) * sizeof(T), true);
    std::memcpy(data_.get() + count * sizeof(T), &value, sizeof(T));
    return count + 1;
  }

  template <class T>
  const T* view() const {
    return reinterpret_cast<const T*>(data_.get());
  }

 private:
  void reserve_bytes(size_t bytes, bool keep) {
    if (bytes <= capacity_) return;
    size_t cap = capacity_ ? capacity_ : 4096;
    while (cap < bytes) cap *= 2;
    // operator new[] of std::byte leaves the memory uninitialised; alignment of max_align_t (16) suffices.
    std::unique_ptr<std::byte[]> fresh(new std::byte[cap]);
    if (keep && capacity_) std::memcpy(fresh.get(), data_.get(), capacity_);
    data_ = std::move(fresh);
    capacity_ = cap;
  }

  std::unique_ptr<std::byte[]> data_;
  size_t capacity_ = 0;
};

SHADOWLAB_ISA_END
}  // namespace raster
