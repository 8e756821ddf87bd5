// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DYNAMIC_POINT_QUADTREE_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DYNAMIC_POINT_QUADTREE_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/assertions.h>
#include <CGAL/Advancing_front_mesh_2/internal/Binary_io.h>
#include <CGAL/Advancing_front_mesh_2/internal/Tree_storage.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The close-point search of step 4 (the paper's quadtree of front points):
// a bucketed point-region quadtree over the active vertices, with O(depth)
// insertion and O(1) removal, queried by disk.
//
// It replaces a CGAL::Kd_tree index because the front changes at every
// step and Kd_tree is static: an insertion invalidates it. Kept beside a
// buffer of recent insertions and rebuilt when the buffer grew past
// 2 sqrt(n), the Kd_tree index took 13.5% of the meshing time of a
// 200k-triangle square with a hole (perf, Release), 2.7 times this
// quadtree's share; see the user manual's benchmark section.
//
// Points are identified by dense integer ids (the mesher's vertex ids).
// Coordinates are doubles and the query disk is padded: callers decide
// with exact predicates.
class Dynamic_point_quadtree
{
  static constexpr std::int32_t no_child = -1;
  static constexpr std::int32_t absent = -1;
  static constexpr std::int32_t overflow_node = -2;

  // a point with its reach (see set_reach()) as `extent`
  typedef Tree_entry Entry;

  struct Node
  {
    std::array<double, 4> box; // x0, y0, x1, y1
    double max_reach = 0;      // bound on the reaches below (not lowered by removals)
    std::int32_t first_child = no_child;
    std::int32_t parent = -1;
    std::int32_t depth = 0;
    std::vector<Entry> entries;
  };

  struct Place
  {
    std::int32_t node = absent; // leaf holding the point, overflow_node, or absent
    std::uint32_t position = 0; // index in that leaf's entries
  };

public:
  Dynamic_point_quadtree() { reset(0, 0, 1, 1); }

  /// Empties the tree and sets its root box; points outside it are kept in
  /// a list that every query scans.
  void reset(double xmin, double ymin, double xmax, double ymax, std::size_t bucket_size = 8,
             int max_depth = 24)
  {
    nodes_.clear();
    blocks_.clear();
    places_.clear();
    overflow_.clear();
    size_ = 0;
    bucket_size_ = bucket_size;
    max_depth_ = max_depth;
    Node root;
    root.box = {{xmin, ymin, xmax, ymax}};
    nodes_.push_back(root);
    const double magnitude = (std::max)({std::abs(xmin), std::abs(ymin), std::abs(xmax), std::abs(ymax), 1e-300});
    abs_pad_ = 1e-12 * magnitude;
  }

  void clear() { reset(0, 0, 1, 1); }

  bool contains(std::size_t id) const { return id < places_.size() && places_[id].node != absent; }

  std::size_t size() const { return size_; }

  void insert(std::size_t id, double x, double y)
  {
    if(id >= places_.size()) places_.resize(id + 1);
    if(places_[id].node != absent) return;
    ++size_;
    const Entry e{x, y, 0., id};
    const std::array<double, 4>& root = nodes_[0].box;
    if(!(x >= root[0] && x <= root[2] && y >= root[1] && y <= root[3])) { // also catches NaN
      places_[id] = Place{overflow_node, std::uint32_t(overflow_.size())};
      overflow_.push_back(e);
      return;
    }
    std::int32_t n = 0;
    while(nodes_[n].first_child != no_child) n = nodes_[n].first_child + child_index(nodes_[n].box, x, y);
    places_[id] = Place{n, std::uint32_t(nodes_[n].entries.size())};
    nodes_[n].entries.push_back(e);
    if(nodes_[n].entries.size() > bucket_size_ && nodes_[n].depth < max_depth_) split(n);
  }

  void remove(std::size_t id)
  {
    if(!contains(id)) return;
    Place& pl = places_[id];
    std::vector<Entry>& v = (pl.node == overflow_node) ? overflow_ : nodes_[pl.node].entries;
    // swap-and-pop keeps removal O(1); the moved point's position is patched
    v[pl.position] = v.back();
    places_[v[pl.position].id].position = pl.position;
    v.pop_back();
    if(v.empty() && pl.node != overflow_node) {
      // the front has left this leaf: merge empty siblings into their
      // parent, whose block of four nodes the next split reuses; the tree
      // stays proportional to the front
      merge_empty_children(nodes_[pl.node].parent);
    }
    pl.node = absent;
    --size_;
  }

  /// Renames the points (point `id` becomes `new_id[id]`, ids absent from
  /// the tree are not read) and rebuilds the tree for the points it holds,
  /// in memory proportional to their number: the node and id arrays
  /// otherwise keep the size of the largest front.
  template <class Id_map>
  void renumber(const Id_map& new_id)
  {
    std::vector<Entry> all(overflow_);
    all.reserve(size_);
    for(const Node& n : nodes_)
      if(n.first_child == no_child) all.insert(all.end(), n.entries.begin(), n.entries.end());
    const std::array<double, 4> box = nodes_[0].box;
    // clear() would keep the capacity
    std::vector<Node>().swap(nodes_);
    blocks_.release_memory();
    std::vector<Place>().swap(places_);
    std::vector<Entry>().swap(overflow_);
    std::vector<std::int32_t>().swap(stack_);
    reset(box[0], box[1], box[2], box[3], bucket_size_, max_depth_);
    for(const Entry& e : all) {
      const std::size_t id = new_id[e.id];
      insert(id, e.x, e.y);
      if(e.extent != 0) set_reach(id, e.extent);
    }
  }

  /// Sets the reach of point `id` (a non-negative length; NaN counts as
  /// infinite): query_with_reach() reports the point for every disk that
  /// comes within its reach. The mesher sets a front vertex's reach to the
  /// length of its longest outgoing front edge, so that the vertices found
  /// lead to every front edge that meets a disk.
  void set_reach(std::size_t id, double reach)
  {
    CGAL_precondition(contains(id));
    if(std::isnan(reach)) reach = std::numeric_limits<double>::infinity();
    const Place& pl = places_[id];
    if(pl.node == overflow_node) {
      overflow_[pl.position].extent = reach;
      return;
    }
    nodes_[pl.node].entries[pl.position].extent = reach;
    for(std::int32_t n = pl.node; n >= 0 && nodes_[n].max_reach < reach; n = nodes_[n].parent)
      nodes_[n].max_reach = reach;
  }

  double reach(std::size_t id) const
  {
    CGAL_precondition(contains(id));
    const Place& pl = places_[id];
    return (pl.node == overflow_node) ? overflow_[pl.position].extent : nodes_[pl.node].entries[pl.position].extent;
  }

  /// Calls `f(id, px, py, in_disk)` for the points within `radius` plus
  /// their reach of (x, y), where `in_disk` tells whether the point is
  /// within `radius` (both padded slightly; points with non-finite
  /// coordinates are always reported, as in the disk).
  template <class Function>
  void query_with_reach(double x, double y, double radius, Function f) const
  {
    const double pad = padding(x, y);
    const double r = radius * (1 + 1e-9) + pad;
    const double r2 = r * r;
    traverse(x, y, radius, true, [&](const Entry& e) {
      const double dx = e.x - x, dy = e.y - y;
      const double d2 = dx * dx + dy * dy;
      if(d2 <= r2 || !std::isfinite(d2)) {
        f(e.id, e.x, e.y, true);
        return;
      }
      const double reach = (radius + e.extent) * (1 + 1e-9) + pad;
      if(d2 <= reach * reach) f(e.id, e.x, e.y, false);
    });
  }

  /// Appends to `out` the ids of the points within `radius` of (x, y)
  /// (padded slightly).
  void query(double x, double y, double radius, std::vector<std::size_t>& out) const
  {
    query(x, y, radius, [&out](std::size_t id, double, double) { out.push_back(id); });
  }

  /// Calls `f(id, px, py)` for the points within `radius` of (x, y)
  /// (padded slightly; points with non-finite coordinates are always
  /// reported).
  template <class Function>
  void query(double x, double y, double radius, Function f) const
  {
    const double r = radius * (1 + 1e-9) + padding(x, y);
    const double r2 = r * r;
    traverse(x, y, radius, false, [&](const Entry& e) {
      const double dx = e.x - x, dy = e.y - y;
      const double d2 = dx * dx + dy * dy;
      if(d2 <= r2 || !std::isfinite(d2)) f(e.id, e.x, e.y);
    });
  }

  std::size_t number_of_queries() const { return number_of_queries_; }
  std::size_t number_of_nodes() const { return nodes_.size(); }

  // Checkpoints. A resumed run must take the decisions of an uninterrupted
  // one, and the order in which the queries report the points (which breaks
  // the mesher's ties) depends on the tree's layout: the history of its
  // insertions, splits, merges and free blocks. So save() writes the whole
  // state exactly (every node with its entries in order, the free blocks,
  // the places of all ids, the overflow list, the scalars), not only the
  // points held, and after load() every sequence of operations behaves as
  // on the saved tree. The format is native (see Binary_io.h).

  /// Writes the tree to `w`.
  void save(Binary_writer& w) const
  {
    w.write(format_tag);
    w.write(format_version);
    w.write(bucket_size_);
    w.write(max_depth_);
    w.write(abs_pad_);
    w.write(size_);
    w.write(number_of_queries_);
    w.write<std::uint64_t>(places_.size());
    for(const Place& pl : places_) {
      w.write(pl.node);
      w.write(pl.position);
    }
    w.write<std::uint64_t>(nodes_.size());
    for(const Node& n : nodes_) {
      w.write(n.box);
      w.write(n.max_reach);
      w.write(n.first_child);
      w.write(n.parent);
      w.write(n.depth);
      save_tree_entries(w, n.entries);
    }
    save_tree_entries(w, overflow_);
    blocks_.save(w);
  }

  /// Replaces the tree by one written by `save()`. The structure read is
  /// checked, so that a corrupt file throws (`r.fail()`) instead of making
  /// a later operation crash; the tree is left unchanged then.
  void load(Binary_reader& r)
  {
    Dynamic_point_quadtree t;
    if(r.read<std::uint32_t>() != format_tag) corrupt(r, "not a saved point quadtree");
    if(r.read<std::uint32_t>() != format_version) corrupt(r, "unknown format version");
    t.bucket_size_ = r.read<std::size_t>();
    t.max_depth_ = r.read<int>();
    t.abs_pad_ = r.read<double>();
    t.size_ = r.read<std::size_t>();
    t.number_of_queries_ = r.read<std::size_t>();
    const std::uint64_t number_of_places = r.read<std::uint64_t>();
    if(number_of_places > t.places_.max_size()) corrupt(r, "too many ids");
    // the vectors grow as their elements are read: a corrupt length costs
    // no more memory than the file holds
    for(std::uint64_t i = 0; i < number_of_places; ++i) {
      Place pl;
      pl.node = r.read<std::int32_t>();
      pl.position = r.read<std::uint32_t>();
      t.places_.push_back(pl);
    }
    const std::uint64_t number_of_nodes = r.read<std::uint64_t>();
    if(number_of_nodes == 0 || number_of_nodes > std::uint64_t((std::numeric_limits<std::int32_t>::max)()))
      corrupt(r, "number of nodes out of range");
    t.nodes_.clear();
    for(std::uint64_t i = 0; i < number_of_nodes; ++i) {
      t.nodes_.emplace_back();
      Node& n = t.nodes_.back();
      n.box = r.read<std::array<double, 4> >();
      n.max_reach = r.read<double>();
      n.first_child = r.read<std::int32_t>();
      n.parent = r.read<std::int32_t>();
      n.depth = r.read<std::int32_t>();
      load_entries(r, n.entries, number_of_places);
    }
    load_entries(r, t.overflow_, number_of_places);
    t.blocks_.load(r, number_of_nodes);
    t.check_loaded(r);
    *this = std::move(t);
  }

private:
  double padding(double x, double y) const { return 1e-12 * (std::abs(x) + std::abs(y)) + abs_pad_; }

  // Calls visit(entry) for the overflow list and for the leaves whose box
  // comes within radius (plus the nodes' reach bounds if with_reach) of
  // (x, y); the caller tests the entries.
  template <class Visit>
  void traverse(double x, double y, double radius, bool with_reach, Visit visit) const
  {
    ++number_of_queries_;
    const double pad = padding(x, y);
    for(const Entry& e : overflow_) visit(e);
    stack_.clear();
    stack_.push_back(0);
    while(!stack_.empty()) {
      const Node& n = nodes_[stack_.back()];
      stack_.pop_back();
      if(n.first_child == no_child) {
        for(const Entry& e : n.entries) visit(e);
        continue;
      }
      for(std::int32_t c = n.first_child; c < n.first_child + 4; ++c) {
        const Node& child = nodes_[c];
        const std::array<double, 4>& b = child.box;
        const double dx = (std::max)({b[0] - x, 0., x - b[2]});
        const double dy = (std::max)({b[1] - y, 0., y - b[3]});
        const double reach = (radius + (with_reach ? child.max_reach : 0.)) * (1 + 1e-9) + pad;
        if(dx * dx + dy * dy <= reach * reach) stack_.push_back(c);
      }
    }
  }

  static std::int32_t child_index(const std::array<double, 4>& b, double x, double y)
  {
    return (x > 0.5 * (b[0] + b[2]) ? 1 : 0) + (y > 0.5 * (b[1] + b[3]) ? 2 : 0);
  }

  void merge_empty_children(std::int32_t n)
  {
    while(n >= 0) {
      Node& node = nodes_[n];
      for(std::int32_t c = node.first_child; c < node.first_child + 4; ++c)
        if(nodes_[c].first_child != no_child || !nodes_[c].entries.empty()) return;
      // buffers are freed on merging, not when a leaf empties: a leaf at
      // the front empties and fills again many times
      for(std::int32_t c = node.first_child; c < node.first_child + 4; ++c)
        std::vector<Entry>().swap(nodes_[c].entries);
      blocks_.give_back(node.first_child, 4);
      node.first_child = no_child;
      node.max_reach = 0;
      n = node.parent;
    }
  }

  void split(std::int32_t n)
  {
    const std::int32_t first = blocks_.take(nodes_, 4);
    const std::array<double, 4> b = nodes_[n].box;
    const double mx = 0.5 * (b[0] + b[2]), my = 0.5 * (b[1] + b[3]);
    for(int c = 0; c < 4; ++c) {
      Node& child = nodes_[first + c];
      child.depth = nodes_[n].depth + 1;
      child.parent = n;
      child.first_child = no_child;
      child.max_reach = 0;
      child.box = {{(c & 1) ? mx : b[0], (c & 2) ? my : b[1], (c & 1) ? b[2] : mx, (c & 2) ? b[3] : my}};
    }
    std::vector<Entry> moved;
    moved.swap(nodes_[n].entries);
    nodes_[n].first_child = first;
    for(const Entry& e : moved) {
      const std::int32_t c = first + child_index(b, e.x, e.y);
      places_[e.id] = Place{c, std::uint32_t(nodes_[c].entries.size())};
      nodes_[c].entries.push_back(e);
      nodes_[c].max_reach = (std::max)(nodes_[c].max_reach, e.extent);
    }
    // a child that is still too full splits on its next insertion
  }

  // tells a saved quadtree from other data (format_version: of its layout)
  static constexpr std::uint32_t format_tag = 0x51504641; // "AFPQ" read as little endian
  static constexpr std::uint32_t format_version = 1;

  [[noreturn]] static void corrupt(const Binary_reader& r, const std::string& what)
  {
    r.fail("corrupt point quadtree: " + what);
  }

  static void load_entries(Binary_reader& r, std::vector<Entry>& v, std::uint64_t number_of_places)
  {
    load_tree_entries(r, v, number_of_places, "more entries in a leaf than ids",
                      [&r](const char* what) { corrupt(r, what); });
  }

  // Checks that a loaded tree is one that the operations can have made, as
  // far as an inconsistency could make them read out of bounds or loop: the
  // nodes reachable from the root form a tree (children blocks of 4 in
  // range, each node reached once, with its parent and depth), every other
  // node is in exactly one free block, and the entries and the places of the
  // ids held point at each other.
  void check_loaded(const Binary_reader& r) const
  {
    const std::size_t n = nodes_.size();
    for(const Node& node : nodes_) {
      if(node.parent < -1 || node.parent >= static_cast<long long>(n)) corrupt(r, "parent index out of range");
      if(node.first_child != no_child && (node.first_child < 1 || static_cast<std::size_t>(node.first_child) + 4 > n))
        corrupt(r, "child index out of range");
    }
    check_tree_layout(nodes_, blocks_, [](const Node&) { return 4; }, [&r](const char* what) { corrupt(r, what); });

    std::size_t held = 0;
    for(const Place& pl : places_) {
      if(pl.node == absent) continue;
      ++held;
      if(pl.node != overflow_node && (pl.node < 0 || static_cast<std::size_t>(pl.node) >= n))
        corrupt(r, "node of an id out of range");
    }
    std::size_t entries = 0;
    auto check_entries = [&](const std::vector<Entry>& v, std::int32_t node) {
      for(std::size_t pos = 0; pos < v.size(); ++pos) {
        const std::size_t id = v[pos].id;
        if(id >= places_.size() || places_[id].node != node || places_[id].position != pos)
          corrupt(r, "entry and place of its id disagree");
      }
      entries += v.size();
    };
    for(std::size_t i = 0; i < n; ++i) check_entries(nodes_[i].entries, static_cast<std::int32_t>(i));
    check_entries(overflow_, overflow_node);
    // each entry names a distinct id (the one whose place is that entry):
    // with as many entries as ids held, every id held has its entry
    if(entries != held || size_ != held) corrupt(r, "size differs from the number of points held");
  }

  std::vector<Node> nodes_;
  Node_blocks<std::int32_t, 1> blocks_; // blocks of 4 siblings merged away, for reuse
  std::vector<Place> places_;
  std::vector<Entry> overflow_;
  mutable std::vector<std::int32_t> stack_;
  std::size_t size_ = 0;
  std::size_t bucket_size_ = 8;
  int max_depth_ = 24;
  double abs_pad_ = 0;
  mutable std::size_t number_of_queries_ = 0;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DYNAMIC_POINT_QUADTREE_H
