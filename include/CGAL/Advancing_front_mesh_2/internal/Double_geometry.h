// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DOUBLE_GEOMETRY_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DOUBLE_GEOMETRY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Geometry in doubles, for the mesher's sizes, orders and filters. No
// combinatorial decision is taken from these values: the exact predicates
// (Front_predicates.h) take them.

// std::hypot without its cost where the plain formula cannot overflow or
// underflow (hypot was 4% of the meshing time)
inline double length(double dx, double dy)
{
  const double s = dx * dx + dy * dy;
  if(s > 1e-280 && s < 1e280) return std::sqrt(s);
  return std::hypot(dx, dy);
}

struct Circle
{
  double cx, cy, r;
};

// The circumcircle of the triangle (a, b, c); an infinite radius when the
// points coincide or a coordinate is not finite. With `error`, also a bound
// on how far the computed centre and radius may each lie from the true
// circumcircle's (infinite when the triangle is too flat for the double
// computation to bound anything): of the points whose coordinates these are
// exactly, or, with `coordinate_error` > 0, of points each of whose
// coordinates may lie that far from these.
inline Circle circle_of(double ax, double ay, double bx, double by, double cx, double cy, double* error = nullptr,
                        double coordinate_error = 0)
{
  // circumcircle relative to a, which keeps the rounding error small for
  // coordinates far from the origin
  // and in a frame scaled to unit size, so that the cubic terms neither
  // overflow nor underflow for very large or very small coordinates
  const double scale = (std::max)({std::abs(bx - ax), std::abs(by - ay), std::abs(cx - ax), std::abs(cy - ay)});
  if(!(scale > 0) || !std::isfinite(scale)) {
    if(error) *error = std::numeric_limits<double>::infinity();
    return Circle{ax, ay, std::numeric_limits<double>::infinity()};
  }
  const double bax = (bx - ax) / scale, bay = (by - ay) / scale, cax = (cx - ax) / scale, cay = (cy - ay) / scale;
  const double d = 2 * (bax * cay - bay * cax);
  const double b2 = bax * bax + bay * bay, c2 = cax * cax + cay * cay;
  const double ux = (cay * b2 - bay * c2) / d, uy = (bax * c2 - cax * b2) / d;
  const Circle c{ax + ux * scale, ay + uy * scale, length(ux, uy) * scale};
  if(error) {
    // Forward error analysis in units of u = 2^-53: the frame's
    // coordinates carry 2u (a subtraction, a division), the squares b2, c2
    // 7u, d's two products 5u each and their difference u more, so
    // |d - d*| <= 12u P with P = |bax cay| + |bay cax|; the numerators'
    // products 10u and their difference u, so |N - N*| <= 11u Q. While
    // |d| >= 24u P, |d*| >= |d| / 2 and the offset (ux, uy) is off by at
    // most 2 (11u Q + 12u P |ux|) / |d| + u |ux| per axis; scaling back and
    // adding a round each coordinate once more, the square root and the
    // product the radius three times. Doubled for the second-order terms.
    //
    // The coordinates' own error moves the frame's coordinates by at most
    // e = 2 coordinate_error / scale each (a difference of two points),
    // where all of them lie within 1 and b2, c2 within 2: d by at most
    // 2 (4e + 2e^2) <= 9e and each numerator by at most
    // 2 (2e + 4e + 2e^2 + e (4e + 2e^2)) <= 13e (for e <= 1e-3). While
    // |d| >= 2 (12u P + 9e), the offset is off by at most
    // 2 (13e + 9e |ux|) / |d| per axis more; the centre by that, scaled
    // back, and a's own error (2 coordinate_error covers its sqrt(2)), the
    // radius by the offset's part alone.
    const double u = std::ldexp(1., -53);
    const double e = 2 * coordinate_error / scale;
    const double P = std::abs(bax * cay) + std::abs(bay * cax);
    const double Qx = std::abs(cay) * b2 + std::abs(bay) * c2, Qy = std::abs(bax) * c2 + std::abs(cax) * b2;
    if(!(std::abs(d) >= 24 * u * P + 18 * e) || !(e <= 1e-3) || !std::isfinite(c.r)) {
      *error = std::numeric_limits<double>::infinity();
    } else {
      const double ex = 2 * (11 * u * Qx + 12 * u * P * std::abs(ux)) / std::abs(d) + u * std::abs(ux);
      const double ey = 2 * (11 * u * Qy + 12 * u * P * std::abs(uy)) / std::abs(d) + u * std::abs(uy);
      const double moved = coordinate_error > 0
                             ? 2 * (26 * e + 9 * e * (std::abs(ux) + std::abs(uy))) / std::abs(d) * scale +
                                 2 * coordinate_error
                             : 0;
      *error = 2 * ((ex + ey + u * (std::abs(ux) + std::abs(uy))) * scale + u * (std::abs(c.cx) + std::abs(c.cy)) +
                    3 * u * c.r + moved);
    }
  }
  return c;
}

// The distance from p to the segment [a, b].
inline double segment_distance(double px, double py, double ax, double ay, double bx, double by)
{
  const double dx = bx - ax, dy = by - ay;
  const double l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
  t = (std::max)(0., (std::min)(1., t));
  return length(px - (ax + t * dx), py - (ay + t * dy));
}

// The signed area of the triangle (a, b, c), positive when counter-clockwise.
inline double signed_area(double ax, double ay, double bx, double by, double cx, double cy)
{
  return 0.5 * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
}

// One implementation of the shape measure: the mesher's needle guard,
// mesh_quality() and the smoothing's guard use it.
// 2r/R of the triangle abc in double precision, 1 when equilateral, 0 when
// flat or degenerate. Lengths are divided by the longest edge first, so that
// neither the squared area nor the product of the lengths under- or
// overflows whatever the coordinates' scale.
inline double radius_ratio(double ax, double ay, double bx, double by, double cx, double cy)
{
  const double ux = bx - ax, uy = by - ay, vx = cx - ax, vy = cy - ay;
  const double a = std::hypot(cx - bx, cy - by), b = std::hypot(vx, vy), c = std::hypot(ux, uy);
  const double longest = (std::max)(a, (std::max)(b, c));
  if(!(longest > 0) || !std::isfinite(longest)) return 0;
  const double area2 = (ux / longest) * (vy / longest) - (uy / longest) * (vx / longest); // twice the area
  const double s = 0.5 * (a + b + c) / longest;
  const double rr = 2 * area2 * area2 / (s * (a / longest) * (b / longest) * (c / longest));
  return std::isfinite(rr) ? (std::min)(1., rr) : 0.;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_DOUBLE_GEOMETRY_H
