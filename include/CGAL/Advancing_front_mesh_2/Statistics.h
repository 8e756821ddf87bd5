// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_STATISTICS_H
#define CGAL_ADVANCING_FRONT_MESH_2_STATISTICS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <cstddef>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Counters filled by `CGAL::Advancing_front_mesher_2` during a run. They
describe the work of the algorithm of Mavriplis (1992) step by step, so that
a user can see where time goes and how large the working set became.
*/
struct Statistics
{
  /// front edges taken from the priority queue and processed (step 2)
  std::size_t front_edges_processed = 0;
  /// new points placed ahead of the front and inserted (steps 6-12)
  std::size_t points_inserted = 0;
  /// triangles built on an existing front point without a new point (step 6)
  std::size_t triangles_closed_on_existing_points = 0;
  /// of those, closures forced because no new point could be placed
  /// (the robustness fallback: gap narrower than the local size, point
  /// outside the region or too close to a front edge or point)
  std::size_t forced_closures = 0;
  /// placed points rejected by the validity check (then a forced closure)
  std::size_t rejected_points = 0;
  /// triangles built around new points (step 11)
  std::size_t triangles_around_new_points = 0;
  /// triangles removed because a new point broke their circumcircle (steps 7-9)
  std::size_t triangles_removed = 0;
  /// point insertions in which step 10 raised the size bound (a broken
  /// triangle was larger than the bound)
  std::size_t size_bound_raised = 0;
  /// queries of the circle octree (front triangles) and of the front-edge
  /// diametral-circle octree
  std::size_t triangle_octree_queries = 0;
  std::size_t edge_octree_queries = 0;
  /// queries of the close-point search structure (Kd_tree), and its rebuilds
  std::size_t point_search_queries = 0;
  std::size_t point_search_rebuilds = 0;
  /// exact predicate evaluations in the Delaunay closure (Merriam's iteration)
  std::size_t incircle_tests = 0;
  /// largest number of front edges at any time
  std::size_t largest_front = 0;
  /// largest number of live triangles: front triangles, whose circumcircles
  /// reach past the front and are held by the circle octree
  std::size_t largest_live_triangles = 0;
  /// edges flipped by the final Lawson check; 0 unless the advancing front
  /// missed a broken circle, which the tests assert never happens
  std::size_t delaunay_repair_flips = 0;
  /// number of vertices and in-domain faces of the result
  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;
  /// wall-clock seconds: initialisation (domain marking, front) and meshing
  double init_time = 0;
  double meshing_time = 0;
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_STATISTICS_H
