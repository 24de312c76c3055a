// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_QP_BUCKET_SORT_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_QP_BUCKET_SORT_H

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// A stable counting sort of items into the buckets 0 to number_of_buckets - 1, the way every
// compressed-column structure of the solver is built: afterwards the items of bucket b are
// items[start[b]] to items[start[b + 1] - 1], in the order in which they were visited.
// for_each_item(emit) must call emit(bucket, item) once per item, and the same way on both of
// its two calls (the first counts, the second places). `items` keeps its capacity.
template <class Item, class ForEachItem>
void bucket_sort(int number_of_buckets, const ForEachItem& for_each_item, std::vector<int>& start,
                 std::vector<Item>& items)
{
  const std::size_t buckets = static_cast<std::size_t>(number_of_buckets);
  start.assign(buckets + 1, 0);
  for_each_item(
      [&start](int bucket, const Item&) { ++start[static_cast<std::size_t>(bucket) + 1]; });
  for (std::size_t b = 0; b < buckets; ++b)
    start[b + 1] += start[b];
  items.resize(static_cast<std::size_t>(start[buckets]));
  std::vector<int> next(start.begin(), start.end() - 1);
  for_each_item([&](int bucket, const Item& item) {
    items[static_cast<std::size_t>(next[static_cast<std::size_t>(bucket)]++)] = item;
  });
}

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_QP_BUCKET_SORT_H
