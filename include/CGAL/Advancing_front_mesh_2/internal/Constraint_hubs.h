// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CONSTRAINT_HUBS_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CONSTRAINT_HUBS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Front_hubs.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The input vertices where many constraints meet, each with the other end
// points of its constraints sorted by direction.
//
// The index of the constraints' diametral circles answers "which
// constraints may cross this segment" (Front_visibility::sees_point());
// near the centre of a star every spoke's circle is near, and each new
// point's cavity tested all of them. A hub's constraints enter that index
// as one circle about the hub that holds them all, and only those whose
// direction lies in the cone the segment spans from the hub are tested.
template <class Vertex_handle, class Predicates>
class Constraint_hubs
{
public:
  // a vertex with at least this many constraints is a hub
  static constexpr std::size_t min_degree = 32;

  bool empty() const { return spokes_.empty(); }
  std::size_t size() const { return spokes_.size(); }
  void clear() { spokes_.clear(); }

  // f(hub, other end points) for every hub, in no particular order
  template <class Function>
  void for_each(Function f) const
  {
    for(const auto& h : spokes_) f(h.second.first, h.second.second);
  }

  // Makes `hub` a hub with constraints to `others` (in any order).
  void add(Vertex_handle hub, std::vector<Vertex_handle> others, const Predicates& pred)
  {
    std::sort(others.begin(), others.end(), [&](const Vertex_handle& a, const Vertex_handle& b) {
      return pred.direction_before(hub->point(), a->point(), b->point());
    });
    spokes_[&*hub] = std::make_pair(hub, std::move(others));
  }

  bool contains(const Vertex_handle& v) const { return spokes_.count(&*v) != 0; }

  // Calls f(w) for the constraints hub-w whose direction lies in the closed
  // counter-clockwise arc from direction hub->from to hub->to (shorter than
  // a half turn, or one direction), until f returns true; returns whether
  // it did.
  template <class Point, class Function>
  bool any_in_arc(const Vertex_handle& hub, const Point& from, const Point& to, const Predicates& pred,
                  const Function& f) const
  {
    CGAL_precondition(contains(hub));
    const std::vector<Vertex_handle>& s = spokes_.find(&*hub)->second.second;
    return any_in_direction_arc(s.begin(), s.end(), hub->point(), from, to,
                                [](const Vertex_handle& w) -> const Point& { return w->point(); }, pred, f);
  }

private:
  std::unordered_map<const void*, std::pair<Vertex_handle, std::vector<Vertex_handle> > > spokes_;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_CONSTRAINT_HUBS_H
