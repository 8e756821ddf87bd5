// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_POCKETS_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_POCKETS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Our order of the queue, not the paper's: the pockets of the front first.
//
// With a uniform size, the lengths of the front edges differ by rounding
// only, and shortest-first grows the mesh like a crystal: patches advance as
// spikes that close around pockets of unmeshed region, whose slightly
// longer edges wait. Left alone, the pockets pile up behind the advancing
// spikes and the front grows in proportion to the mesh (40k edges at 1M
// triangles), not to its perimeter. After a step that split or joined loops
// of the front (see Front_triangles::make_triangle()), the loops through the
// edges it created are walked in step, at most `walk_limit` edges each;
// those that close within the limit are taken for pockets (also a loop just
// joined from two small ones, or the whole front near the end: the order
// within them is unchanged). Their edges, and the edges created while
// processing them, go one level up in the queue: before all edges of lower
// levels, so that a pocket is meshed soon after it forms (and a pocket
// within it sooner still). Only the order changes: every edge is still
// processed by the same rules.
template <class Front>
class Pockets
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Edge_key Edge_key;
  typedef typename Front::Front_edge Front_edge;
  static constexpr std::size_t walk_limit = 1024;

  Pockets(Context& ctx, Front& front) : ctx_(ctx), front_(front) {}

  void mark();
  void clear() { walks_.clear(); }

private:
  // A walk along a loop of the front: state 0 walking, 1 closed, 2 open (or
  // unknown), 3 stopped on the loop of another walk.
  struct Walk
  {
    Edge_key start;
    Vid at;
    std::size_t length;
    int state;
  };

  void start_walk(Edge_key k);
  void walk_loops();
  void promote_closed_loops();

  Context& ctx_;
  Front& front_;
  std::vector<Walk> walks_;
};

template <class Front>
void Pockets<Front>::mark()
{
  walks_.clear();
  for(Edge_key k : front_.created_this_step) {
    if(!front_.contains(k)) continue;
    start_walk(k);
    // A walk stops at a vertex where loops meet, so the loop that leaves
    // such a vertex is walked from there: after a closure of a -> b on a
    // vertex c of its own loop, the loop through the new edge a -> c is
    // walked from c's older edge, and closes back at c.
    const Vid v = Front::target(k);
    if(front_.out[v].size() > 1)
      for(Vid w : front_.out[v]) start_walk(Front::key(v, w));
  }
  walk_loops();
  promote_closed_loops();
}

template <class Front>
void Pockets<Front>::start_walk(Edge_key k)
{
  for(const Walk& w : walks_)
    if(w.start == k) return;
  walks_.push_back(Walk{k, Front::target(k), 1, 0});
}

// All walks go on in step until each has closed, given up or met another.
template <class Front>
void Pockets<Front>::walk_loops()
{
  std::size_t walking = walks_.size();
  while(walking > 0) {
    for(Walk& w : walks_) {
      if(w.state != 0) continue;
      if(w.at == Front::source(w.start)) w.state = 1;
      // a vertex where loops meet: its successor depends on the geometry;
      // the walk gives up and the loop counts as open
      else if(front_.out[w.at].size() != 1 || w.length >= walk_limit) w.state = 2;
      else {
        // a walk that starts here is on this walk's loop: it can stop
        for(Walk& o : walks_)
          if(o.state == 0 && Front::source(o.start) == w.at) {
            o.state = 3;
            --walking;
          }
        w.at = front_.out[w.at].begin()[0];
        ++w.length;
        continue;
      }
      --walking;
    }
  }
}

// Every loop that closed is promoted, also when no walk found a larger one
// (a loop just joined, a small front at the end): requiring a larger loop
// beside it measured a little worse on the benchmark's square (share of
// radius ratios above 0.9), for the same front size.
template <class Front>
void Pockets<Front>::promote_closed_loops()
{
  const std::uint16_t level =
    (front_.level < (std::numeric_limits<std::uint16_t>::max)()) ? front_.level + 1 : front_.level;
  for(const Walk& walk : walks_) {
    if(walk.state != 1) continue;
    Front_edge* first = front_.find(walk.start);
    if(first->level >= level) continue; // the loop of an earlier walk
    ++ctx_.stats.pockets;
    Vid u = Front::source(walk.start), w = Front::target(walk.start);
    do {
      Front_edge* fe = front_.find(Front::key(u, w));
      CGAL_assertion(fe != nullptr);
      fe->level = level;
      // a new version makes the edge's old queue entry stale
      fe->version = ++front_.version_counter;
      front_.push(Front::key(u, w), *fe);
      u = w;
      w = front_.out[u].begin()[0];
    } while(u != Front::source(walk.start));
  }
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_POCKETS_H
