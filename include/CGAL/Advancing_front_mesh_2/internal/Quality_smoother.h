// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_QUALITY_SMOOTHER_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_QUALITY_SMOOTHER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Double_geometry.h>
#include <CGAL/Advancing_front_mesh_2/internal/Star_smoother.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The moves of CGAL::quality_smooth_mesh_2(): a local optimisation of the
// star. Two directions are proposed, each of which improves some stars and
// not others: the centroid of the neighbours (Laplacian smoothing) and the
// area-weighted mean of the star's circumcentres (the optimal Delaunay
// triangulation's update, Chen and Xu 2004), at full, half and quarter
// steps, and halfway between the two; the vertex goes to the one whose star
// has the largest sum of radius ratios, among those that raise that sum and
// keep the star's worst radius ratio.
struct Quality_moves
{
  static constexpr bool best_first = true;

  void candidates(double x, double y, const std::vector<std::array<double, 2> >& ring,
                  std::vector<std::array<double, 2> >& out) const
  {
    const std::size_t n = ring.size();
    double lx = 0, ly = 0, ux = 0, uy = 0, area = 0;
    for(std::size_t k = 0; k < n; ++k) {
      const std::array<double, 2>& a = ring[k];
      const std::array<double, 2>& b = ring[(k + 1) % n];
      lx += a[0];
      ly += a[1];
      const Circle c = circle_of(x, y, a[0], a[1], b[0], b[1]);
      const double t = 0.5 * std::abs(signed_area(x, y, a[0], a[1], b[0], b[1]));
      ux += t * c.cx;
      uy += t * c.cy;
      area += t;
    }
    lx /= double(n);
    ly /= double(n);
    out.push_back({{lx, ly}});
    out.push_back({{0.5 * (x + lx), 0.5 * (y + ly)}});
    out.push_back({{0.75 * x + 0.25 * lx, 0.75 * y + 0.25 * ly}});
    // a flat triangle's circumcentre is far or not a number: no ODT move then
    if(area > 0 && std::isfinite(ux) && std::isfinite(uy)) {
      ux /= area;
      uy /= area;
      out.push_back({{ux, uy}});
      out.push_back({{0.5 * (x + ux), 0.5 * (y + uy)}});
      out.push_back({{0.5 * (lx + ux), 0.5 * (ly + uy)}});
    }
  }

  bool acceptable(const Star_quality& after, const Star_quality& before) const
  {
    return after.worst_ratio >= before.worst_ratio;
  }

  bool improves(const Star_quality& after, const Star_quality& before) const
  {
    return after.ratio_sum > before.ratio_sum;
  }
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_QUALITY_SMOOTHER_H
