// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_TREE_STORAGE_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_TREE_STORAGE_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Binary_io.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// What the point quadtree and the lifted circle octree share: the entries
// of their leaves, the blocks of sibling nodes in one vector, and the
// checks of a loaded tree's layout.

// An item as stored in a leaf: a point and its reach (the quadtree), or a
// circle's centre and radius (the octree). `extent` is how far the item
// reaches from (x, y).
struct Tree_entry
{
  double x, y;
  double extent;
  std::size_t id;
};

// field by field: the padding of a struct would make the bytes (and the
// checksum) indeterminate
inline void save_tree_entries(Binary_writer& w, const std::vector<Tree_entry>& v)
{
  w.write<std::uint64_t>(v.size());
  for(const Tree_entry& e : v) {
    w.write(e.x);
    w.write(e.y);
    w.write(e.extent);
    w.write(e.id);
  }
}

// Reads what save_tree_entries() wrote, at most `max_entries` of them;
// `corrupt(what)` does not return.
template <class Corrupt>
void load_tree_entries(Binary_reader& r, std::vector<Tree_entry>& v, std::uint64_t max_entries,
                       const char* too_many, Corrupt corrupt)
{
  const std::uint64_t n = r.read<std::uint64_t>();
  if(n > max_entries) corrupt(too_many);
  v.clear();
  for(std::uint64_t i = 0; i < n; ++i) {
    Tree_entry e;
    e.x = r.read<double>();
    e.y = r.read<double>();
    e.extent = r.read<double>();
    e.id = r.read<std::size_t>();
    v.push_back(e);
  }
}

// The nodes of a tree live in one vector, siblings in a block of 4 (or 8):
// a split takes a block, and a merge of empty siblings gives it back for
// the next split, which keeps the tree's size proportional to the items it
// holds (the front), not to the region they swept. `Kinds` is 1 for blocks
// of 4 only, 2 for blocks of 4 and of 8.
template <class Index, std::size_t Kinds>
class Node_blocks
{
public:
  // The first node of a free block of `size` nodes, appended to `nodes` if
  // none is free.
  template <class Nodes>
  Index take(Nodes& nodes, int size)
  {
    std::vector<Index>& free = free_[kind(size)];
    if(!free.empty()) {
      const Index first = free.back();
      free.pop_back();
      return first;
    }
    const Index first = static_cast<Index>(nodes.size());
    nodes.resize(nodes.size() + size);
    return first;
  }

  void give_back(Index first, int size) { free_[kind(size)].push_back(first); }

  void clear()
  {
    for(std::vector<Index>& f : free_) f.clear();
  }

  // clear() keeps the capacity
  void release_memory()
  {
    for(std::vector<Index>& f : free_) std::vector<Index>().swap(f);
  }

  void save(Binary_writer& w) const
  {
    for(const std::vector<Index>& f : free_) w.write_vector(f);
  }

  void load(Binary_reader& r, std::uint64_t number_of_nodes)
  {
    for(std::size_t k = 0; k < Kinds; ++k) r.read_vector(free_[k], number_of_nodes / block_size(k));
  }

  // Marks the nodes of the free blocks in `seen`; a block out of range, a
  // node already seen (in use, or in another block) or a node that
  // `is_in_use` says holds something is corrupt.
  template <class Is_in_use, class Corrupt>
  void mark_free_nodes(std::vector<char>& seen, Is_in_use is_in_use, Corrupt corrupt) const
  {
    const std::size_t n = seen.size();
    for(std::size_t k = 0; k < Kinds; ++k) {
      const int size = block_size(k);
      for(Index first : free_[k]) {
        if(first < 1 || static_cast<std::size_t>(first) + size > n) corrupt("free block out of range");
        for(Index c = first; c < first + size; ++c) {
          if(seen[c]) corrupt("free node in use or in two free blocks");
          seen[c] = 1;
          if(is_in_use(c)) corrupt("free node in use");
        }
      }
    }
  }

private:
  static std::size_t kind(int size) { return size == 8 ? 1 : 0; }
  static int block_size(std::size_t k) { return k == 0 ? 4 : 8; }

  std::array<std::vector<Index>, Kinds> free_; // first nodes of the free blocks of 4 (and 8) siblings
};

// Checks that the nodes reachable from the root form a tree (each node
// reached once, with its parent and depth; inner nodes hold no entries),
// that every other node is in exactly one free block, and that no node is
// neither. `children(node)` is the number of children of an inner node,
// whose indices the caller has checked to be in range.
template <class Nodes, class Index, std::size_t Kinds, class Children, class Corrupt>
void check_tree_layout(const Nodes& nodes, const Node_blocks<Index, Kinds>& blocks, Children children,
                       Corrupt corrupt)
{
  const std::size_t n = nodes.size();
  if(nodes[0].parent != -1 || nodes[0].depth != 0) corrupt("root with a parent");
  std::vector<char> seen(n, 0);
  seen[0] = 1;
  std::vector<Index> stack(1, 0);
  while(!stack.empty()) {
    const Index i = stack.back();
    stack.pop_back();
    const auto& node = nodes[i];
    if(node.first_child == -1) continue;
    if(!node.entries.empty()) corrupt("inner node with entries");
    for(Index c = node.first_child; c < node.first_child + children(node); ++c) {
      if(seen[c]) corrupt("node reached twice");
      seen[c] = 1;
      if(nodes[c].parent != i || nodes[c].depth != node.depth + 1) corrupt("wrong parent or depth");
      stack.push_back(c);
    }
  }
  blocks.mark_free_nodes(seen, [&](Index c) { return nodes[c].first_child != -1 || !nodes[c].entries.empty(); },
                         corrupt);
  if(std::find(seen.begin(), seen.end(), 0) != seen.end()) corrupt("node neither in the tree nor free");
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_TREE_STORAGE_H
