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
#include <limits>
#include <utility>
#include <type_traits>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Internal coordinates are the user's less an origin, divided by
// 2^exponent; internal sizes are the user's divided by 2^exponent.
//
// The power of two, chosen so that a domain near 1e+300 or 1e-300 is meshed
// near 1: squared lengths and circle radii then neither overflow nor
// underflow, and the mesh is the one the same domain gets at unit scale. A
// power of two scales every double exactly.
//
// The origin, for a domain far from (0, 0) compared with its size (a unit
// square at 1e12): the searches pad their answers by a small fraction of
// the coordinates' magnitude, which would otherwise be the whole domain's
// width there and turn every search into a scan. The origin is taken on an
// axis only when every coordinate of the domain's box lies within 25% of it
// (well inside the factor of two of Sterbenz's lemma), so that the
// subtraction is exact for the input points and for every point the mesher
// makes inside the box; and only when every vertex's coordinates are
// doubles (always so with double coordinates; with other number types, when
// the user's points are): the searches' paddings, relative to the internal
// coordinates, would not cover to_double's rounding of other coordinates,
// which is relative to the user's magnitude. The mesher makes its points
// from doubles.
template <class Point>
class Coordinate_scaling
{
public:
  typedef typename Kernel_traits<Point>::Kernel::FT FT;

  int exponent() const { return exponent_; }
  double origin_x() const { return origin_x_; }
  double origin_y() const { return origin_y_; }
  void set(int exponent, double origin_x, double origin_y)
  {
    exponent_ = exponent;
    origin_x_ = origin_x;
    origin_y_ = origin_y;
  }

  // Are the internal coordinates the points themselves, moved and scaled
  // exactly? So with doubles (up to the rounding of the origin's
  // subtraction and the scaling, ruled out above), and with another number
  // type when every vertex's coordinates are doubles: the mesher makes its
  // points from doubles. Exact internal coordinates let the mesher bound
  // its double computations rigorously and answer predicates in doubles.
  bool exact() const { return std::is_same<FT, double>::value || exact_; }
  void set_exact(bool e) { exact_ = e; }

  // How far an internal coordinate may lie from the true one, in internal
  // units: 0 when exact(), else measured on the vertices when the scaling
  // was made (for_triangulation(); the mesher's own points are doubles),
  // and not a number when unknown.
  double coordinate_error() const { return exact() ? 0 : coordinate_error_; }

  // a length (a size, a radius): scaled, not moved
  double to_internal_length(const FT& v) const { return scaled(CGAL::to_double(v)); }
  double ix(const Point& p) const { return scaled(CGAL::to_double(p.x()) - origin_x_); }
  double iy(const Point& p) const { return scaled(CGAL::to_double(p.y()) - origin_y_); }

  Point to_user_point(double px, double py) const
  {
    if(exponent_ == 0) return Point(px + origin_x_, py + origin_y_);
    return Point(std::ldexp(px, exponent_) + origin_x_, std::ldexp(py, exponent_) + origin_y_);
  }

  // The origin and exponent for the triangulation's vertices.
  template <class Tr>
  static Coordinate_scaling for_triangulation(const Tr& tr)
  {
    double lo[2] = {0, 0}, hi[2] = {0, 0};
    bool first = true;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      const double c[2] = {CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())};
      for(int k = 0; k < 2; ++k) {
        lo[k] = first ? c[k] : (std::min)(lo[k], c[k]);
        hi[k] = first ? c[k] : (std::max)(hi[k], c[k]);
      }
      first = false;
    }
    Coordinate_scaling s;
    s.exact_ = coordinates_are_doubles(tr);
    if(s.exact_) {
      s.origin_x_ = origin_for(lo[0], hi[0]);
      s.origin_y_ = origin_for(lo[1], hi[1]);
    }
    s.exponent_ = s.exponent_for(tr);
    if(!s.exact_) s.coordinate_error_ = s.scaled(2 * largest_to_double_error(tr));
    return s;
  }

private:
  template <class Tr>
  static bool coordinates_are_doubles(const Tr& tr)
  {
    if(std::is_same<FT, double>::value) return true;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      if(FT(CGAL::to_double(v->point().x())) != v->point().x() ||
         FT(CGAL::to_double(v->point().y())) != v->point().y())
        return false;
    return true;
  }

  // The largest distance between a vertex coordinate and its to_double():
  // both lie in the coordinate's to_interval(), which is read after
  // to_double() (that may refine a lazy number's interval). CGAL promises
  // to_double() only to a relative 1e-5, but a number made by a few exact
  // operations on doubles (a point divided by 3) is known to a few units in
  // the last place, and the circles' error bounds must not be wider than
  // the mesh's triangles.
  template <class Tr>
  static double largest_to_double_error(const Tr& tr)
  {
    double largest = 0;
    auto measure = [&largest](const FT& c) {
      CGAL::to_double(c);
      const std::pair<double, double> i = CGAL::to_interval(c);
      largest = (std::max)(largest, i.second - i.first);
    };
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      measure(v->point().x());
      measure(v->point().y());
    }
    return largest;
  }

  double scaled(double d) const { return exponent_ == 0 ? d : std::ldexp(d, -exponent_); }

  // The origin of one axis whose coordinates span [lo, hi]: its midpoint
  // when the whole span lies within [o / 2, 2 o] with room to spare (the
  // points the mesher makes lie inside the span, up to rounding), else 0.
  static double origin_for(double lo, double hi)
  {
    if(!std::isfinite(lo) || !std::isfinite(hi)) return 0;
    const double o = 0.5 * lo + 0.5 * hi;
    const double half_width = 0.5 * hi - 0.5 * lo;
    // the span is small against |o|: lo >= 3/4 o and hi <= 5/4 o (for o > 0)
    if(!(half_width <= 0.25 * std::abs(o)) || !std::isfinite(o)) return 0;
    return o;
  }

  // The exponent for the largest internal coordinate magnitude m before
  // scaling: 0 while m lies within 2^(+-100) of 1, where nothing can
  // overflow, and otherwise the one that brings m to [1, 2), unless some
  // coordinate would not survive the scaling exactly (a domain spanning
  // 1e-300 to 1e+300).
  template <class Tr>
  int exponent_for(const Tr& tr) const
  {
    double m = 0;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      m = (std::max)({m, std::abs(CGAL::to_double(v->point().x()) - origin_x_),
                      std::abs(CGAL::to_double(v->point().y()) - origin_y_)});
    if(!(m > 0) || !std::isfinite(m) || (m < std::ldexp(1., 100) && m > std::ldexp(1., -100))) return 0;
    const int e = std::ilogb(m);
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
      for(const double c : {CGAL::to_double(v->point().x()) - origin_x_, CGAL::to_double(v->point().y()) - origin_y_})
        if(std::ldexp(std::ldexp(c, -e), e) != c) return 0;
    return e;
  }

  int exponent_ = 0;
  double origin_x_ = 0, origin_y_ = 0;
  bool exact_ = false;
  double coordinate_error_ = std::numeric_limits<double>::quiet_NaN();
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_COORDINATE_SCALING_H
