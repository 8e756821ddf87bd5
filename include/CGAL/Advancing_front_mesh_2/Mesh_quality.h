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

#include <CGAL/Advancing_front_mesh_2/internal/Double_geometry.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

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

  /// radius ratio percentiles: the value below which 1%, 5%, 50% of the
  /// triangles lie
  double radius_ratio_p1 = 0, radius_ratio_p5 = 0, radius_ratio_median = 0;
  /// number of triangles per radius ratio bin [0.05 k, 0.05 (k + 1)), the
  /// last bin including 1
  std::array<std::size_t, 20> radius_ratio_histogram{};
  /// number of triangle angles per 10-degree bin [10 k, 10 (k + 1)) degrees
  std::array<std::size_t, 18> angle_histogram{};
  /// share of triangle angles below 30 degrees
  double share_angles_below_30 = 0;

  /// \name Edge length over target size
  /// Filled by the overload of `mesh_quality()` that takes a sizing field:
  /// for every edge of the domain, its length over the field's `h` at its
  /// midpoint.
  /// @{
  bool has_size_figures = false;
  std::size_t number_of_edges = 0;
  double min_edge_over_size = 0, max_edge_over_size = 0, mean_edge_over_size = 0;
  /// share of edges with length / h in [1/sqrt(2), sqrt(2)]
  double share_edges_within_sqrt2 = 0;
  /// @}
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
  std::size_t above = 0, sharp_angles = 0;
  std::vector<double> ratios;
  ratios.reserve(cdt.number_of_faces());
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
    // for a clockwise (inverted) triangle the shape is that of its mirror image
    double rr = internal::radius_ratio(x[0], y[0], x[1], y[1], x[2], y[2]);
    if(rr == 0) rr = internal::radius_ratio(x[0], y[0], x[2], y[2], x[1], y[1]);
    sum += rr;
    if(rr > 0.9) ++above;
    ratios.push_back(rr);
    ++q.radius_ratio_histogram[(std::min)(std::size_t(19), std::size_t((std::max)(0., rr) * 20))];
    q.min_radius_ratio = (std::min)(q.min_radius_ratio, rr);
    for(int i = 0; i < 3; ++i) {
      const double a = l[(i + 1) % 3], b = l[(i + 2) % 3], c = l[i];
      const double cosine = (std::max)(-1., (std::min)(1., (a * a + b * b - c * c) / (2 * a * b)));
      const double angle = std::acos(cosine) * to_degrees;
      q.min_angle_degrees = (std::min)(q.min_angle_degrees, angle);
      q.max_angle_degrees = (std::max)(q.max_angle_degrees, angle);
      ++q.angle_histogram[(std::min)(std::size_t(17), std::size_t(angle / 10))];
      if(angle < 30) ++sharp_angles;
    }
    ++q.number_of_triangles;
  }
  if(q.number_of_triangles > 0) {
    q.mean_radius_ratio = sum / double(q.number_of_triangles);
    q.share_above_0_9 = double(above) / double(q.number_of_triangles);
    q.share_angles_below_30 = double(sharp_angles) / double(3 * q.number_of_triangles);
    // the order statistics by selection, each in the part above the one
    // before (a sort of a million ratios took a tenth of a second)
    auto percentile = [&](double p, std::vector<double>::iterator from) {
      const auto at = ratios.begin() + std::ptrdiff_t(p * double(ratios.size() - 1));
      std::nth_element(from, at, ratios.end());
      return at;
    };
    const auto p1 = percentile(0.01, ratios.begin());
    const auto p5 = percentile(0.05, p1);
    const auto median = percentile(0.5, p5);
    q.radius_ratio_p1 = *p1;
    q.radius_ratio_p5 = *p5;
    q.radius_ratio_median = *median;
  } else {
    q.min_radius_ratio = 0;
    q.min_angle_degrees = 0;
  }
  return q;
}

/*!
\ingroup PkgAdvancingFrontMesh2Ref
Same as above, and also the edge length over target size figures, with the
target edge length `h` given by `sizing` (a model of
`AdvancingFrontSizingField_2`) at the midpoint of every edge of the domain.
*/
template <class CDT, class SizingField>
Mesh_quality mesh_quality(const CDT& cdt, const SizingField& sizing)
{
  typedef typename CDT::Geom_traits::Point_2 Point_2;
  Mesh_quality q = mesh_quality(cdt);
  q.has_size_figures = true;
  q.min_edge_over_size = std::numeric_limits<double>::infinity();
  double sum = 0;
  std::size_t within = 0;
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    const auto f = e->first;
    const auto g = f->neighbor(e->second);
    const bool f_in = !cdt.is_infinite(f) && f->is_in_domain(), g_in = !cdt.is_infinite(g) && g->is_in_domain();
    if(!f_in && !g_in) continue;
    const auto& a = f->vertex(CDT::cw(e->second))->point();
    const auto& b = f->vertex(CDT::ccw(e->second))->point();
    const double ax = CGAL::to_double(a.x()), ay = CGAL::to_double(a.y());
    const double bx = CGAL::to_double(b.x()), by = CGAL::to_double(b.y());
    const double h = CGAL::to_double(sizing(Point_2(0.5 * (ax + bx), 0.5 * (ay + by))));
    const double r = std::hypot(bx - ax, by - ay) / h;
    q.min_edge_over_size = (std::min)(q.min_edge_over_size, r);
    q.max_edge_over_size = (std::max)(q.max_edge_over_size, r);
    sum += r;
    if(r >= std::sqrt(0.5) && r <= std::sqrt(2.)) ++within;
    ++q.number_of_edges;
  }
  if(q.number_of_edges > 0) {
    q.mean_edge_over_size = sum / double(q.number_of_edges);
    q.share_edges_within_sqrt2 = double(within) / double(q.number_of_edges);
  } else {
    q.min_edge_over_size = 0;
  }
  return q;
}

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_MESH_QUALITY_H
