// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FLAT_HASH_MAP_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FLAT_HASH_MAP_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// An open-addressing hash map (linear probing, backward-shift deletion, no
// tombstones) for the mesher's front: keys are 64-bit integers or
// pointers, one key value is reserved as "empty".
//
// Why not std::unordered_map: it allocates a node per entry, and on a
// 1M-triangle mesh its lookups of front edges took 11% of the meshing time,
// nearly all of it cache misses on the nodes; here a lookup reads one or
// two adjacent slots of a flat array. Boost 1.74 (Debian 12) has no flat
// map yet.
template <class Key, class Value>
class Flat_hash_map
{
public:
  typedef std::pair<Key, Value> Slot;

  explicit Flat_hash_map(Key empty_key = Key()) : empty_(empty_key) { clear(); }

  void clear()
  {
    slots_.assign(16, Slot(empty_, Value()));
    mask_ = slots_.size() - 1;
    shift_ = 60;
    size_ = 0;
  }

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }

  Value* find(const Key& k)
  {
    CGAL_precondition(k != empty_);
    for(std::size_t i = home(k);; i = (i + 1) & mask_) {
      if(slots_[i].first == k) return &slots_[i].second;
      if(slots_[i].first == empty_) return nullptr;
    }
  }

  const Value* find(const Key& k) const { return const_cast<Flat_hash_map*>(this)->find(k); }

  bool contains(const Key& k) const { return find(k) != nullptr; }

  /// Inserts `k` (which must be absent) and returns its value.
  Value& insert(const Key& k, const Value& v)
  {
    CGAL_precondition(k != empty_ && !contains(k));
    // linear probing stays short up to a load of 3/4 with this hash
    if(4 * (size_ + 1) > 3 * slots_.size()) grow();
    ++size_;
    return place(k, v);
  }

  /// Removes `k`; returns whether it was there.
  bool erase(const Key& k)
  {
    std::size_t i = home(k);
    for(;; i = (i + 1) & mask_) {
      if(slots_[i].first == empty_) return false;
      if(slots_[i].first == k) break;
    }
    // backward shift: move later entries of the probe run into the hole
    // when their home slot allows it, so that no tombstone is needed
    std::size_t hole = i;
    for(std::size_t j = (i + 1) & mask_; slots_[j].first != empty_; j = (j + 1) & mask_) {
      const std::size_t h = home(slots_[j].first);
      // is h cyclically outside (hole, j]? then the entry may fill the hole
      const bool movable = (hole <= j) ? (h <= hole || h > j) : (h <= hole && h > j);
      if(movable) {
        slots_[hole] = std::move(slots_[j]);
        hole = j;
      }
    }
    slots_[hole] = Slot(empty_, Value());
    --size_;
    return true;
  }

  /// Gives the table room for `n` entries without growing.
  void reserve(std::size_t n)
  {
    std::size_t capacity = slots_.size();
    while(4 * n > 3 * capacity) capacity *= 2;
    if(capacity != slots_.size()) rehash(capacity);
  }

  /// Halves the table until it is between an eighth and a quarter full,
  /// once it is less than an eighth full: the table follows the front as it shrinks instead
  /// of keeping the size of the largest front. Returns whether it shrank.
  bool shrink_if_sparse()
  {
    if(slots_.size() <= 16 || 8 * size_ >= slots_.size()) return false;
    std::size_t capacity = slots_.size();
    while(capacity > 16 && 4 * size_ < capacity / 2) capacity /= 2;
    rehash(capacity);
    return true;
  }

  /// Calls `f(key, value)` for every entry.
  template <class Function>
  void for_each(Function f) const
  {
    for(const Slot& s : slots_)
      if(s.first != empty_) f(s.first, s.second);
  }

  /// Memory held by the table, in bytes.
  std::size_t memory() const { return slots_.capacity() * sizeof(Slot); }

private:
  static std::uint64_t bits(std::uint64_t k) { return k; }
  template <class T>
  static std::uint64_t bits(T* p) { return static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(p)); }

  std::size_t home(const Key& k) const
  {
    // Fibonacci hashing: the multiplication spreads the key's low and high
    // bits (vertex pairs, aligned pointers) over the top bits
    return static_cast<std::size_t>((bits(k) * 0x9E3779B97F4A7C15ull) >> shift_) & mask_;
  }

  Value& place(const Key& k, const Value& v)
  {
    std::size_t i = home(k);
    while(slots_[i].first != empty_) i = (i + 1) & mask_;
    slots_[i] = Slot(k, v);
    return slots_[i].second;
  }

  void grow() { rehash(2 * slots_.size()); }

  // capacity: a power of two, at least 16, with room for the entries
  void rehash(std::size_t capacity)
  {
    CGAL_precondition(capacity >= 16 && (capacity & (capacity - 1)) == 0 && size_ < capacity);
    std::vector<Slot> old(capacity, Slot(empty_, Value()));
    old.swap(slots_);
    mask_ = capacity - 1;
    shift_ = 64;
    for(std::size_t c = capacity; c > 1; c /= 2) --shift_;
    for(Slot& s : old)
      if(s.first != empty_) place(s.first, s.second);
  }

  std::vector<Slot> slots_;
  std::size_t mask_ = 15;
  int shift_ = 60; // 64 - log2(capacity)
  std::size_t size_ = 0;
  Key empty_;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FLAT_HASH_MAP_H
