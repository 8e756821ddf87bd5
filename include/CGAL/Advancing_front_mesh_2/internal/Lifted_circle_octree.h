// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_LIFTED_CIRCLE_OCTREE_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_LIFTED_CIRCLE_OCTREE_H

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

// A dynamic region octree over circles lifted to points (cx, cy, r), after
// section 5 and Fig. 11 of Mavriplis (1992).
//
// A query point q "breaks" a circle when |q - c| < r, i.e. when the lifted
// point lies above the 45-degree cone with apex (q, 0). An octant
// [x0,x1] x [y0,y1] x [r0,r1] can hold such a point only if
// r1 >= distance(q, [x0,x1] x [y0,y1]); all other octants are pruned.
// The same query with an inflated radius s (|q - c| < r + s) finds the
// circles that meet the disk of radius s about q (the constraints, stored
// as diametral circles, near a segment).
//
// Coordinates are doubles: the tree is a conservative filter (the test is
// padded by a relative epsilon); callers decide with exact predicates.
// Items whose lifted point falls outside the root box go to an overflow list
// that every query scans; with the root box padded generously this list
// stays nearly empty (it holds near-degenerate triangles' huge circles).
//
// Speed (measured on a 200k-triangle mesh, where the octree took 30% of the
// meshing time): the r-axis of the root box must cover every circle that may
// appear, so near the root an octant's r-range is far larger than the
// circles it holds and the cone test prunes little. Each node therefore also
// keeps the largest radius stored below it (an upper bound: removals do not
// lower it), and the cone test uses the smaller of the two. Leaves keep their
// circles inline, so a query reads them without an indirection.
//
// Memory: the front sweeps through the tree, so the octants it has left
// are empty. Eight empty sibling leaves merge back into their parent and
// their block of nodes is reused by the next split, which keeps the tree's
// size proportional to the circles it holds (the front), not to the region
// swept (without it, the nodes were 28 bytes per triangle of the mesh).
template <class Payload_ = std::size_t>
class Lifted_circle_octree
{
public:
  typedef Payload_ Payload;
  typedef std::size_t Item_id;
  /// the same tree for other payloads (the mesher holds two)
  template <class P>
  struct Rebind_payload
  {
    typedef Lifted_circle_octree<P> Other;
  };
  static constexpr Item_id null_item = (std::numeric_limits<Item_id>::max)();

private:
  static constexpr int no_child = -1;
  static constexpr int overflow_node = -2;

  // a circle as stored in a leaf (or in the overflow list): its centre and
  // its radius as `extent`
  typedef Tree_entry Entry;

  struct Node
  {
    std::array<double, 6> box; // x0, y0, r0, x1, y1, r1
    double max_r = -1;         // bound on the radii stored in the subtree; -1: empty since made
    double r_split = 0;        // radius dividing the children, if they are 8
    int first_child = no_child;
    int parent = -1;
    int depth = 0;
    int children = 0;          // 8 (octants), or 4 (quadrants, r not divided)
    std::vector<Entry> entries;
  };

  struct Item
  {
    Payload payload;
    int node;              // leaf holding the item, or overflow_node
    std::size_t position;  // index in that leaf's entry vector
    bool alive;
  };

public:
  Lifted_circle_octree() { reset(0, 0, 1, 1, 1); }

  /// Resets the tree to the root box [xmin,xmax] x [ymin,ymax] x [0,rmax].
  void reset(double xmin, double ymin, double xmax, double ymax, double rmax,
             std::size_t bucket_size = 16, int max_depth = 22)
  {
    // Lifted coordinates carry rounding errors proportional to the magnitude
    // of the input coordinates (think of a domain offset by 1e6), so the
    // padding has an absolute part as well as a relative one.
    const double magnitude = (std::max)({std::abs(xmin), std::abs(ymin), std::abs(xmax),
                                         std::abs(ymax), rmax, 1e-300});
    abs_pad_ = 1e-12 * magnitude;
    nodes_.clear();
    blocks_.clear();
    items_.clear();
    free_items_.clear();
    overflow_.clear();
    size_ = 0;
    bucket_size_ = bucket_size;
    max_depth_ = max_depth;
    Node root;
    root.box = {{xmin, ymin, 0., xmax, ymax, rmax}};
    nodes_.push_back(root);
  }

  std::size_t size() const { return size_; }
  std::size_t overflow_size() const { return overflow_.size(); }
  std::size_t number_of_nodes() const { return nodes_.size(); }

  // inner nodes whose children also divide the radii (for tests)
  std::size_t number_of_radius_divisions() const
  {
    std::size_t k = 0;
    for(const Node& n : nodes_)
      if(n.first_child != no_child && n.children == 8) ++k;
    return k;
  }

  const Payload& payload(Item_id id) const { return items_[id].payload; }

  /// Whether `id` names a circle the tree holds.
  bool is_alive(Item_id id) const { return id < items_.size() && items_[id].alive; }

  /// Calls `f(payload)` for every circle the tree holds, in item order.
  template <class Function>
  void for_each_payload(Function f) const
  {
    for(const Item& it : items_)
      if(it.alive) f(it.payload);
  }

  Item_id insert(double cx, double cy, double r, const Payload& p)
  {
    Item_id id;
    if(!free_items_.empty()) {
      id = free_items_.back();
      free_items_.pop_back();
    } else {
      id = items_.size();
      items_.emplace_back();
    }
    Item& it = items_[id];
    it.payload = p;
    it.alive = true;
    ++size_;
    const Entry e{cx, cy, r, id};
    if(!inside(nodes_[0].box, cx, cy, r)) { // also catches NaN
      it.node = overflow_node;
      it.position = overflow_.size();
      overflow_.push_back(e);
      return id;
    }
    int n = 0;
    for(;;) {
      Node& node = nodes_[n];
      node.max_r = (std::max)(node.max_r, r);
      if(node.first_child == no_child) break;
      n = node.first_child + child_index(node, cx, cy, r);
    }
    add_to_leaf(n, e);
    return id;
  }

  void remove(Item_id id)
  {
    CGAL_precondition(id < items_.size() && items_[id].alive);
    Item& it = items_[id];
    std::vector<Entry>& v = (it.node == overflow_node) ? overflow_ : nodes_[it.node].entries;
    // swap-and-pop keeps removal O(1); the moved item's position is patched
    const std::size_t pos = it.position;
    v[pos] = v.back();
    items_[v[pos].id].position = pos;
    v.pop_back();
    it.alive = false;
    if(v.empty() && it.node != overflow_node) {
      // the front has left this leaf: merge it with its empty siblings
      nodes_[it.node].max_r = -1;
      merge_empty_children(nodes_[it.node].parent);
    }
    free_items_.push_back(id);
    --size_;
  }

  /// Whether most of the memory the tree holds is left over from a time
  /// when it held more circles (then `rebuild()` releases it).
  bool is_sparse() const { return items_.size() >= 256 && 4 * size_ < items_.size(); }

  /// Rebuilds the tree for the circles it holds, in memory proportional to
  /// their number: the item, node and free-list arrays otherwise keep the
  /// size of the largest front until the end of the run. The items are
  /// renumbered; `renamed(payload, new_id)` is called for each of them.
  template <class Renamed>
  void rebuild(Renamed renamed)
  {
    struct Live { Entry entry; Payload payload; };
    std::vector<Live> live;
    live.reserve(size_);
    for(Item_id id = 0; id < items_.size(); ++id) {
      const Item& it = items_[id];
      if(!it.alive) continue;
      const Entry& e = (it.node == overflow_node) ? overflow_[it.position] : nodes_[it.node].entries[it.position];
      live.push_back(Live{e, it.payload});
    }
    const std::array<double, 6> box = nodes_[0].box;
    // clear() would keep the capacity
    std::vector<Node>().swap(nodes_);
    blocks_.release_memory();
    std::vector<Item>().swap(items_);
    std::vector<Item_id>().swap(free_items_);
    std::vector<Entry>().swap(overflow_);
    std::vector<int>().swap(stack_);
    reset(box[0], box[1], box[3], box[4], box[5], bucket_size_, max_depth_);
    items_.reserve(live.size());
    for(const Live& l : live) renamed(l.payload, insert(l.entry.x, l.entry.y, l.entry.extent, l.payload));
  }

  /// Releases the spare capacity of the arrays (for a tree that no longer
  /// grows).
  void shrink_to_fit()
  {
    nodes_.shrink_to_fit();
    items_.shrink_to_fit();
    overflow_.shrink_to_fit();
    for(Node& n : nodes_) n.entries.shrink_to_fit();
  }

  /// Calls `f(payload)` for every circle with |q - c| < r + inflate (padded).
  template <class Function>
  void query(double qx, double qy, double inflate, Function f) const
  {
    for(const Entry& e : overflow_) test_entry(e, qx, qy, inflate, f);
    stack_.clear();
    stack_.push_back(0);
    while(!stack_.empty()) {
      const Node& n = nodes_[stack_.back()];
      stack_.pop_back();
      if(n.max_r < 0) continue;
      const double dx = (std::max)({n.box[0] - qx, 0., qx - n.box[3]});
      const double dy = (std::max)({n.box[1] - qy, 0., qy - n.box[4]});
      const double reach = ((std::min)(n.box[5], n.max_r) + inflate) * (1 + 1e-9) + abs_pad_;
      if(dx * dx + dy * dy > reach * reach) continue;
      if(n.first_child == no_child) {
        // entries in the tree lie in the root box, so they are finite
        for(const Entry& e : n.entries) test_finite_entry(e, qx, qy, inflate, f);
      } else {
        for(int c = 0; c < n.children; ++c)
          if(nodes_[n.first_child + c].max_r >= 0) stack_.push_back(n.first_child + c);
      }
    }
  }

  // Checkpoints. A resumed run must take the decisions of an uninterrupted
  // one, and the order in which query() reports the circles (which breaks
  // the mesher's ties) depends on the tree's layout: the history of its
  // insertions, splits, merges and free lists. So save() writes the whole
  // state exactly (every node with its entries in order, the free lists, the
  // removed items' slots, the overflow list, the scalars), not only the
  // circles held, and after load() every sequence of operations behaves as
  // on the saved tree. The format is native (see Binary_io.h).

  /// Writes the tree to `w`; `write_payload(w, p)` writes the payload `p`
  /// of a live item (a removed item's payload, which may be a dangling
  /// handle, is not written).
  template <class PayloadWriter>
  void save(Binary_writer& w, PayloadWriter write_payload) const
  {
    w.write(format_tag);
    w.write(format_version);
    w.write(bucket_size_);
    w.write(max_depth_);
    w.write(abs_pad_);
    w.write(size_);
    w.write<std::uint64_t>(items_.size());
    for(const Item& it : items_) {
      w.write<std::uint8_t>(it.alive ? 1 : 0); // 0: removed, no payload follows
      w.write(it.node);
      w.write(it.position);
      if(it.alive) write_payload(w, it.payload);
    }
    w.write<std::uint64_t>(nodes_.size());
    for(const Node& n : nodes_) {
      w.write(n.box);
      w.write(n.max_r);
      w.write(n.r_split);
      w.write(n.first_child);
      w.write(n.parent);
      w.write(n.depth);
      w.write(n.children);
      save_tree_entries(w, n.entries);
    }
    save_tree_entries(w, overflow_);
    blocks_.save(w);
    w.write_vector(free_items_);
  }

  /// Replaces the tree by one written by `save()`; `read_payload(r)`
  /// returns a payload written by the `write_payload` of `save()`. Removed
  /// items get a default-constructed payload. The structure read is
  /// checked, so that a corrupt file throws (`r.fail()`) instead of making
  /// a later operation crash; the tree is left unchanged then.
  template <class PayloadReader>
  void load(Binary_reader& r, PayloadReader read_payload)
  {
    Lifted_circle_octree t;
    if(r.read<std::uint32_t>() != format_tag) corrupt(r, "not a saved lifted circle octree");
    if(r.read<std::uint32_t>() != format_version) corrupt(r, "unknown format version");
    t.bucket_size_ = r.read<std::size_t>();
    t.max_depth_ = r.read<int>();
    t.abs_pad_ = r.read<double>();
    t.size_ = r.read<std::size_t>();
    const std::uint64_t number_of_items = r.read<std::uint64_t>();
    if(number_of_items > t.items_.max_size()) corrupt(r, "too many items");
    // the vectors grow as their elements are read: a corrupt length costs
    // no more memory than the file holds
    for(std::uint64_t i = 0; i < number_of_items; ++i) {
      t.items_.emplace_back();
      Item& it = t.items_.back();
      const std::uint8_t alive = r.read<std::uint8_t>();
      if(alive > 1) corrupt(r, "item neither live nor removed");
      it.alive = (alive == 1);
      it.node = r.read<int>();
      it.position = r.read<std::size_t>();
      if(it.alive) it.payload = read_payload(r);
    }
    const std::uint64_t number_of_nodes = r.read<std::uint64_t>();
    if(number_of_nodes == 0 || number_of_nodes > std::uint64_t((std::numeric_limits<int>::max)()))
      corrupt(r, "number of nodes out of range");
    t.nodes_.clear();
    for(std::uint64_t i = 0; i < number_of_nodes; ++i) {
      t.nodes_.emplace_back();
      Node& n = t.nodes_.back();
      n.box = r.read<std::array<double, 6> >();
      n.max_r = r.read<double>();
      n.r_split = r.read<double>();
      n.first_child = r.read<int>();
      n.parent = r.read<int>();
      n.depth = r.read<int>();
      n.children = r.read<int>();
      load_entries(r, n.entries, number_of_items);
    }
    load_entries(r, t.overflow_, number_of_items);
    t.blocks_.load(r, number_of_nodes);
    r.read_vector(t.free_items_, number_of_items);
    t.check_loaded(r);
    *this = std::move(t);
  }

private:
  template <class Function>
  void test_entry(const Entry& e, double qx, double qy, double inflate, Function& f) const
  {
    // a circle whose lifted point could not be computed (overflow, NaN) is
    // always reported: the exact test downstream decides
    if(!std::isfinite(e.extent) || !std::isfinite(e.x) || !std::isfinite(e.y)) {
      f(items_[e.id].payload);
      return;
    }
    test_finite_entry(e, qx, qy, inflate, f);
  }

  template <class Function>
  void test_finite_entry(const Entry& e, double qx, double qy, double inflate, Function& f) const
  {
    const double dx = e.x - qx, dy = e.y - qy;
    const double reach = (e.extent + inflate) * (1 + 1e-9) + abs_pad_;
    if(dx * dx + dy * dy <= reach * reach) f(items_[e.id].payload);
  }

  static bool inside(const std::array<double, 6>& b, double x, double y, double r)
  {
    return x >= b[0] && x <= b[3] && y >= b[1] && y <= b[4] && r >= b[2] && r <= b[5];
  }

  static int child_index(const Node& n, double x, double y, double r)
  {
    const std::array<double, 6>& b = n.box;
    return (x > 0.5 * (b[0] + b[3]) ? 1 : 0) + (y > 0.5 * (b[1] + b[4]) ? 2 : 0) +
           (n.children == 8 && r > n.r_split ? 4 : 0);
  }

  void add_to_leaf(int n, const Entry& e)
  {
    items_[e.id].node = n;
    items_[e.id].position = nodes_[n].entries.size();
    nodes_[n].entries.push_back(e);
    if(nodes_[n].entries.size() > bucket_size_ && nodes_[n].depth < max_depth_) split(n);
  }

  void merge_empty_children(int n)
  {
    while(n >= 0) {
      Node& node = nodes_[n];
      const int end = node.first_child + node.children;
      for(int c = node.first_child; c < end; ++c)
        if(nodes_[c].first_child != no_child || !nodes_[c].entries.empty()) return;
      // the leaves' buffers are freed here, not when they empty: a leaf at
      // the front empties and fills again many times
      for(int c = node.first_child; c < end; ++c) std::vector<Entry>().swap(nodes_[c].entries);
      blocks_.give_back(node.first_child, node.children);
      node.first_child = no_child;
      node.max_r = -1;
      n = node.parent;
    }
  }

  // The radii are divided only where the leaf's circles differ in size by
  // more than about half the leaf's width: only then does the cone test
  // prune one size class and not the other. With a smooth size field the
  // circles near each other have nearly equal radii, and dividing the
  // r-axis at its midpoint, as a plain octree does, adds a level per
  // halving of the root's r-range (about ten on a uniform mesh) that prunes
  // nothing but lengthens every insertion and query path. Where the radii
  // are divided, it is at the middle of the leaf's radii, not of its box.
  void split(int n)
  {
    const std::array<double, 6> b = nodes_[n].box;
    double r_lo = b[5], r_hi = b[2];
    for(const Entry& e : nodes_[n].entries) {
      r_lo = (std::min)(r_lo, e.extent);
      r_hi = (std::max)(r_hi, e.extent);
    }
    const double width = (std::max)(b[3] - b[0], b[4] - b[1]);
    const double mr = 0.5 * (r_lo + r_hi);
    const int children = (r_hi - r_lo > 0.5 * width && mr > b[2] && mr < b[5]) ? 8 : 4;
    const int first = blocks_.take(nodes_, children);
    const double mx = 0.5 * (b[0] + b[3]), my = 0.5 * (b[1] + b[4]);
    nodes_[n].children = children;
    nodes_[n].r_split = mr;
    for(int c = 0; c < children; ++c) {
      Node& child = nodes_[first + c];
      child.depth = nodes_[n].depth + 1;
      child.parent = n;
      child.first_child = no_child;
      child.max_r = -1;
      child.box = {{(c & 1) ? mx : b[0], (c & 2) ? my : b[1], (c & 4) ? mr : b[2],
                    (c & 1) ? b[3] : mx, (c & 2) ? b[4] : my, (children == 8 && !(c & 4)) ? mr : b[5]}};
    }
    std::vector<Entry> moved;
    moved.swap(nodes_[n].entries);
    nodes_[n].first_child = first;
    for(const Entry& e : moved) {
      const int c = first + child_index(nodes_[n], e.x, e.y, e.extent);
      items_[e.id].node = c;
      items_[e.id].position = nodes_[c].entries.size();
      nodes_[c].entries.push_back(e);
      nodes_[c].max_r = (std::max)(nodes_[c].max_r, e.extent);
    }
    // no recursive split here: a child that is still too full splits on its
    // next insertion, which bounds the work of one insertion
  }

  // tells a saved octree from other data (format_version: of its layout)
  static constexpr std::uint32_t format_tag = 0x434c4641; // "AFLC" read as little endian
  static constexpr std::uint32_t format_version = 1;

  [[noreturn]] static void corrupt(const Binary_reader& r, const std::string& what)
  {
    r.fail("corrupt lifted circle octree: " + what);
  }

  static void load_entries(Binary_reader& r, std::vector<Entry>& v, std::uint64_t number_of_items)
  {
    load_tree_entries(r, v, number_of_items, "more entries in a leaf than items",
                      [&r](const char* what) { corrupt(r, what); });
  }

  // Checks that a loaded tree is one that the operations can have made, as
  // far as an inconsistency could make them read out of bounds or loop: the
  // nodes reachable from the root form a tree (children blocks of 4 or 8 in
  // range, each node reached once, with its parent and depth), every other
  // node is in exactly one free block, the entries and the live items point
  // at each other, and the free items are the removed ones.
  void check_loaded(const Binary_reader& r) const
  {
    const std::size_t n = nodes_.size();
    for(const Node& node : nodes_) {
      if(node.children != 0 && node.children != 4 && node.children != 8) corrupt(r, "children neither 4 nor 8");
      if(node.parent < -1 || node.parent >= static_cast<long long>(n)) corrupt(r, "parent index out of range");
      if(node.first_child != no_child &&
         (node.children == 0 || node.first_child < 1 ||
          static_cast<std::size_t>(node.first_child) + static_cast<std::size_t>(node.children) > n))
        corrupt(r, "child index out of range");
    }
    check_tree_layout(nodes_, blocks_, [](const Node& node) { return node.children; },
                      [&r](const char* what) { corrupt(r, what); });

    std::size_t alive = 0;
    for(const Item& it : items_) {
      alive += it.alive ? 1 : 0;
      if(it.node != overflow_node && (it.node < 0 || static_cast<std::size_t>(it.node) >= n))
        corrupt(r, "item's node out of range");
    }
    std::size_t entries = 0;
    auto check_entries = [&](const std::vector<Entry>& v, int node) {
      for(std::size_t pos = 0; pos < v.size(); ++pos) {
        const Item_id id = v[pos].id;
        if(id >= items_.size() || !items_[id].alive || items_[id].node != node || items_[id].position != pos)
          corrupt(r, "entry and item disagree");
      }
      entries += v.size();
    };
    for(std::size_t i = 0; i < n; ++i) check_entries(nodes_[i].entries, static_cast<int>(i));
    check_entries(overflow_, overflow_node);
    // each entry names a distinct live item (the one pointing at it): with
    // as many entries as live items, every live item has its entry
    if(entries != alive || size_ != alive) corrupt(r, "size differs from the number of items held");
    if(free_items_.size() != items_.size() - alive) corrupt(r, "free items differ from the removed ones");
    std::vector<char> freed(items_.size(), 0);
    for(Item_id id : free_items_) {
      if(id >= items_.size() || items_[id].alive || freed[id]) corrupt(r, "free items differ from the removed ones");
      freed[id] = 1;
    }
  }

  std::vector<Node> nodes_;
  Node_blocks<int, 2> blocks_; // blocks of 4 and 8 siblings merged away, for reuse
  std::vector<Item> items_;
  std::vector<Item_id> free_items_;
  std::vector<Entry> overflow_;
  mutable std::vector<int> stack_;
  std::size_t size_ = 0;
  std::size_t bucket_size_ = 16;
  int max_depth_ = 22;
  double abs_pad_ = 0;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_LIFTED_CIRCLE_OCTREE_H
