// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DYNAMIC_POINT_INDEX_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DYNAMIC_POINT_INDEX_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/tuple/tuple.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The close-point search of step 4: the active (front) vertices, searched
// by disk with CGAL's Kd_tree and Fuzzy_sphere.
//
// Kd_tree is static: an insertion invalidates the tree and the next query
// rebuilds it from scratch. The front changes at every step, so the index
// keeps the tree as a snapshot and absorbs changes beside it:
//  - insertion appends to a small unsorted buffer, scanned linearly by
//    every query: O(1) per insertion, O(buffer) per query;
//  - removal clears a flag; dead points stay in the tree and are filtered
//    out of query results: O(1) per removal;
//  - when the buffer exceeds max(64, 2 sqrt(n)) or the dead points exceed
//    half the tree, the tree is rebuilt from the live points in
//    O(n log n). With n live points this amortises to O(sqrt(n) log n) per
//    change, and a query costs O(log n + sqrt(n) + k).
// n is the front size, O(sqrt(N)) for N mesh vertices in smooth fields.
class Dynamic_point_index
{
  typedef CGAL::Simple_cartesian<double> Approximate_kernel;
  typedef Approximate_kernel::Point_2 Approximate_point;
  typedef boost::tuple<Approximate_point, std::size_t> Point_and_id;
  typedef CGAL::Search_traits_2<Approximate_kernel> Base_traits;
  typedef CGAL::Search_traits_adapter<Point_and_id,
                                      CGAL::Nth_of_tuple_property_map<0, Point_and_id>,
                                      Base_traits> Traits;
  typedef CGAL::Kd_tree<Traits> Tree;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;

  enum State : unsigned char { ABSENT = 0, IN_TREE = 1, IN_BUFFER = 2 };

public:
  void clear()
  {
    tree_.reset(new Tree());
    tree_count_ = 0;
    dead_in_tree_ = 0;
    buffer_.clear();
    state_.clear();
    points_.clear();
    in_tree_dead_.clear();
    tree_ids_.clear();
    live_ = 0;
  }

  Dynamic_point_index() { clear(); }

  bool contains(std::size_t id) const { return id < state_.size() && state_[id] != ABSENT; }

  std::size_t size() const { return live_; }

  void insert(std::size_t id, double x, double y)
  {
    if(id >= state_.size()) {
      state_.resize(id + 1, ABSENT);
      points_.resize(id + 1);
      in_tree_dead_.resize(id + 1, false);
    }
    if(state_[id] != ABSENT) return;
    points_[id] = Approximate_point(x, y);
    if(in_tree_dead_[id]) {
      // still physically in the tree: revive it instead of duplicating it
      in_tree_dead_[id] = false;
      --dead_in_tree_;
      state_[id] = IN_TREE;
    } else {
      state_[id] = IN_BUFFER;
      buffer_.push_back(id);
    }
    ++live_;
    const std::size_t limit = (std::max)(std::size_t(64),
                                         std::size_t(2 * std::sqrt(double(tree_count_))));
    if(buffer_.size() > limit) rebuild();
  }

  void remove(std::size_t id)
  {
    if(!contains(id)) return;
    if(state_[id] == IN_TREE) {
      in_tree_dead_[id] = true;
      ++dead_in_tree_;
    } else {
      buffer_.erase(std::find(buffer_.begin(), buffer_.end(), id));
    }
    state_[id] = ABSENT;
    --live_;
    if(dead_in_tree_ > 64 && 2 * dead_in_tree_ > tree_count_) rebuild();
  }

  /// Appends to `out` the ids of the live points within `radius` of (x, y)
  /// (padded slightly: callers decide with exact predicates).
  void query(double x, double y, double radius, std::vector<std::size_t>& out) const
  {
    ++number_of_queries_;
    const double r = radius * (1 + 1e-9) + 1e-12 * (std::abs(x) + std::abs(y));
    if(tree_count_ > 0) {
      Sphere s(Point_and_id(Approximate_point(x, y), 0), r, 0.);
      scratch_.clear();
      tree_->search(std::back_inserter(scratch_), s);
      for(const Point_and_id& p : scratch_) {
        const std::size_t id = boost::get<1>(p);
        if(state_[id] == IN_TREE) out.push_back(id);
      }
    }
    const double r2 = r * r;
    for(std::size_t id : buffer_) {
      const double dx = points_[id].x() - x, dy = points_[id].y() - y;
      if(dx * dx + dy * dy <= r2) out.push_back(id);
    }
  }

  std::size_t number_of_queries() const { return number_of_queries_; }
  std::size_t number_of_rebuilds() const { return number_of_rebuilds_; }

private:
  void rebuild()
  {
    // only the ids in the old tree and the buffer are visited, so a rebuild
    // costs O(n log n) in the front size n, not in the mesh size
    std::vector<Point_and_id> pts;
    pts.reserve(live_);
    std::vector<std::size_t> ids;
    ids.reserve(live_);
    for(std::size_t id : tree_ids_) {
      in_tree_dead_[id] = false;
      if(state_[id] == IN_TREE) ids.push_back(id);
    }
    for(std::size_t id : buffer_) {
      state_[id] = IN_TREE;
      ids.push_back(id);
    }
    for(std::size_t id : ids) pts.push_back(Point_and_id(points_[id], id));
    tree_ids_.swap(ids);
    tree_.reset(new Tree(pts.begin(), pts.end()));
    if(!pts.empty()) tree_->build(); // Kd_tree refuses to build on no points
    tree_count_ = pts.size();
    dead_in_tree_ = 0;
    buffer_.clear();
    ++number_of_rebuilds_;
  }

  std::unique_ptr<Tree> tree_;
  std::size_t tree_count_ = 0;
  std::size_t dead_in_tree_ = 0;
  std::size_t live_ = 0;
  std::vector<std::size_t> buffer_;
  std::vector<std::size_t> tree_ids_;
  std::vector<State> state_;
  std::vector<bool> in_tree_dead_;
  std::vector<Approximate_point> points_;
  mutable std::vector<Point_and_id> scratch_;
  mutable std::size_t number_of_queries_ = 0;
  std::size_t number_of_rebuilds_ = 0;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DYNAMIC_POINT_INDEX_H
