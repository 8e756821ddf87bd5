// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_HUBS_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_HUBS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Calls f(x) for the x of [first, last), sorted by the direction of
// point_of(x) about pv (Front_predicates::direction_before()), whose
// direction lies in the closed counter-clockwise arc from direction
// pv->from to direction pv->to (the caller makes it shorter than a half
// turn, or a single direction), until f returns true; returns whether it
// did. Two binary searches find the arc.
template <class Iterator, class Point, class PointOf, class Predicates, class Function>
bool any_in_direction_arc(Iterator first, Iterator last, const Point& pv, const Point& from, const Point& to,
                          const PointOf& point_of, const Predicates& pred, const Function& f)
{
  typedef typename std::iterator_traits<Iterator>::value_type Value;
  const Iterator begin = std::partition_point(first, last, [&](const Value& x) {
    return pred.direction_before(pv, point_of(x), from);
  });
  const Iterator end = std::partition_point(first, last, [&](const Value& x) {
    return !pred.direction_before(pv, to, point_of(x));
  });
  if(!pred.direction_before(pv, to, from)) // the arc does not pass the x axis
    return std::any_of(begin, end, f);
  return std::any_of(begin, last, f) || std::any_of(first, end, f);
}

// The front vertices where many front edges meet ("hubs"), each with its
// front edges ("spokes") sorted by direction.
//
// Where n input constraints meet at a vertex (the centre of a star), 2n
// front edges meet there, and every neighbourhood near it held them all:
// each visibility test scanned them, and a star of 4,000 spokes cost 76
// times the square's time per triangle. A spoke can only meet a segment
// that does not end at the hub if its direction lies in the cone the
// segment spans from the hub; sorted by direction, those spokes are found
// by two binary searches, and the hub's edges are left out of the gathered
// neighbourhoods (Neighbourhood.h).
//
// The order uses the exact predicates only (Front_predicates::
// direction_before()); equal directions (the two sides of a constraint)
// are ordered outgoing first, then by vertex id, so that the order is a
// function of the front alone (a checkpoint rebuilds the same). No answer
// depends on that tie order.
template <class Point, class Predicates>
class Front_hubs
{
public:
  typedef std::uint32_t Vid;

  // A vertex is a hub while it has at least this many outgoing front edges
  // (below, scanning its edges costs about what the cone search does).
  static constexpr std::size_t min_out_degree = 32;

  struct Spoke
  {
    Vid other;     // the edge's other end point
    bool outgoing; // the edge leaves the hub
  };
  typedef std::vector<Spoke> Spokes;

  bool empty() const { return spokes_.empty(); }
  std::size_t size() const { return spokes_.size(); }
  // asked for nearly every vertex the searches meet: a flag, not a lookup
  bool contains(Vid v) const { return v < is_hub_.size() && is_hub_[v] != 0; }
  const Spokes& spokes(Vid v) const
  {
    CGAL_precondition(contains(v));
    return spokes_.find(v)->second;
  }
  void clear()
  {
    spokes_.clear();
    is_hub_.clear();
  }

  // Makes v a hub with the given front edges (targets of its outgoing ones,
  // sources of its incoming ones).
  template <class Ids, class PointOf>
  void make(Vid v, const Ids& out, const Ids& in, const PointOf& point_of, const Predicates& pred)
  {
    if(v >= is_hub_.size()) is_hub_.resize(std::size_t(v) + 1, 0);
    is_hub_[v] = 1;
    Spokes& s = spokes_[v];
    s.clear();
    for(Vid w : out) s.push_back(Spoke{w, true});
    for(Vid w : in) s.push_back(Spoke{w, false});
    std::sort(s.begin(), s.end(), order(point_of(v), point_of, pred));
  }

  void unmake(Vid v)
  {
    spokes_.erase(v);
    is_hub_[v] = 0;
  }

  template <class PointOf>
  void insert(Vid v, Vid w, bool outgoing, const PointOf& point_of, const Predicates& pred)
  {
    Spokes& s = spokes_.find(v)->second;
    const Spoke added{w, outgoing};
    s.insert(std::upper_bound(s.begin(), s.end(), added, order(point_of(v), point_of, pred)), added);
  }

  void erase(Vid v, Vid w, bool outgoing)
  {
    Spokes& s = spokes_.find(v)->second;
    const auto it = std::find_if(s.begin(), s.end(),
                                 [w, outgoing](const Spoke& k) { return k.other == w && k.outgoing == outgoing; });
    CGAL_assertion(it != s.end());
    s.erase(it);
  }

  // Calls f(spoke) for the spokes of hub v whose direction lies in the
  // closed counter-clockwise arc from direction v->from to direction v->to
  // (the caller makes it shorter than a half turn, or a single direction),
  // until f returns true; returns whether it did.
  template <class PointOf, class Function>
  bool any_in_arc(Vid v, const Point& from, const Point& to, const PointOf& point_of, const Predicates& pred,
                  const Function& f) const
  {
    const Spokes& s = spokes(v);
    return any_in_direction_arc(s.begin(), s.end(), point_of(v), from, to,
                                [&](const Spoke& k) -> const Point& { return point_of(k.other); }, pred, f);
  }

private:
  template <class PointOf>
  struct Order
  {
    const Point& pv;
    const PointOf& point_of;
    const Predicates& pred;
    bool operator()(const Spoke& a, const Spoke& b) const
    {
      const Point& pa = point_of(a.other);
      const Point& pb = point_of(b.other);
      if(pred.direction_before(pv, pa, pb)) return true;
      if(pred.direction_before(pv, pb, pa)) return false;
      if(a.outgoing != b.outgoing) return a.outgoing;
      return a.other < b.other;
    }
  };
  template <class PointOf>
  static Order<PointOf> order(const Point& pv, const PointOf& point_of, const Predicates& pred)
  {
    return Order<PointOf>{pv, point_of, pred};
  }

  std::unordered_map<Vid, Spokes> spokes_;
  std::vector<unsigned char> is_hub_; // by vertex id
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_HUBS_H
