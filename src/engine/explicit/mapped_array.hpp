#pragma once
// A growable array of trivially copyable values for the explicit search's per-state arrays (the
// states, their parents). On Linux it lives in its own mapping and grows by remapping it
// (mremap): growing copies nothing and never holds an old and a new block at once, and only the
// pages written are resident. A std::vector that doubles holds up to three times its contents at
// the moment it grows, and a search of 10^7 states is measured in bytes per state.

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace sfcv::engine {

template <class T>
class MappedArray {
  static_assert(std::is_trivially_copyable_v<T> && 4096 % sizeof(T) == 0);

 public:
  MappedArray() = default;
  MappedArray(const MappedArray&) = delete;
  MappedArray& operator=(const MappedArray&) = delete;
  MappedArray(MappedArray&& other) noexcept { swap(other); }
  MappedArray& operator=(MappedArray&& other) noexcept {
    MappedArray moved(std::move(other));
    swap(moved);
    return *this;
  }
  ~MappedArray() { release(data_, capacity_); }

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

  void push_back(const T& value) {
    if (size_ == capacity_) grow(size_ + 1);
    data_[size_++] = value;
  }
  /// Appends the `count` values at `first` (which must not lie in this array).
  void append(const T* first, std::size_t count) {
    if (size_ + count > capacity_) grow(size_ + count);
    std::memcpy(data_ + size_, first, count * sizeof(T));
    size_ += count;
  }
  /// Replaces the contents with `count` copies of `value`.
  void assign(std::size_t count, const T& value) {
    size_ = 0;
    if (count > capacity_) grow(count);
    std::fill(data_, data_ + count, value);
    size_ = count;
  }
  void reserve(std::size_t count) {
    if (count > capacity_) grow(count);
  }
  /// The bytes written so far, rounded up to whole pages: what the array holds resident.
  std::size_t resident_bytes() const { return (size_ * sizeof(T) + kPage - 1) / kPage * kPage; }

 private:
  static constexpr std::size_t kPage = 4096;

  void swap(MappedArray& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
  }

  /// Room for at least `needed` values, at least doubling the capacity.
  void grow(std::size_t needed) {
    const std::size_t want = std::max({needed, capacity_ * 2, kPage / sizeof(T)});
    if (want > (~std::size_t{0}) / sizeof(T) / 2) throw std::bad_alloc();
    const std::size_t bytes = (want * sizeof(T) + kPage - 1) / kPage * kPage;
    const std::size_t old_bytes = capacity_ * sizeof(T);
#if defined(__linux__)
    void* p = data_ == nullptr
                  ? mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0)
                  : mremap(data_, old_bytes, bytes, MREMAP_MAYMOVE);
    // No MADV_HUGEPAGE: with the kernel's default "defrag=madvise", a fault on a huge page
    // compacts memory first, and that system time outgrew the TLB misses it saves
    // (docs/benchmarks.md, round 2 session 19).
    if (p == MAP_FAILED) throw std::bad_alloc();
#else
    void* p = std::realloc(data_, bytes);
    if (p == nullptr) throw std::bad_alloc();
#endif
    data_ = static_cast<T*>(p);
    capacity_ = bytes / sizeof(T);
  }

  static void release(T* data, std::size_t capacity) noexcept {
    if (data == nullptr) return;
#if defined(__linux__)
    munmap(data, capacity * sizeof(T));
#else
    static_cast<void>(capacity);
    std::free(data);
#endif
  }

  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace sfcv::engine
