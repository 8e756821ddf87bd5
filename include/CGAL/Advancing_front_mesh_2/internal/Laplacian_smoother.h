// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_LAPLACIAN_SMOOTHER_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_LAPLACIAN_SMOOTHER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Star_smoother.h>

#include <array>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The moves of CGAL::laplacian_smooth_mesh_2() (the paper's Fig. 13): the
// centroid of the neighbours, then halfway there, the first that neither
// lowers the star's worst radius ratio nor its worst smallest angle.
struct Laplacian_moves
{
  static constexpr bool best_first = false;

  void candidates(double x, double y, const std::vector<std::array<double, 2> >& ring,
                  std::vector<std::array<double, 2> >& out) const
  {
    double sx = 0, sy = 0;
    for(const auto& q : ring) {
      sx += q[0];
      sy += q[1];
    }
    const double n = static_cast<double>(ring.size());
    out.push_back({{sx / n, sy / n}});
    out.push_back({{0.5 * (x + sx / n), 0.5 * (y + sy / n)}});
  }

  bool acceptable(const Star_quality& after, const Star_quality& before) const
  {
    return after.worst_ratio >= before.worst_ratio && after.worst_sine2 >= before.worst_sine2;
  }

  bool improves(const Star_quality&, const Star_quality&) const { return true; }
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_LAPLACIAN_SMOOTHER_H
