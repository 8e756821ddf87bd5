// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SEGMENT_SIZE_DIVISION_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SEGMENT_SIZE_DIVISION_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The one-dimensional mesh of one segment: where to cut it so that its
// pieces follow the size field, as Gmsh meshes curves. The number of edge
// lengths that fit along the segment is N = integral of ds / h(s); the
// segment gets n = round(N) pieces (at least one), cut where the integral
// reaches N k / n, so every piece holds the same share of it. With this
// rounding a piece holds less than 1.25 target lengths (N < n + 1/2), and a
// segment shorter than 1.5 h stays whole, as the paper's front takes it.
//
// The integral is summed by the trapezoid rule over steps of an eighth of the
// local size, so a graded field (whose size changes by a bounded factor over
// one edge length) is followed closely; every step costs one call of the
// field. `size_at(t)` gives h at the point a + t (b - a), t in [0, 1].
// Returns the parameters of the cuts, increasing, strictly inside (0, 1).
template <class SizeAt>
std::vector<double> segment_cut_parameters(double length, SizeAt size_at)
{
  std::vector<double> cuts;
  if(!(length > 0) || !std::isfinite(length)) return cuts;
  auto checked_size = [&](double t) {
    const double h = size_at(t);
    if(!(h > 0) || !std::isfinite(h))
      throw std::invalid_argument("boundary discretisation: the sizing field returned " + std::to_string(h) +
                                  ", not a positive finite number");
    return h;
  };
  // samples of t and of the integral up to t
  std::vector<double> ts(1, 0.), integral(1, 0.);
  double t = 0, h = checked_size(0.);
  while(t < 1) {
    const double next = (std::min)(1., t + h / (8 * length));
    // a step below the precision of t cannot advance: the size is far below
    // the segment's length at double precision; end the walk there
    if(!(next > t)) break;
    const double h_next = checked_size(next);
    integral.push_back(integral.back() + (next - t) * length * 0.5 * (1 / h + 1 / h_next));
    ts.push_back(next);
    t = next;
    h = h_next;
  }
  const double total = integral.back();
  const double n = (std::max)(1., std::floor(total + 0.5));
  if(n < 2 || ts.back() < 1) return cuts;
  cuts.reserve(static_cast<std::size_t>(n) - 1);
  std::size_t i = 1;
  for(double k = 1; k < n; ++k) {
    const double target = total * k / n;
    while(i + 1 < integral.size() && integral[i] < target) ++i;
    const double f0 = integral[i - 1], f1 = integral[i];
    const double w = f1 > f0 ? (target - f0) / (f1 - f0) : 0.5;
    const double cut = ts[i - 1] + (std::min)(1., (std::max)(0., w)) * (ts[i] - ts[i - 1]);
    if(cut > 0 && cut < 1 && (cuts.empty() || cut > cuts.back())) cuts.push_back(cut);
  }
  return cuts;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SEGMENT_SIZE_DIVISION_H
