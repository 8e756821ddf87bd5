// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_COORDINATE_SCALING_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_COORDINATE_SCALING_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Internal coordinates and sizes are the user's divided by 2^exponent,
// chosen so that a domain near 1e+300 or 1e-300 is meshed near 1: squared
// lengths and circle radii then neither overflow nor underflow, and the
// mesh is the one the same domain gets at unit scale. A power of two
// scales every double exactly, so the internal coordinates stay exact.
template <class Point>
class Coordinate_scaling
{
public:
  typedef typename Kernel_traits<Point>::Kernel::FT FT;

  int exponent() const { return exponent_; }
  void set_exponent(int e) { exponent_ = e; }

  double to_internal(const FT& v) const
  {
    const double d = CGAL::to_double(v);
    return exponent_ == 0 ? d : std::ldexp(d, -exponent_);
  }
  double ix(const Point& p) const { return to_internal(p.x()); }
  double iy(const Point& p) const { return to_internal(p.y()); }

  Point to_user_point(double px, double py) const
  {
    if(exponent_ == 0) return Point(px, py);
    return Point(std::ldexp(px, exponent_), std::ldexp(py, exponent_));
  }

  // The exponent for the largest coordinate magnitude m of the
  // triangulation's vertices: 0 while m lies within 2^(+-100) of 1, where
  // nothing can overflow, and otherwise the one that brings m to [1, 2),
  // unless some input coordinate would not survive the scaling exactly (a
  // domain spanning 1e-300 to 1e+300).
  template <class Tr>
  static int exponent_for(const Tr& tr)
  {
    double m = 0;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      m = (std::max)({m, std::abs(CGAL::to_double(v->point().x())), std::abs(CGAL::to_double(v->point().y()))});
    if(!(m > 0) || !std::isfinite(m) || (m < std::ldexp(1., 100) && m > std::ldexp(1., -100))) return 0;
    const int e = std::ilogb(m);
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      for(const double c : {CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())})
        if(std::ldexp(std::ldexp(c, -e), e) != c) return 0;
    return e;
  }

private:
  int exponent_ = 0;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_COORDINATE_SCALING_H
