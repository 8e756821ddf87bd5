// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_COMPACT_ID_LIST_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_COMPACT_ID_LIST_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The front edges leaving (or entering) one vertex: a list of 32-bit
// vertex ids in 16 bytes, two ids stored inline and more on the heap.
//
// The mesher keeps two of these for every active vertex; nearly every front
// vertex has one edge each way, and two for a moment while a triangle
// replaces one front edge by another. boost's small_vector takes 32 bytes
// for the same.
class Compact_id_list
{
public:
  typedef std::uint32_t Id;
  typedef const Id* const_iterator;
  static constexpr std::uint32_t inline_capacity = 2;

  Compact_id_list() { inline_[0] = inline_[1] = 0; }
  ~Compact_id_list() { release(); }

  Compact_id_list(const Compact_id_list& o) { assign(o); }
  Compact_id_list& operator=(const Compact_id_list& o)
  {
    if(this != &o) {
      release();
      assign(o);
    }
    return *this;
  }
  Compact_id_list(Compact_id_list&& o) noexcept { steal(o); }
  Compact_id_list& operator=(Compact_id_list&& o) noexcept
  {
    if(this != &o) {
      release();
      steal(o);
    }
    return *this;
  }

  std::uint32_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  const Id* begin() const { return on_heap() ? heap_ : inline_; }
  const Id* end() const { return begin() + size_; }

  void push_back(Id id)
  {
    if(size_ == capacity_) grow();
    data()[size_++] = id;
  }

  /// Removes one occurrence of `id` (which must be there); the order of
  /// the others may change.
  void erase_value(Id id)
  {
    Id* d = data();
    Id* it = std::find(d, d + size_, id);
    CGAL_precondition(it != d + size_);
    *it = d[size_ - 1];
    --size_;
    if(on_heap() && size_ <= inline_capacity) {
      // back to inline storage: the lists grow only for a moment
      Id kept[inline_capacity] = {0, 0};
      std::copy(d, d + size_, kept);
      const std::uint32_t n = size_;
      release();
      std::copy(kept, kept + inline_capacity, inline_);
      size_ = n;
    }
  }

private:
  bool on_heap() const { return capacity_ > inline_capacity; }
  Id* data() { return on_heap() ? heap_ : inline_; }

  void grow()
  {
    const std::uint32_t new_capacity = capacity_ * 2;
    Id* d = new Id[new_capacity];
    std::memcpy(d, data(), size_ * sizeof(Id));
    const std::uint32_t n = size_;
    release();
    heap_ = d;
    capacity_ = new_capacity;
    size_ = n;
  }

  // frees the heap block, if any; the list is then empty and inline
  void release()
  {
    if(on_heap()) delete[] heap_;
    capacity_ = inline_capacity;
    size_ = 0;
    inline_[0] = inline_[1] = 0;
  }

  void assign(const Compact_id_list& o)
  {
    size_ = 0;
    capacity_ = inline_capacity;
    inline_[0] = inline_[1] = 0;
    for(Id id : o) push_back(id);
  }

  void steal(Compact_id_list& o)
  {
    size_ = o.size_;
    capacity_ = o.capacity_;
    if(o.on_heap()) heap_ = o.heap_;
    else std::copy(o.inline_, o.inline_ + inline_capacity, inline_);
    o.size_ = 0;
    o.capacity_ = inline_capacity;
    o.inline_[0] = o.inline_[1] = 0;
  }

  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = inline_capacity; // up to inline_capacity: stored inline
  union {
    Id inline_[inline_capacity];
    Id* heap_;
  };
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_COMPACT_ID_LIST_H
