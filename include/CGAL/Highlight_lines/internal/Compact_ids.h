// Copyright (c) 2026 The Highlight_lines package authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_HIGHLIGHT_LINES_INTERNAL_COMPACT_IDS_H
#define CGAL_HIGHLIGHT_LINES_INTERNAL_COMPACT_IDS_H

#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Highlight_lines {
namespace internal {

// Maps a sparse or dense element index (as given by an index property map) to a compact id.
// Dense storage when the whole mesh is processed; otherwise an open-addressing hash table
// (linear probing, at most half full), which a fairing builds once per call for a few
// thousand elements: a node-based std::unordered_map cost an allocation per element.
class Compact_ids
{
public:
  static constexpr int none = -1;

  Compact_ids() = default;
  Compact_ids(bool dense, std::size_t bound) : dense_(dense)
  {
    if (dense_)
      table_.assign(bound, none);
  }

  int find(std::size_t key) const
  {
    if (dense_)
      return key < table_.size() ? table_[key] : none;
    if (slots_.empty())
      return none;
    for (std::size_t s = slot_of(key);; s = (s + 1) & mask_) {
      if (slots_[s].id == none)
        return none;
      if (slots_[s].key == key)
        return slots_[s].id;
    }
  }

  // Makes room for `n` keys at once (hashed storage): a fairing's local mesh knows about how
  // many it will insert, and growing from 64 slots rehashed them all about twice.
  void reserve(std::size_t n)
  {
    if (dense_ || 2 * n <= slots_.size())
      return;
    std::size_t capacity = 64;
    while (capacity < 2 * n)
      capacity *= 2;
    rehash(capacity);
  }

  // Returns the id of `key`, assigning `next` if it has none yet.
  int insert(std::size_t key, int next, bool& inserted)
  {
    if (dense_) {
      if (key >= table_.size())
        table_.resize(key + 1, none);
      inserted = table_[key] == none;
      if (inserted)
        table_[key] = next;
      return table_[key];
    }
    if (2 * (size_ + 1) > slots_.size())
      grow();
    for (std::size_t s = slot_of(key);; s = (s + 1) & mask_) {
      if (slots_[s].id == none) {
        slots_[s] = {key, next};
        ++size_;
        inserted = true;
        return next;
      }
      if (slots_[s].key == key) {
        inserted = false;
        return slots_[s].id;
      }
    }
  }

private:
  struct Slot
  {
    std::size_t key;
    int id;
  };

  // Fibonacci hashing: indices of neighbouring elements are often consecutive.
  std::size_t slot_of(std::size_t key) const
  {
    return std::size_t((std::uint64_t(key) * 0x9E3779B97F4A7C15ull) >> shift_);
  }

  void grow() { rehash(slots_.empty() ? 64 : 2 * slots_.size()); }

  void rehash(std::size_t capacity)
  {
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.assign(capacity, Slot{0, none});
    mask_ = capacity - 1;
    shift_ = 64;
    for (std::size_t c = capacity; c > 1; c >>= 1)
      --shift_;
    size_ = 0;
    for (const Slot& slot : old)
      if (slot.id != none) {
        bool inserted = false;
        insert(slot.key, slot.id, inserted);
      }
  }

  bool dense_ = false;
  std::vector<int> table_;
  std::vector<Slot> slots_;
  std::size_t mask_ = 0, size_ = 0;
  int shift_ = 64;
};

} // namespace internal
} // namespace Highlight_lines
} // namespace CGAL

#endif // CGAL_HIGHLIGHT_LINES_INTERNAL_COMPACT_IDS_H
