// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_LAWSON_FLIPS_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_LAWSON_FLIPS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Lawson's flips (Lawson 1972), the one implementation of the package: the
// mesher's final check and the smoothing's edge swapping use it.

// Lawson's flips, starting from the edges on `stack`, on the edges between
// two finite in-domain faces until every edge reached is locally Delaunay
// (strictly: cocircular quadrilaterals are left alone). Constrained edges are
// never flipped. Calls `on_flip(f, g)` after each flip, f and g the two faces
// (now sharing the new diagonal). Returns the number of flips.
template <class CDT, class On_flip>
std::size_t lawson_flips(CDT& cdt, std::vector<typename CDT::Edge>& stack, const On_flip& on_flip)
{
  typedef typename CDT::Face_handle Face_handle;
  std::size_t flips = 0;
  while(!stack.empty()) {
    Face_handle f = stack.back().first; // flip() takes a reference
    const int i = stack.back().second;
    stack.pop_back();
    const Face_handle g = f->neighbor(i);
    if(!f->is_in_domain() || cdt.is_infinite(f) || cdt.is_infinite(g) || !g->is_in_domain()) continue;
    if(!cdt.is_flipable(f, i, false)) continue;
    cdt.flip(f, i);
    ++flips;
    on_flip(f, g);
    // the four edges of the new quadrilateral's sides
    for(Face_handle h : {f, g})
      for(int k = 0; k < 3; ++k)
        if(h->neighbor(k) != f && h->neighbor(k) != g) stack.emplace_back(h, k);
  }
  return flips;
}

// Lawson's flips over the whole triangulation's in-domain faces; returns
// the number of flips. Each edge is seeded once, from the face with the
// smaller address, and flipped at once with what its flips reach, so the
// stack holds the flips' edges, not the mesh's (a stack of every edge was
// 48 bytes per triangle, the largest allocation of a whole meshing run).
template <class CDT>
std::size_t restore_constrained_delaunay(CDT& cdt)
{
  typedef typename CDT::Face_handle Face_handle;
  std::vector<typename CDT::Edge> stack;
  std::size_t flips = 0;
  for(auto fit = cdt.finite_faces_begin(); fit != cdt.finite_faces_end(); ++fit) {
    const Face_handle f = fit;
    if(!f->is_in_domain()) continue;
    for(int i = 0; i < 3; ++i) {
      if(&*f->neighbor(i) < &*f) continue;
      stack.emplace_back(f, i);
      flips += lawson_flips(cdt, stack, [](Face_handle, Face_handle) {});
    }
  }
  return flips;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_LAWSON_FLIPS_H
