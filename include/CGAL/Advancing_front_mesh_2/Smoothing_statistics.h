// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_SMOOTHING_STATISTICS_H
#define CGAL_ADVANCING_FRONT_MESH_2_SMOOTHING_STATISTICS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

What `CGAL::laplacian_smooth_mesh_2()` or `CGAL::quality_smooth_mesh_2()` did.
*/
struct Smoothing_statistics
{
  std::size_t passes = 0;                   ///< smoothing + swapping alternations done
  std::size_t movable_vertices = 0;         ///< interior vertices free to move (first pass)
  std::size_t moves = 0;                    ///< accepted moves, over all passes
  std::size_t rejected_moves = 0;           ///< candidate positions refused by the guard (before or after the flips)
  std::size_t flips = 0;                    ///< edge flips restoring the constrained Delaunay property
  std::vector<std::size_t> flips_per_pass;  ///< the same, pass by pass
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_SMOOTHING_STATISTICS_H
