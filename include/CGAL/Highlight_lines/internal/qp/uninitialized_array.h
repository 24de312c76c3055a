// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_QP_UNINITIALIZED_ARRAY_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_QP_UNINITIALIZED_ARRAY_H

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// An array of trivially copyable values that resize() leaves uninitialised, for the factor of
// a sparse factorisation: every entry is written by the factorisation before it is read, and
// zero-filling a factor of hundreds of megabytes when it is allocated costs more than the
// symbolic analysis itself (the first touch of each page is a page fault). On Linux, large
// arrays ask for transparent huge pages, so that the first touch faults once per 2 MiB instead
// of once per 4 KiB (a no-op where the kernel does not offer them).
template <typename T>
class Uninitialized_array
{
  static_assert(std::is_trivially_copyable<T>::value, "values are copied bytewise");

public:
  Uninitialized_array() = default;
  Uninitialized_array(const Uninitialized_array& other) { *this = other; }
  Uninitialized_array(Uninitialized_array&& other) noexcept { *this = std::move(other); }
  Uninitialized_array& operator=(Uninitialized_array&& other) noexcept
  {
    if (this != &other) {
      values_ = std::move(other.values_);
      size_ = other.size_;
      capacity_ = other.capacity_;
      other.size_ = other.capacity_ = 0; // empty, not a size without storage
    }
    return *this;
  }
  Uninitialized_array& operator=(const Uninitialized_array& other)
  {
    if (this != &other) {
      resize(other.size_);
      std::copy(other.data(), other.data() + other.size_, data());
    }
    return *this;
  }

  // Keeps the storage when it is large enough; the values are unspecified afterwards.
  void resize(std::size_t size)
  {
    if (size > capacity_) {
      values_.reset();       // release first: the old and the new factor need not coexist
      size_ = capacity_ = 0; // empty if the allocation throws
      values_.reset(new T[size]);
      capacity_ = size;
      advise_huge_pages();
    }
    size_ = size;
  }

  std::size_t size() const { return size_; }
  T* data() { return values_.get(); }
  const T* data() const { return values_.get(); }

private:
  void advise_huge_pages()
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const std::uintptr_t huge_page = std::uintptr_t(1) << 21;
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(values_.get());
    const std::uintptr_t end = begin + capacity_ * sizeof(T);
    const std::uintptr_t first = (begin + huge_page - 1) & ~(huge_page - 1);
    const std::uintptr_t last = end & ~(huge_page - 1);
    if (last > first) // advice only: a kernel without huge pages ignores or refuses it
      (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
  }

  std::unique_ptr<T[]> values_;
  std::size_t size_ = 0, capacity_ = 0;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_QP_UNINITIALIZED_ARRAY_H
