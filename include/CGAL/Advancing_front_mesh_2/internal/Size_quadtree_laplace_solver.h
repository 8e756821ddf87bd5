// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_QUADTREE_LAPLACE_SOLVER_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_QUADTREE_LAPLACE_SOLVER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Size_quadtree_2.h>

#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Solves the Laplace equation on the corners of a Size_quadtree_2 with the
// given Dirichlet values (the point sources and the boundary spacing act as
// heat sources held at fixed temperature, as in Pirzadeh's structured
// background grids, AIAA 91-3233) and zero flux through the sides of the
// root box.
//
// Each free corner's equation is the five-point finite-difference Laplacian
// on its nearest corners along the axes (unequal arms allowed); a missing
// arm on the root box is mirrored (zero flux). Divided by its diagonal, every
// row states that the corner's value is a convex combination of other
// corners' values, and a hanging corner's row states that it is the mean of
// its parents. The matrix is therefore an M-matrix, and the solution obeys
// the discrete maximum principle: it lies between the smallest and the
// largest Dirichlet value, whatever the tree.
//
// `fixed[i]` tells whether corner i is a Dirichlet corner, with value
// `value[i]`; the other entries of `value` are overwritten.
inline void solve_laplace_on_quadtree(const Size_quadtree_2& tree,
                                      const std::vector<char>& fixed,
                                      std::vector<double>& value)
{
  typedef Size_quadtree_2::Corner Corner;
  const std::vector<Corner>& corners = tree.corners();
  const int n = int(corners.size());
  std::vector<Eigen::Triplet<double> > entries;
  entries.reserve(std::size_t(n) * 5);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for(int i = 0; i < n; ++i) {
    const Corner& c = corners[i];
    entries.emplace_back(i, i, 1.);
    if(fixed[i]) {
      rhs[i] = value[i];
      continue;
    }
    if(c.is_hanging()) {
      entries.emplace_back(i, c.parent[0], -0.5);
      entries.emplace_back(i, c.parent[1], -0.5);
      continue;
    }
    double weight[4] = {0, 0, 0, 0};
    for(int axis = 0; axis < 2; ++axis) {
      const int lo = 2 * axis, hi = 2 * axis + 1;
      const bool has_lo = c.neighbor[lo] >= 0, has_hi = c.neighbor[hi] >= 0;
      if(has_lo && has_hi) {
        const double a = c.distance[lo], b = c.distance[hi];
        weight[lo] = 2. / (a * (a + b));
        weight[hi] = 2. / (b * (a + b));
      } else if(has_lo) {
        weight[lo] = 2. / (c.distance[lo] * c.distance[lo]);
      } else if(has_hi) {
        weight[hi] = 2. / (c.distance[hi] * c.distance[hi]);
      }
    }
    const double total = weight[0] + weight[1] + weight[2] + weight[3];
    CGAL_assertion(total > 0);
    for(int d = 0; d < 4; ++d)
      if(weight[d] > 0) entries.emplace_back(i, c.neighbor[d], -weight[d] / total);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int> > lu;
  lu.compute(A);
  if(lu.info() != Eigen::Success)
    throw std::runtime_error("background size field: the Laplace system could not be factorised");
  const Eigen::VectorXd u = lu.solve(rhs);
  if(lu.info() != Eigen::Success)
    throw std::runtime_error("background size field: the Laplace system could not be solved");
  // Round-off may step outside the Dirichlet range; the maximum principle
  // says the exact solution does not, so clamp to it.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for(int i = 0; i < n; ++i)
    if(fixed[i]) { lo = (std::min)(lo, value[i]); hi = (std::max)(hi, value[i]); }
  for(int i = 0; i < n; ++i)
    if(!fixed[i]) value[i] = (std::min)(hi, (std::max)(lo, u[i]));
  tree.interpolate_hanging_corners(value);
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_SIZE_QUADTREE_LAPLACE_SOLVER_H
