// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_GRADATION_LIMITER_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_GRADATION_LIMITER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Size_quadtree_2.h>

#include <functional>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Lowers the corner values of a Size_quadtree_2 so that
// the values of any two corners joined by a leaf side differ by at most
// `gradation` times their distance (the H-correction of Borouchaki et al.,
// done as a shortest-path computation as in Gmsh and JIGSAW). Bilinear
// interpolation then changes by at most `gradation` per unit length along
// each axis inside every leaf, so the sampled field is Lipschitz with
// constant sqrt(2) * gradation at worst.
//
// Hanging corners are not free: their value is the mean of their parents'.
// A hanging corner that must come down to t lowers its parents just enough
// for their mean to be t when one of them is already at most t (the case of
// a constraint coming from a parent along the side, which then allows the
// full slope along it); otherwise both parents come down to t, a little more
// than the mean needs. A parent that comes down lowers its hanging children.
// Values only decrease, and every constraint holds at the end.
//
// Returns the number of corners lowered.
// `length_scale` converts the tree's lengths to the values' units.
inline std::size_t limit_size_gradation(const Size_quadtree_2& tree, double gradation,
                                        std::vector<double>& value, double length_scale = 1.)
{
  typedef Size_quadtree_2::Corner Corner;
  const std::vector<Corner>& corners = tree.corners();
  const int n = int(corners.size());
  tree.interpolate_hanging_corners(value);

  std::vector<std::vector<int> > hanging_children(n);
  for(int i = 0; i < n; ++i)
    if(corners[i].is_hanging()) {
      hanging_children[corners[i].parent[0]].push_back(i);
      hanging_children[corners[i].parent[1]].push_back(i);
    }

  typedef std::pair<double, int> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  std::vector<char> lowered(n, 0);
  std::size_t number_lowered = 0;

  // Sets a free corner to at most t; a hanging corner passes it to its parents.
  std::function<void(int, double)> lower = [&](int i, double t) {
    if(corners[i].is_hanging()) {
      if(value[i] <= t) return;
      const int p = corners[i].parent[0], q = corners[i].parent[1];
      if(value[p] <= t) {
        lower(q, 2 * t - value[p]);
      } else if(value[q] <= t) {
        lower(p, 2 * t - value[q]);
      } else {
        lower(p, t);
        lower(q, t);
      }
      return;
    }
    if(value[i] <= t) return;
    value[i] = t;
    if(!lowered[i]) { lowered[i] = 1; ++number_lowered; }
    queue.emplace(t, i);
  };

  const double cell = tree.finest_cell_width() * length_scale;
  std::function<void(int)> relax_from = [&](int i) {
    const Corner& c = corners[i];
    for(int d = 0; d < 4; ++d)
      if(c.neighbor[d] >= 0) lower(c.neighbor[d], value[i] + gradation * (c.distance[d] * cell));
    for(int m : hanging_children[i]) {
      const double mean = 0.5 * (value[corners[m].parent[0]] + value[corners[m].parent[1]]);
      if(mean < value[m]) {
        value[m] = mean;
        relax_from(m);
      }
    }
  };

  // Hanging corners too: their neighbours must respect them even if they
  // never come down themselves.
  for(int i = 0; i < n; ++i) queue.emplace(value[i], i);
  while(!queue.empty()) {
    const Entry e = queue.top();
    queue.pop();
    if(e.first != value[e.second]) continue; // stale entry
    relax_from(e.second);
  }
  tree.interpolate_hanging_corners(value);
  return number_lowered;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_GRADATION_LIMITER_H
