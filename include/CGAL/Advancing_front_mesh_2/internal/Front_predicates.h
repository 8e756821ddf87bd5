// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_PREDICATES_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_PREDICATES_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Kernel_23/internal/Has_boolean_tags.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The combinatorial tests of the advancing front, written only with the
// traits' exact predicates (orientation, angle, collinear ordering), so that
// every decision is exact whatever the kernel's number type.
//
// With traits whose predicates are not filtered (Simple_cartesian<
// Exact_rational>, which computes every test in rationals: a star of 1,000
// constraints took 2.6 s against Epick's 0.11 s) and points whose
// coordinates are all doubles (the mesher makes its points from doubles,
// and input read from a file is doubles), the three predicates the mesher
// calls most (orientation, angle, in-circle) are answered by Epick's on the
// same doubles: exact too, since the doubles are the points, and filtered.
// The owner says when the coordinates are doubles
// (set_coordinates_are_doubles()). Filtered traits (Epick, Epeck) keep
// their own predicates: Epeck's compare its points' stored intervals,
// cheaper than reading a lazy point's coordinates.
template <class GeomTraits>
class Front_predicates
{
public:
  typedef typename GeomTraits::Point_2 Point;

  explicit Front_predicates(const GeomTraits& gt = GeomTraits()) : gt_(gt) {}

  // Every point these predicates will be asked about has coordinates that
  // are doubles (to_double() is exact for them).
  void set_coordinates_are_doubles(bool yes) { doubles_ = yes && !filtered; }

  Orientation orientation(const Point& a, const Point& b, const Point& c) const
  {
    if(doubles_) return Epick().orientation_2_object()(as_double(a), as_double(b), as_double(c));
    return gt_.orientation_2_object()(a, b, c);
  }

  // Position of direction d in the counter-clockwise turn about v that
  // starts just after direction ref: 0 for angles in (0, pi), 1 for pi,
  // 2 for (pi, 2 pi), 3 for 2 pi (same direction as ref).
  int turn_region(const Point& v, const Point& ref, const Point& d) const
  {
    const Orientation o = orientation(v, ref, d);
    if(o == LEFT_TURN) return 0;
    if(o == RIGHT_TURN) return 2;
    return angle(ref, v, d) == OBTUSE ? 1 : 3;
  }

  // Does direction v->a come strictly before v->b when turning
  // counter-clockwise from v->ref (angles measured in (0, 2 pi])?
  bool turns_before(const Point& v, const Point& ref, const Point& a, const Point& b) const
  {
    const int ra = turn_region(v, ref, a), rb = turn_region(v, ref, b);
    if(ra != rb) return ra < rb;
    if(ra == 0 || ra == 2) return orientation(v, a, b) == LEFT_TURN;
    return false;
  }

  // Does direction v->a come strictly before v->b in the counter-clockwise
  // turn that starts at the direction of the positive x axis (angles in
  // [0, 2 pi))? Equal directions are equivalent: a strict weak order of the
  // directions about v, in which the front edges at a hub are sorted.
  bool direction_before(const Point& v, const Point& a, const Point& b) const
  {
    const bool upper_a = in_upper_half(v, a), upper_b = in_upper_half(v, b);
    if(upper_a != upper_b) return upper_a;
    return orientation(v, a, b) == LEFT_TURN;
  }

  // Is q on the closed segment [a, b], knowing a, b, q collinear?
  bool collinear_on_segment(const Point& a, const Point& b, const Point& q) const
  {
    return gt_.collinear_are_ordered_along_line_2_object()(a, q, b);
  }

  // Is q in the open segment (a, b)?
  bool in_open_segment(const Point& a, const Point& b, const Point& q) const
  {
    return orientation(a, b, q) == COLLINEAR &&
           gt_.collinear_are_strictly_ordered_along_line_2_object()(a, q, b);
  }

  // Do the closed segments [p1, p2] and [q1, q2] share a point?
  bool closed_segments_meet(const Point& p1, const Point& p2,
                            const Point& q1, const Point& q2) const
  {
    const Orientation o1 = orientation(p1, p2, q1), o2 = orientation(p1, p2, q2);
    if(o1 != COLLINEAR && o1 == o2) return false;
    const Orientation o3 = orientation(q1, q2, p1), o4 = orientation(q1, q2, p2);
    if(o3 != COLLINEAR && o3 == o4) return false;
    if(o1 != COLLINEAR || o2 != COLLINEAR) return true; // proper or touching crossing
    // all four collinear: they meet iff their extents overlap
    return collinear_on_segment(p1, p2, q1) || collinear_on_segment(p1, p2, q2) ||
           collinear_on_segment(q1, q2, p1);
  }

  // Does the segment from s to t overlap, beyond s, the segment from s to o
  // (both starting at the shared end point s)?
  bool overlap_from_shared_end(const Point& s, const Point& o, const Point& t) const
  {
    return orientation(s, o, t) == COLLINEAR && angle(o, s, t) == ACUTE;
  }

  // Is d strictly inside the circle through a, b, c (counter-clockwise)?
  bool strictly_inside_circle(const Point& a, const Point& b, const Point& c, const Point& d) const
  {
    if(doubles_)
      return Epick().side_of_oriented_circle_2_object()(as_double(a), as_double(b), as_double(c), as_double(d)) ==
             ON_POSITIVE_SIDE;
    return gt_.side_of_oriented_circle_2_object()(a, b, c, d) == ON_POSITIVE_SIDE;
  }

  const GeomTraits& traits() const { return gt_; }

private:
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
  static constexpr bool filtered = CGAL::internal::Has_filtered_predicates<GeomTraits>::value;

  static Epick::Point_2 as_double(const Point& p) { return Epick::Point_2(CGAL::to_double(p.x()), CGAL::to_double(p.y())); }

  Angle angle(const Point& a, const Point& b, const Point& c) const
  {
    if(doubles_) return Epick().angle_2_object()(as_double(a), as_double(b), as_double(c));
    return gt_.angle_2_object()(a, b, c);
  }

  // Is the direction v->a in [0, pi), i.e. above v or level with it and to
  // its right?
  bool in_upper_half(const Point& v, const Point& a) const
  {
    const Comparison_result cy = gt_.compare_y_2_object()(a, v);
    return cy == LARGER || (cy == EQUAL && gt_.compare_x_2_object()(a, v) == LARGER);
  }

  GeomTraits gt_;
  bool doubles_ = false;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_PREDICATES_H
