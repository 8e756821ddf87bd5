// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_NEIGHBOURHOOD_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_NEIGHBOURHOOD_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Step 4 of Mavriplis (1992): the front points close to an edge (the
// candidates of steps 5 and 11) and the front edges near them (for the
// visibility tests), gathered in a disk by one search of the point index.
template <class Front>
class Neighbourhood
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Edge_key Edge_key;
  typedef typename Context::Phase_scope Phase_scope;

  // A front edge near the disk, with its end points' coordinates copied
  // once, so that the many box tests of the visibility checks read them
  // from one small array.
  struct Near_edge
  {
    Edge_key key;
    double x0, y0, x1, y1;
  };

  Neighbourhood(Context& ctx, Front& front) : ctx_(ctx), front_(front) {}

  void gather(double x, double y, double r);
  bool still_on_front(Edge_key k) const;

  // The edges created since the gathering: they can block too.
  const std::vector<Edge_key>& new_edges() const { return front_.created_since_gather; }

  // Adds a vertex made after the gathering (the new point, inside the disk).
  void add_vertex(Vid v, double x, double y)
  {
    vertices.push_back(v);
    vertex_xy.push_back({{x, y}});
  }

  double cx = 0, cy = 0, radius = 0;
  std::vector<std::size_t> vertices;             // active vertices in the disk
  std::vector<std::array<double, 2> > vertex_xy; // their coordinates, in the same order
  std::vector<Near_edge> edges;                  // front edges meeting the disk when gathered, but
  std::vector<Vid> hubs;                         // the hubs near it, whose edges are not listed

private:
  Context& ctx_;
  Front& front_;
};

template <class Front>
void Neighbourhood<Front>::gather(double x, double y, double r)
{
  cx = x;
  cy = y;
  radius = r;
  vertices.clear();
  vertex_xy.clear();
  edges.clear();
  hubs.clear();
  front_.start_change_log();
  // One search finds the active vertices in the disk and, through the
  // vertices within their reach, the front edges whose diametral disk
  // meets it (they may pass through the disk with both end points far
  // away; the padding is the trees' own). A hub's edges are not listed:
  // the visibility tests find the few that matter by direction
  // (Front_hubs.h). The hub is found through its own reach, which covers
  // all its edges.
  Phase_scope phase(ctx_.timer, CLOSE_POINT_SEARCH);
  const double pad = 1e-12 * (std::abs(x) + std::abs(y));
  front_.active_points.query_with_reach(x, y, r, [this, x, y, r, pad](std::size_t id, double px, double py,
                                                                      bool in_disk) {
    if(in_disk) {
      vertices.push_back(id);
      vertex_xy.push_back({{px, py}});
    }
    const bool any_hubs = !front_.hubs.empty();
    if(any_hubs && front_.is_hub(Vid(id))) {
      hubs.push_back(Vid(id));
      return;
    }
    for(Vid h : front_.out[Vid(id)]) {
      if(any_hubs && front_.is_hub(h)) continue;
      const double hx = front_.x(h), hy = front_.y(h);
      const double dx = 0.5 * (px + hx) - x, dy = 0.5 * (py + hy) - y;
      const double reach = (0.5 * length(hx - px, hy - py) + r) * (1 + 1e-9) + pad +
                           1e-12 * (std::abs(px) + std::abs(py) + std::abs(hx) + std::abs(hy));
      // written so that an edge whose test cannot be computed is kept
      if(!(dx * dx + dy * dy > reach * reach)) edges.push_back(Near_edge{Front::key(Vid(id), h), px, py, hx, hy});
    }
  });
  ++ctx_.stats.point_search_queries;
}

// Is k, a front edge of `edges` or `new_edges()`, still on the front? It is
// unless it was removed since the gathering (and not created again); the
// few removals since are scanned instead of probing the front's hash table,
// whose probes miss the cache on large fronts.
template <class Front>
bool Neighbourhood<Front>::still_on_front(Edge_key k) const
{
  const std::vector<Edge_key>& removed = front_.removed_since_gather;
  if(removed.size() > 8) return front_.contains(k);
  for(Edge_key e : removed)
    if(e == k) return front_.contains(k);
  return true;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_NEIGHBOURHOOD_H
