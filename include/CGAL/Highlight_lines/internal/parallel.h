// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_PARALLEL_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_PARALLEL_H

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// CGAL's concurrency tag convention: Parallel_tag derives from Sequential_tag, and
// Parallel_if_available_tag is Parallel_tag exactly when CGAL_LINKED_WITH_TBB is defined.
template <typename ConcurrencyTag>
struct Is_parallel
    : std::integral_constant<bool, std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value>
{
  static_assert(std::is_convertible<ConcurrencyTag, CGAL::Sequential_tag>::value,
                "the concurrency tag must be CGAL::Sequential_tag, CGAL::Parallel_tag or "
                "CGAL::Parallel_if_available_tag");
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_convertible<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
};

// Splits [0, n) into chunks whose bounds depend on n and the grain only (never on the number
// of threads or on scheduling), so that results gathered per chunk and merged in chunk order
// are the same whichever chunks ran concurrently.
struct Chunks
{
  std::size_t n = 0, grain = 1;

  Chunks(std::size_t size, std::size_t grain_size)
      : n(size), grain((std::max)(std::size_t(1), grain_size))
  {
  }
  std::size_t size() const { return (n + grain - 1) / grain; }
  std::size_t begin(std::size_t c) const { return c * grain; }
  std::size_t end(std::size_t c) const { return (std::min)(n, (c + 1) * grain); }
};

// Calls f(c, begin, end) for every chunk c of `chunks`: concurrently with a parallel tag,
// in order otherwise. Exceptions thrown by f propagate (TBB rethrows one of them).
template <typename ConcurrencyTag, typename F>
void for_each_chunk(const Chunks& chunks, F&& f)
{
  const std::size_t count = chunks.size();
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr (Is_parallel<ConcurrencyTag>::value) {
    if (count > 1) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, count, 1),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t c = r.begin(); c != r.end(); ++c)
                            f(c, chunks.begin(c), chunks.end(c));
                        });
      return;
    }
  }
#else
  (void)Is_parallel<ConcurrencyTag>::value; // the static assertions
#endif
  for (std::size_t c = 0; c < count; ++c)
    f(c, chunks.begin(c), chunks.end(c));
}

// The chunking of a pass over n elements: one chunk when sequential (no merging cost), chunks
// of `grain` elements when parallel.
template <typename ConcurrencyTag>
Chunks chunks_for(std::size_t n, std::size_t grain)
{
  return Is_parallel<ConcurrencyTag>::value ? Chunks(n, grain) : Chunks(n, (std::max)(n, grain));
}

// Appends the per-chunk vectors to `out`, in chunk order.
template <typename T>
void concatenate(std::vector<std::vector<T>>& parts, std::vector<T>& out)
{
  std::size_t total = out.size();
  for (const auto& part : parts)
    total += part.size();
  out.reserve(total);
  for (const auto& part : parts)
    out.insert(out.end(), part.begin(), part.end());
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_PARALLEL_H
