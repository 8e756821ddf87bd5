// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_MESH_QUALITY_H
#define CGAL_ADVANCING_FRONT_MESH_2_MESH_QUALITY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Shape figures of the in-domain triangles of a mesh, computed in double
precision. The radius ratio is 2r/R (inscribed over circumscribed radius,
times two): 1 for the equilateral triangle, 0 for a degenerate one.
*/
struct Mesh_quality
{
  std::size_t number_of_triangles = 0;
  double min_radius_ratio = 0;
  double mean_radius_ratio = 0;
  /// share of triangles with radius ratio above 0.9
  double share_above_0_9 = 0;
  double min_angle_degrees = 0;
  double max_angle_degrees = 0;
};

/*!
\ingroup PkgAdvancingFrontMesh2Ref
Computes `Mesh_quality` over the finite faces of `cdt` with `is_in_domain()`.
*/
template <class CDT>
Mesh_quality mesh_quality(const CDT& cdt)
{
  Mesh_quality q;
  q.min_radius_ratio = 1;
  q.min_angle_degrees = 180;
  double sum = 0;
  std::size_t above = 0;
  const double to_degrees = 180 / std::acos(-1.);
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    double x[3], y[3];
    for(int i = 0; i < 3; ++i) {
      x[i] = CGAL::to_double(f->vertex(i)->point().x());
      y[i] = CGAL::to_double(f->vertex(i)->point().y());
    }
    double l[3];
    for(int i = 0; i < 3; ++i)
      l[i] = std::hypot(x[(i + 1) % 3] - x[(i + 2) % 3], y[(i + 1) % 3] - y[(i + 2) % 3]);
    const double area = 0.5 * std::abs((x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]));
    const double s = 0.5 * (l[0] + l[1] + l[2]);
    // 2r/R = 16 area^2 / (s l0 l1 l2) with r = area/s and R = l0 l1 l2 / (4 area)
    const double rr = (area > 0) ? 8 * area * area / (s * l[0] * l[1] * l[2]) : 0;
    sum += rr;
    if(rr > 0.9) ++above;
    q.min_radius_ratio = (std::min)(q.min_radius_ratio, rr);
    for(int i = 0; i < 3; ++i) {
      const double a = l[(i + 1) % 3], b = l[(i + 2) % 3], c = l[i];
      const double cosine = (std::max)(-1., (std::min)(1., (a * a + b * b - c * c) / (2 * a * b)));
      const double angle = std::acos(cosine) * to_degrees;
      q.min_angle_degrees = (std::min)(q.min_angle_degrees, angle);
      q.max_angle_degrees = (std::max)(q.max_angle_degrees, angle);
    }
    ++q.number_of_triangles;
  }
  if(q.number_of_triangles > 0) {
    q.mean_radius_ratio = sum / double(q.number_of_triangles);
    q.share_above_0_9 = double(above) / double(q.number_of_triangles);
  } else {
    q.min_radius_ratio = 0;
    q.min_angle_degrees = 0;
  }
  return q;
}

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_MESH_QUALITY_H
