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

namespace internal {

// The triangle figures of `Mesh_quality` added up one triangle at a time,
// so that they can also be added over the shares of a mesh (afmesh_2_mpi
// adds its ranks' sums); the percentiles need the ratios themselves, which
// add() returns.
struct Triangle_quality_sums
{
  std::size_t triangles = 0, above_0_9 = 0, sharp_angles = 0;
  double sum_of_ratios = 0, min_ratio = 1, min_angle = 180, max_angle = 0;
  std::array<std::size_t, 20> ratio_histogram{};
  std::array<std::size_t, 18> angle_histogram{};

  // Adds the triangle (x[i], y[i]) and returns its radius ratio.
  double add(const double x[3], const double y[3])
  {
    const double to_degrees = 180 / std::acos(-1.);
    double l[3];
    for(int i = 0; i < 3; ++i)
      l[i] = std::hypot(x[(i + 1) % 3] - x[(i + 2) % 3], y[(i + 1) % 3] - y[(i + 2) % 3]);
    // for a clockwise (inverted) triangle the shape is that of its mirror image
    double rr = radius_ratio(x[0], y[0], x[1], y[1], x[2], y[2]);
    if(rr == 0) rr = radius_ratio(x[0], y[0], x[2], y[2], x[1], y[1]);
    sum_of_ratios += rr;
    if(rr > 0.9) ++above_0_9;
    ++ratio_histogram[(std::min)(std::size_t(19), std::size_t((std::max)(0., rr) * 20))];
    min_ratio = (std::min)(min_ratio, rr);
    for(int i = 0; i < 3; ++i) {
      const double a = l[(i + 1) % 3], b = l[(i + 2) % 3], c = l[i];
      const double cosine = (std::max)(-1., (std::min)(1., (a * a + b * b - c * c) / (2 * a * b)));
      const double angle = std::acos(cosine) * to_degrees;
      min_angle = (std::min)(min_angle, angle);
      max_angle = (std::max)(max_angle, angle);
      ++angle_histogram[(std::min)(std::size_t(17), std::size_t(angle / 10))];
      if(angle < 30) ++sharp_angles;
    }
    ++triangles;
    return rr;
  }

  // Sets the figures of `q` but the percentiles.
  void finish(Mesh_quality& q) const
  {
    q.number_of_triangles = triangles;
    q.radius_ratio_histogram = ratio_histogram;
    q.angle_histogram = angle_histogram;
    if(triangles == 0) return; // all figures 0
    q.min_radius_ratio = min_ratio;
    q.min_angle_degrees = min_angle;
    q.max_angle_degrees = max_angle;
    q.mean_radius_ratio = sum_of_ratios / double(triangles);
    q.share_above_0_9 = double(above_0_9) / double(triangles);
    q.share_angles_below_30 = double(sharp_angles) / double(3 * triangles);
  }
};

// The index, in the sorted radius ratios of `n` triangles, of the
// percentile `p` that `Mesh_quality` gives.
inline std::size_t percentile_index(double p, std::size_t n) { return std::size_t(p * double(n - 1)); }

// The edge length over size figures of `Mesh_quality`, one edge at a time.
struct Edge_size_sums
{
  std::size_t edges = 0, within_sqrt2 = 0;
  double sum = 0, min = std::numeric_limits<double>::infinity(), max = 0;

  // Adds an edge of length over size `r`.
  void add(double r)
  {
    min = (std::min)(min, r);
    max = (std::max)(max, r);
    sum += r;
    if(r >= std::sqrt(0.5) && r <= std::sqrt(2.)) ++within_sqrt2;
    ++edges;
  }

  void finish(Mesh_quality& q) const
  {
    q.has_size_figures = true;
    q.number_of_edges = edges;
    if(edges == 0) return; // all figures 0
    q.min_edge_over_size = min;
    q.max_edge_over_size = max;
    q.mean_edge_over_size = sum / double(edges);
    q.share_edges_within_sqrt2 = double(within_sqrt2) / double(edges);
  }
};

// The length of the edge (ax, ay)-(bx, by) over `sizing`'s h at its
// midpoint (a point of type Point_2).
template <class Point_2, class SizingField>
double edge_over_size(const SizingField& sizing, double ax, double ay, double bx, double by)
{
  const double h = CGAL::to_double(sizing(Point_2(0.5 * (ax + bx), 0.5 * (ay + by))));
  return std::hypot(bx - ax, by - ay) / h;
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2Ref
Computes `Mesh_quality` over the finite faces of `cdt` with `is_in_domain()`.
*/
template <class CDT>
Mesh_quality mesh_quality(const CDT& cdt)
{
  Mesh_quality q;
  internal::Triangle_quality_sums sums;
  std::vector<double> ratios;
  ratios.reserve(cdt.number_of_faces());
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    double x[3], y[3];
    for(int i = 0; i < 3; ++i) {
      x[i] = CGAL::to_double(f->vertex(i)->point().x());
      y[i] = CGAL::to_double(f->vertex(i)->point().y());
    }
    ratios.push_back(sums.add(x, y));
  }
  sums.finish(q);
  if(!ratios.empty()) {
    // the order statistics by selection, each in the part above the one
    // before (a sort of a million ratios took a tenth of a second); each
    // read at once, as the next selection reorders its place too (until
    // 2026-11-29 they were read after the three, and the 1% and 5% were
    // wrong: 0.90 and 1.0 for 0.86 and 0.97 on the square with a hole)
    auto percentile = [&](double p, std::vector<double>::iterator from, double& value) {
      const auto at = ratios.begin() + std::ptrdiff_t(internal::percentile_index(p, ratios.size()));
      std::nth_element(from, at, ratios.end());
      value = *at;
      return at;
    };
    const auto p1 = percentile(0.01, ratios.begin(), q.radius_ratio_p1);
    const auto p5 = percentile(0.05, p1, q.radius_ratio_p5);
    percentile(0.5, p5, q.radius_ratio_median);
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
  internal::Edge_size_sums sums;
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    const auto f = e->first;
    const auto g = f->neighbor(e->second);
    const bool f_in = !cdt.is_infinite(f) && f->is_in_domain(), g_in = !cdt.is_infinite(g) && g->is_in_domain();
    if(!f_in && !g_in) continue;
    const auto& a = f->vertex(CDT::cw(e->second))->point();
    const auto& b = f->vertex(CDT::ccw(e->second))->point();
    sums.add(internal::edge_over_size<Point_2>(sizing, CGAL::to_double(a.x()), CGAL::to_double(a.y()),
                                      CGAL::to_double(b.x()), CGAL::to_double(b.y())));
  }
  sums.finish(q);
  return q;
}

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_MESH_QUALITY_H
