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

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
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
// circles that meet the disk of radius s about q, which is how front edges
// (stored as diametral circles) near a search disk are found.
//
// Coordinates are doubles: the tree is a conservative filter (the test is
// padded by a relative epsilon); callers decide with exact predicates.
// Items whose lifted point falls outside the root box go to an overflow list
// that every query scans; with the root box padded generously this list
// stays nearly empty (it holds near-degenerate triangles' huge circles).
template <class Payload>
class Lifted_circle_octree
{
public:
  typedef std::size_t Item_id;
  static constexpr Item_id null_item = (std::numeric_limits<Item_id>::max)();

private:
  static constexpr int no_child = -1;
  static constexpr int overflow_node = -2;

  struct Node
  {
    std::array<double, 6> box; // x0, y0, r0, x1, y1, r1
    int first_child = no_child;
    int depth = 0;
    std::vector<Item_id> items;
  };

  struct Item
  {
    double x, y, r;
    Payload payload;
    int node;              // leaf holding the item, or overflow_node
    std::size_t position;  // index in that leaf's item vector
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

  const Payload& payload(Item_id id) const { return items_[id].payload; }

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
    it.x = cx; it.y = cy; it.r = r;
    it.payload = p;
    it.alive = true;
    ++size_;
    if(!inside(nodes_[0].box, cx, cy, r)) { // also catches NaN
      it.node = overflow_node;
      it.position = overflow_.size();
      overflow_.push_back(id);
      return id;
    }
    int n = 0;
    while(nodes_[n].first_child != no_child)
      n = nodes_[n].first_child + child_index(nodes_[n].box, cx, cy, r);
    add_to_leaf(n, id);
    return id;
  }

  void remove(Item_id id)
  {
    CGAL_precondition(id < items_.size() && items_[id].alive);
    Item& it = items_[id];
    std::vector<Item_id>& v = (it.node == overflow_node) ? overflow_ : nodes_[it.node].items;
    // swap-and-pop keeps removal O(1); the moved item's position is patched
    const std::size_t pos = it.position;
    v[pos] = v.back();
    items_[v[pos]].position = pos;
    v.pop_back();
    it.alive = false;
    free_items_.push_back(id);
    --size_;
  }

  /// Calls `f(payload)` for every circle with |q - c| < r + inflate (padded).
  template <class Function>
  void query(double qx, double qy, double inflate, Function f) const
  {
    for(Item_id id : overflow_) test_item(items_[id], qx, qy, inflate, f);
    stack_.clear();
    stack_.push_back(0);
    while(!stack_.empty()) {
      const Node& n = nodes_[stack_.back()];
      stack_.pop_back();
      const double dx = (std::max)({n.box[0] - qx, 0., qx - n.box[3]});
      const double dy = (std::max)({n.box[1] - qy, 0., qy - n.box[4]});
      const double reach = (n.box[5] + inflate) * (1 + 1e-9) + abs_pad_;
      if(dx * dx + dy * dy > reach * reach) continue;
      if(n.first_child == no_child) {
        for(Item_id id : n.items) test_item(items_[id], qx, qy, inflate, f);
      } else {
        for(int c = 0; c < 8; ++c) stack_.push_back(n.first_child + c);
      }
    }
  }

private:
  template <class Function>
  void test_item(const Item& it, double qx, double qy, double inflate, Function& f) const
  {
    // a circle whose lifted point could not be computed (overflow, NaN) is
    // always reported: the exact test downstream decides
    if(!std::isfinite(it.r) || !std::isfinite(it.x) || !std::isfinite(it.y)) {
      f(it.payload);
      return;
    }
    const double dx = it.x - qx, dy = it.y - qy;
    const double reach = (it.r + inflate) * (1 + 1e-9) + abs_pad_;
    if(dx * dx + dy * dy <= reach * reach) f(it.payload);
  }

  static bool inside(const std::array<double, 6>& b, double x, double y, double r)
  {
    return x >= b[0] && x <= b[3] && y >= b[1] && y <= b[4] && r >= b[2] && r <= b[5];
  }

  static int child_index(const std::array<double, 6>& b, double x, double y, double r)
  {
    return (x > 0.5 * (b[0] + b[3]) ? 1 : 0) + (y > 0.5 * (b[1] + b[4]) ? 2 : 0) +
           (r > 0.5 * (b[2] + b[5]) ? 4 : 0);
  }

  void add_to_leaf(int n, Item_id id)
  {
    items_[id].node = n;
    items_[id].position = nodes_[n].items.size();
    nodes_[n].items.push_back(id);
    if(nodes_[n].items.size() > bucket_size_ && nodes_[n].depth < max_depth_) split(n);
  }

  void split(int n)
  {
    const int first = static_cast<int>(nodes_.size());
    const std::array<double, 6> b = nodes_[n].box;
    const double mx = 0.5 * (b[0] + b[3]), my = 0.5 * (b[1] + b[4]), mr = 0.5 * (b[2] + b[5]);
    for(int c = 0; c < 8; ++c) {
      Node child;
      child.depth = nodes_[n].depth + 1;
      child.box = {{(c & 1) ? mx : b[0], (c & 2) ? my : b[1], (c & 4) ? mr : b[2],
                    (c & 1) ? b[3] : mx, (c & 2) ? b[4] : my, (c & 4) ? b[5] : mr}};
      nodes_.push_back(child);
    }
    std::vector<Item_id> moved;
    moved.swap(nodes_[n].items);
    nodes_[n].first_child = first;
    for(Item_id id : moved) {
      const Item& it = items_[id];
      const int c = first + child_index(b, it.x, it.y, it.r);
      items_[id].node = c;
      items_[id].position = nodes_[c].items.size();
      nodes_[c].items.push_back(id);
    }
    // no recursive split here: a child that is still too full splits on its
    // next insertion, which bounds the work of one insertion
  }

  std::vector<Node> nodes_;
  std::vector<Item> items_;
  std::vector<Item_id> free_items_;
  std::vector<Item_id> overflow_;
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
