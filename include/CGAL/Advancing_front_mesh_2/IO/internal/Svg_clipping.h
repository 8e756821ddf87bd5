// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_CLIPPING_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_CLIPPING_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// The rectangle drawn, and the larger one beyond which lines are clipped, in
// mesh coordinates.
struct Svg_box
{
  double xmin, ymin, xmax, ymax;
};

inline int svg_outcode(const std::array<double, 2>& p, const Svg_box& b)
{
  int c = 0;
  if(p[0] < b.xmin) c |= 1; else if(p[0] > b.xmax) c |= 2;
  if(p[1] < b.ymin) c |= 4; else if(p[1] > b.ymax) c |= 8;
  return c;
}

// Liang-Barsky. Clipping far-away endpoints keeps the numbers in the file
// within a few picture sizes: renderers work in single precision and draw
// garbage for coordinates far outside the viewport.
inline bool svg_clip_segment(std::array<double, 2>& p, std::array<double, 2>& q,
                             const Svg_box& b)
{
  const double dx = q[0] - p[0], dy = q[1] - p[1];
  const double pk[4] = {-dx, dx, -dy, dy};
  const double qk[4] = {p[0] - b.xmin, b.xmax - p[0], p[1] - b.ymin, b.ymax - p[1]};
  double t0 = 0, t1 = 1;
  for(int k = 0; k < 4; ++k) {
    if(pk[k] == 0) {
      if(qk[k] < 0)
        return false;
    } else {
      const double r = qk[k] / pk[k];
      if(pk[k] < 0) {
        if(r > t1) return false;
        if(r > t0) t0 = r;
      } else {
        if(r < t0) return false;
        if(r < t1) t1 = r;
      }
    }
  }
  const std::array<double, 2> a{{p[0] + t0 * dx, p[1] + t0 * dy}};
  const std::array<double, 2> c{{p[0] + t1 * dx, p[1] + t1 * dy}};
  p = a;
  q = c;
  return true;
}

// Sutherland-Hodgman against the four sides of a box. For points inside the
// box the winding number is preserved, which is all the nonzero fill rule
// looks at, so clipped boundary loops still fill the right region.
inline void svg_clip_polygon(std::vector<std::array<double, 2> >& poly,
                             const Svg_box& b)
{
  std::vector<std::array<double, 2> > out;
  for(int side = 0; side < 4 && !poly.empty(); ++side) {
    const int axis = side / 2;
    const double bound = (side == 0) ? b.xmin : (side == 1) ? b.xmax
                       : (side == 2) ? b.ymin : b.ymax;
    const bool keep_above = (side % 2 == 0);
    auto inside = [&](const std::array<double, 2>& p) {
      return keep_above ? p[axis] >= bound : p[axis] <= bound;
    };
    auto cut = [&](const std::array<double, 2>& p, const std::array<double, 2>& q) {
      const double t = (bound - p[axis]) / (q[axis] - p[axis]);
      std::array<double, 2> r;
      r[axis] = bound;
      r[1 - axis] = p[1 - axis] + t * (q[1 - axis] - p[1 - axis]);
      return r;
    };
    out.clear();
    const std::size_t n = poly.size();
    for(std::size_t i = 0; i < n; ++i) {
      const std::array<double, 2>& cur = poly[i];
      const std::array<double, 2>& prev = poly[(i + n - 1) % n];
      const bool cin = inside(cur), pin = inside(prev);
      if(cin) {
        if(!pin)
          out.push_back(cut(prev, cur));
        out.push_back(cur);
      } else if(pin) {
        out.push_back(cut(prev, cur));
      }
    }
    poly.swap(out);
  }
}

} // namespace internal

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_CLIPPING_H
