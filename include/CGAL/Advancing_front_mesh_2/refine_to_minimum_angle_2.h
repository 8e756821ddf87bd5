// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_REFINE_TO_MINIMUM_ANGLE_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_REFINE_TO_MINIMUM_ANGLE_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/number_utils.h>

#include <array>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

What `refine_to_minimum_angle_2()` did. Counts are of the faces in the
domain (`is_in_domain()`).
*/
struct Minimum_angle_statistics
{
  /// the bound asked for, in degrees
  double angle = 0;
  /// triangles before and after
  std::size_t triangles_before = 0, triangles_after = 0;
  /// triangles with an angle below the bound, before and after (after: the
  /// exceptions, see `refine_to_minimum_angle_2()`)
  std::size_t below_before = 0, below_after = 0;
  /// vertices the refinement inserted (circumcentres and segment midpoints)
  std::size_t points_inserted = 0;
  /// triangles of the result that were not triangles of the mesh before:
  /// the part of the mesh the refinement changed
  std::size_t triangles_changed = 0;
  /// the smallest angle of the result, in degrees
  double smallest_angle = 0;
  /// `false` when the insertion limit stopped the refinement (the mesh is
  /// valid, with `below_after` triangles left below the bound)
  bool completed = true;
};

namespace internal {

// The smallest angle of a triangle, in degrees (doubles: a report, not a
// decision).
template <class Point>
double smallest_angle_degrees(const Point& a, const Point& b, const Point& c)
{
  const std::array<std::array<double, 2>, 3> p{{{{CGAL::to_double(a.x()), CGAL::to_double(a.y())}},
                                                {{CGAL::to_double(b.x()), CGAL::to_double(b.y())}},
                                                {{CGAL::to_double(c.x()), CGAL::to_double(c.y())}}}};
  double smallest = 180;
  for(int i = 0; i < 3; ++i) {
    const auto& o = p[i];
    const auto& u = p[(i + 1) % 3];
    const auto& w = p[(i + 2) % 3];
    double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
    // each side scaled to at most 1, so that neither the products overflow
    // near 1e300 nor underflow near 1e-300 (the angle does not change)
    const double su = (std::max)(std::abs(ux), std::abs(uy)), sw = (std::max)(std::abs(wx), std::abs(wy));
    if(!(su > 0) || !(sw > 0)) return 0;
    ux /= su;
    uy /= su;
    wx /= sw;
    wy /= sw;
    // atan2 of cross and dot: accurate for tiny angles too
    const double angle = std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / CGAL_PI;
    smallest = (std::min)(smallest, angle);
  }
  return smallest;
}

template <class CDT>
std::array<typename CDT::Vertex_handle, 3> sorted_vertices(typename CDT::Face_handle f)
{
  std::array<typename CDT::Vertex_handle, 3> v{{f->vertex(0), f->vertex(1), f->vertex(2)}};
  std::sort(v.begin(), v.end());
  return v;
}

// Mesh_2's refinement step by step, at most `limit` insertions.
template <class Mesher>
bool refine_with_limit(Mesher& mesher, std::size_t limit)
{
  mesher.init(true); // the domain marks as they are
  std::size_t steps = 0;
  while(!mesher.is_refinement_done()) {
    if(steps++ == limit) return false;
    mesher.step_by_step_refine_mesh();
  }
  return true;
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Raises the smallest angle of the mesh in `cdt` to `degrees` by local
Delaunay refinement, after the frontal pass: the triangles of the domain
with an angle below the bound, usually few, get their circumcentres inserted
(Ruppert's and Shewchuk's algorithm, as CGAL's Mesh_2 implements it, with
Mesh_2's clusters at small input angles); where a circumcentre would
encroach on a constrained edge, the edge is split at its midpoint instead
(`split_constraints == true`), or the circumcentre is not inserted
(`split_constraints == false`, the paper's mode, where every input segment
stays an edge). The rest of the mesh, the frontal mesh, is not touched, and
the result is a constrained Delaunay triangulation again. The domain is the
one marked in `cdt` (`is_in_domain()`), as the mesher leaves it.

<b>What is guaranteed.</b> With `split_constraints`, every triangle of the
result has its angles at or above the bound, except triangles at small input
angles: the refinement cannot remove an angle smaller than the bound that
the input itself makes between two constraints, and next to input angles
under about 60 degrees Mesh_2's clusters leave some triangles below the
bound by design (that is how they keep the refinement finite). Without
`split_constraints`, triangles whose circumcentre encroaches on a kept
segment (input features closer together than the local size) stay as they
are too. Ruppert's proof of termination covers bounds up to 20.7 degrees
(Mesh_2's documented bound); above it, up to 30 degrees, Delaunay refinement
terminates in practice (Triangle offers up to about 33), and this package
measured it on every geometry of its tests, the shared data and 10,000
random domains. As a safeguard against inputs beyond those, at most
`max_insertions` points are inserted (0: ten per triangle of the domain
plus a thousand); `completed` then says whether the bound was reached.
Mesh_2 tests the shape and places circumcentres in double precision (with
`Epick`): where coordinates exceed about 1e150 or triangles are smaller than
about 1e-150, those overflow or underflow, and the refinement leaves such
triangles as they are (they are counted in `below_after`).

Triangles below the bound that are left, measured: none on the tests'
catalogue of hard inputs (slits of width 1e-7, nearly collinear boundaries,
boundary spacings varying by 1e4, holes among tiny holes), and on 10,000
random domains with `split_constraints`, every triangle left below 30
degrees has a vertex within one local size of an input vertex where two
input segments meet at less than 60 degrees; the tests assert this with two
local sizes.

\tparam CDT a constrained Delaunay triangulation with Mesh_2's face base
  (`Delaunay_mesh_face_base_2`), or a `Constrained_triangulation_plus_2` of
  one
\param degrees the bound, in (0, 30]
\throws std::invalid_argument if `degrees` is not in (0, 30]: above 30
  degrees Delaunay refinement need not terminate, and bounds near 35
  degrees are known not to
*/
template <class CDT>
Minimum_angle_statistics refine_to_minimum_angle_2(CDT& cdt, double degrees, bool split_constraints = true,
                                                   std::size_t max_insertions = 0)
{
  if(!(degrees > 0 && degrees <= 30))
    throw std::invalid_argument("refine_to_minimum_angle_2: the angle bound must be in (0, 30] degrees, not "
                                + std::to_string(degrees));
  typedef typename CDT::Face_handle Face_handle;
  typedef std::array<typename CDT::Vertex_handle, 3> Triple;
  Minimum_angle_statistics st;
  st.angle = degrees;
  auto for_domain_faces = [&](auto&& visit) {
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if(f->is_in_domain()) visit(Face_handle(f));
  };
  auto smallest_angle = [](Face_handle f) {
    return internal::smallest_angle_degrees(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
  };
  // below the bound beyond rounding (Mesh_2 decides on the squared sine)
  auto below = [&](double angle) { return angle < degrees * (1 - 1e-9); };
  st.smallest_angle = 180;
  for_domain_faces([&](Face_handle f) {
    const double angle = smallest_angle(f);
    ++st.triangles_before;
    st.below_before += below(angle) ? 1 : 0;
    st.smallest_angle = (std::min)(st.smallest_angle, angle);
  });
  // Nothing to refine (the usual case after smoothing on smooth fields): the
  // mesh is the result, and one scan was all it cost.
  if(st.below_before == 0 || cdt.dimension() != 2) {
    st.triangles_after = st.triangles_before;
    st.below_after = st.below_before;
    if(st.triangles_after == 0) st.smallest_angle = 0;
    return st;
  }
  // The frontal triangles, sorted, to count the ones the refinement changed.
  std::vector<Triple> before;
  before.reserve(st.triangles_before);
  for_domain_faces([&](Face_handle f) { before.push_back(internal::sorted_vertices<CDT>(f)); });
  std::sort(before.begin(), before.end());
  const std::size_t vertices_before = cdt.number_of_vertices();
  {
    const std::size_t limit = max_insertions != 0 ? max_insertions : 10 * st.triangles_before + 1000;
    // Mesh_2's shape criterion: the squared sine of the smallest angle
    const double sine = std::sin(degrees * CGAL_PI / 180);
    const Delaunay_mesh_criteria_2<CDT> criteria(sine * sine);
    if(split_constraints) {
      Delaunay_mesher_2<CDT, Delaunay_mesh_criteria_2<CDT> > mesher(cdt, criteria);
      st.completed = internal::refine_with_limit(mesher, limit);
    } else {
      Delaunay_mesher_no_edge_refinement_2<CDT, Delaunay_mesh_criteria_2<CDT> > mesher(cdt, criteria);
      st.completed = internal::refine_with_limit(mesher, limit);
    }
  }
  st.points_inserted = cdt.number_of_vertices() - vertices_before;
  st.smallest_angle = 180;
  for_domain_faces([&](Face_handle f) {
    const double angle = smallest_angle(f);
    ++st.triangles_after;
    st.below_after += below(angle) ? 1 : 0;
    st.triangles_changed += std::binary_search(before.begin(), before.end(), internal::sorted_vertices<CDT>(f)) ? 0 : 1;
    st.smallest_angle = (std::min)(st.smallest_angle, angle);
  });
  if(st.triangles_after == 0) st.smallest_angle = 0;
  return st;
}

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_REFINE_TO_MINIMUM_ANGLE_2_H
