// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_KD_TREE_POINT_INDEX_H
#define CGAL_ADVANCING_FRONT_MESH_2_KD_TREE_POINT_INDEX_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_2.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Splitters.h>
#include <CGAL/assertions.h>
#include <CGAL/property_map.h>

#include <boost/tuple/tuple.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

The close-point search of step 4 built on CGAL's Spatial_searching package:
a `CGAL::Kd_tree` queried with `CGAL::Fuzzy_sphere`. A model of
`AdvancingFrontPointIndex_2`, for
`Advancing_front_mesher_2<CDT, SizingField, Visitor, Kd_tree_point_index>`.

A `Kd_tree` is static: an insertion invalidates it, and the next query
rebuilds it from scratch, while the front changes at every step. So the
index keeps the tree as a snapshot and absorbs the changes beside it: an
insertion goes to a small buffer that every query scans, a removal only
flags the point, and the tree is rebuilt from the live points when the
buffer exceeds max(64, 2 sqrt(n)) points or half the tree is dead. With n
points (the front, O(sqrt(N)) for N mesh vertices in a smooth field) an
update costs O(sqrt(n) log n) amortised and a query O(log n + sqrt(n) + k).

The reach of a point (see the concept) is handled by searching the disk
enlarged by the largest reach of any point, then filtering: the search
finds more points than the default quadtree, which bounds the reach per
node. On the benchmark (user manual, Section "Performance") a run takes
1.06 to 1.24 times the default's time on the square with a hole up to 1M
triangles, 1.7 times at 10M, and 5.3 times on the graded MESH2D islands,
whose long boundary edges make the largest reach, and so every searched
disk, large. Every mesh is valid with either; they may differ where equal
candidates are taken in another order (on the benchmark's inputs the counts
and quality figures were the same).

The index cannot be saved: a mesher using it refuses checkpoints.

\cgalModels{AdvancingFrontPointIndex_2}
*/
class Kd_tree_point_index
{
  typedef CGAL::Simple_cartesian<double> Approximate_kernel;
  typedef Approximate_kernel::Point_2 Approximate_point;
  typedef boost::tuple<Approximate_point, std::size_t> Point_and_id;
  typedef CGAL::Search_traits_2<Approximate_kernel> Base_traits;
  typedef CGAL::Search_traits_adapter<Point_and_id, CGAL::Nth_of_tuple_property_map<0, Point_and_id>, Base_traits>
    Traits;
  typedef CGAL::Sliding_midpoint<Traits> Splitter;
  typedef CGAL::Kd_tree<Traits, Splitter> Tree;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;

  enum State : unsigned char { ABSENT = 0, IN_TREE = 1, IN_BUFFER = 2 };

public:
  Kd_tree_point_index() { clear(); }

  /// Empties the index; `leaf_size` is the bucket size of the tree's
  /// leaves. The box is not needed.
  void reset(double, double, double, double, std::size_t leaf_size = 10)
  {
    clear();
    bucket_size_ = (std::max)(leaf_size, std::size_t(1));
  }

  void clear()
  {
    tree_.reset();
    tree_ids_.clear();
    non_finite_.clear();
    dead_in_tree_ = 0;
    buffer_.clear();
    state_.clear();
    in_tree_.clear();
    points_.clear();
    points_in_tree_.clear();
    reach_.clear();
    live_ = 0;
    max_reach_ = 0;
    magnitude_ = 0;
  }

  bool contains(std::size_t id) const { return id < state_.size() && state_[id] != ABSENT; }
  std::size_t size() const { return live_; }

  void insert(std::size_t id, double x, double y)
  {
    if(id >= state_.size()) {
      state_.resize(id + 1, ABSENT);
      in_tree_.resize(id + 1, false);
      points_.resize(id + 1);
      reach_.resize(id + 1, 0.);
    }
    if(state_[id] != ABSENT) return;
    points_[id] = Approximate_point(x, y);
    reach_[id] = 0;
    ++live_;
    if(in_tree_[id] && points_in_tree_[id] == points_[id]) {
      // still physically in the tree, at the same place: revived
      --dead_in_tree_;
      state_[id] = IN_TREE;
      return;
    }
    state_[id] = IN_BUFFER;
    buffer_.push_back(id);
    if(buffer_.size() > (std::max)(std::size_t(64), std::size_t(2 * std::sqrt(double(tree_ids_.size())))))
      rebuild();
  }

  void remove(std::size_t id)
  {
    if(!contains(id)) return;
    if(state_[id] == IN_TREE) {
      ++dead_in_tree_;
    } else {
      buffer_.erase(std::find(buffer_.begin(), buffer_.end(), id));
    }
    state_[id] = ABSENT;
    --live_;
    if(dead_in_tree_ > 64 && 2 * dead_in_tree_ > tree_ids_.size()) rebuild();
  }

  void set_reach(std::size_t id, double reach)
  {
    CGAL_precondition(contains(id));
    if(std::isnan(reach)) reach = std::numeric_limits<double>::infinity();
    reach_[id] = reach;
    max_reach_ = (std::max)(max_reach_, reach);
  }

  double reach(std::size_t id) const
  {
    CGAL_precondition(contains(id));
    return reach_[id];
  }

  /// Calls `f(id, px, py, in_disk)` for the points within `radius` plus
  /// their reach of (x, y), `in_disk` telling whether the point is within
  /// `radius` (both padded slightly; points with non-finite coordinates are
  /// always reported, as in the disk).
  template <class Function>
  void query_with_reach(double x, double y, double radius, Function f) const
  {
    const double pad = 1e-12 * (std::abs(x) + std::abs(y) + magnitude_);
    const double r = radius * (1 + 1e-9) + pad;
    auto report = [&](std::size_t id) {
      const double px = points_[id].x(), py = points_[id].y();
      const double dx = px - x, dy = py - y;
      const double d2 = dx * dx + dy * dy;
      if(d2 <= r * r || !std::isfinite(d2)) {
        f(id, px, py, true);
        return;
      }
      const double reach = (radius + reach_[id]) * (1 + 1e-9) + pad;
      if(d2 <= reach * reach) f(id, px, py, false);
    };
    if(tree_ != nullptr) {
      const double search = (radius + max_reach_) * (1 + 1e-9) + pad;
      scratch_.clear();
      if(std::isfinite(search)) {
        tree_->search(std::back_inserter(scratch_), Sphere(Point_and_id(Approximate_point(x, y), 0), search, 0.));
        for(const Point_and_id& p : scratch_) {
          const std::size_t id = boost::get<1>(p);
          if(state_[id] == IN_TREE) report(id);
        }
      } else {
        // a reach that is not finite: every point may be within it
        for(std::size_t id : tree_ids_)
          if(state_[id] == IN_TREE) report(id);
      }
    }
    for(std::size_t id : non_finite_) if(state_[id] == IN_TREE) report(id);
    for(std::size_t id : buffer_) report(id);
  }

  /// Renames the points (point `id` becomes `new_id[id]`) and rebuilds the
  /// tree in memory proportional to their number.
  template <class Id_map>
  void renumber(const Id_map& new_id)
  {
    std::vector<std::pair<std::size_t, std::size_t> > live; // new id, old id
    for(std::size_t id = 0; id < state_.size(); ++id)
      if(state_[id] != ABSENT) live.emplace_back(new_id[id], id);
    std::vector<Approximate_point> points = points_;
    std::vector<double> reach = reach_;
    const std::size_t bucket_size = bucket_size_;
    clear();
    bucket_size_ = bucket_size;
    for(const auto& p : live) {
      if(p.first >= state_.size()) {
        state_.resize(p.first + 1, ABSENT);
        in_tree_.resize(p.first + 1, false);
        points_.resize(p.first + 1);
        reach_.resize(p.first + 1, 0.);
      }
      state_[p.first] = IN_BUFFER;
      points_[p.first] = points[p.second];
      reach_[p.first] = reach[p.second];
      max_reach_ = (std::max)(max_reach_, reach[p.second]);
      buffer_.push_back(p.first);
      ++live_;
    }
    rebuild();
  }

  /// the number of times the tree was rebuilt (for tests and benchmarks)
  std::size_t number_of_rebuilds() const { return number_of_rebuilds_; }

private:
  // Builds the tree from the live points: O(n log n) in the number of live
  // points, never in the number of ids ever used.
  void rebuild()
  {
    std::vector<std::size_t> ids;
    ids.reserve(live_);
    for(std::size_t id : tree_ids_) {
      in_tree_[id] = false;
      if(state_[id] == IN_TREE) ids.push_back(id);
    }
    for(std::size_t id : non_finite_) {
      in_tree_[id] = false;
      if(state_[id] == IN_TREE) ids.push_back(id);
    }
    ids.insert(ids.end(), buffer_.begin(), buffer_.end());
    std::vector<Point_and_id> pts;
    std::vector<std::size_t> finite_ids;
    non_finite_.clear();
    max_reach_ = 0;
    magnitude_ = 0;
    for(std::size_t id : ids) {
      state_[id] = IN_TREE;
      in_tree_[id] = true;
      max_reach_ = (std::max)(max_reach_, reach_[id]);
      const Approximate_point& p = points_[id];
      if(std::isfinite(p.x()) && std::isfinite(p.y())) {
        pts.push_back(Point_and_id(p, id));
        finite_ids.push_back(id);
        magnitude_ = (std::max)({magnitude_, std::abs(p.x()), std::abs(p.y())});
      } else {
        // a Kd_tree cannot hold them; every query reports them
        non_finite_.push_back(id);
      }
    }
    points_in_tree_ = points_;
    tree_ids_.swap(finite_ids);
    tree_.reset();
    if(!pts.empty()) {
      // Kd_tree refuses to build on no points
      tree_.reset(new Tree(pts.begin(), pts.end(), Splitter(static_cast<unsigned int>(bucket_size_))));
      tree_->build();
    }
    dead_in_tree_ = 0;
    buffer_.clear();
    ++number_of_rebuilds_;
  }

  std::unique_ptr<Tree> tree_;
  std::vector<std::size_t> tree_ids_;      // the ids in the tree, live or dead
  std::vector<std::size_t> non_finite_;    // the ids held beside the tree, always reported
  std::size_t dead_in_tree_ = 0;
  std::vector<std::size_t> buffer_;        // the ids inserted since the last rebuild
  std::vector<State> state_;
  std::vector<bool> in_tree_;              // physically in the tree (or beside it), live or not
  std::vector<Approximate_point> points_, points_in_tree_;
  std::vector<double> reach_;
  std::size_t live_ = 0;
  double max_reach_ = 0;                   // at least every live point's reach
  double magnitude_ = 0;                   // of the coordinates in the tree
  std::size_t bucket_size_ = 10;
  std::size_t number_of_rebuilds_ = 0;
  mutable std::vector<Point_and_id> scratch_;
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_KD_TREE_POINT_INDEX_H
