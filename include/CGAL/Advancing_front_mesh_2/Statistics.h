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

Wall-clock seconds spent in each phase of the advancing front, measured
only when the mesher was asked to (`Advancing_front_mesher_2::set_phase_timing()`),
because reading the clock at every phase change costs a few percent. The
phases partition the meshing time: each moment is charged to exactly one.
*/
struct Phase_times
{
  /// taking the next front edge from the priority queue (step 2), the sizing field (step 3)
  double front_selection = 0;
  /// the close-point search: queries of the active-point quadtree (step 4; its
  /// updates are front bookkeeping)
  double close_point_search = 0;
  /// the Delaunay closure: candidate filtering (orientation, free sectors at
  /// the front vertices) and Merriam's in-circle iteration (step 5)
  double delaunay_closure = 0;
  /// placing a new point and checking that it is acceptable (step 6)
  double placement = 0;
  /// queries and updates of the lifted-circle octrees (steps 7-8 and the front-edge circles)
  double circle_octree = 0;
  /// the cavity: removing broken triangles and rebuilding the triangles about the new point (steps 9-12)
  double cavity = 0;
  /// visibility: segments blocked by front edges, vertices or constraints
  double visibility = 0;
  /// front bookkeeping: creating and removing triangles in the data structure,
  /// updating the front, its queue and the active-point quadtree
  double front_update = 0;
  /// the output: the final Delaunay check and restoring the triangulation's invariants
  double output = 0;

  /// the sum of all phases
  double total() const
  {
    return front_selection + close_point_search + delaunay_closure + placement + circle_octree + cavity +
           visibility + front_update + output;
  }
};

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
  /// searches of the front triangles' circle index for the circles a new
  /// point breaks (step 7); called `triangle_octree_queries` before 2026-11
  std::size_t broken_circle_queries = 0;
  /// queries of the index of the input constraints, which decide whether a
  /// new point sees a triangle whose circle it breaks (Fig. 6); called
  /// `edge_octree_queries` before 2026-11, when it also counted the searches
  /// for front edges, which point_search_queries counts
  std::size_t constraint_index_queries = 0;
  /// searches of the point index of active vertices, for the close points
  /// and front edges of step 4
  std::size_t point_search_queries = 0;
  /// exact predicate evaluations in the Delaunay closure (Merriam's iteration)
  std::size_t incircle_tests = 0;
  /// largest number of front edges at any time
  std::size_t largest_front = 0;
  /// pockets found: loops of the front of at most 1024 edges found closed
  /// after a step that split or joined loops, whose edges are then
  /// processed before all others (see `set_pocket_priority()`)
  std::size_t pockets = 0;
  /// times the active vertices were renumbered and the structures keyed by
  /// them rebuilt, to release the memory of a front that has shrunk to a
  /// quarter of its largest size since the last time
  std::size_t memory_compactions = 0;
  /// largest number of active vertices (front vertices and free points),
  /// the only ones the mesher keeps a record of
  std::size_t largest_active_vertices = 0;
  /// largest number of live triangles: front triangles, whose circumcircles
  /// reach past the front and are held by the circle octree
  std::size_t largest_live_triangles = 0;
  /// edges flipped by the final Lawson check (in streaming mode, by the
  /// check of the finished triangles before they go to the sink, which
  /// tests every edge of theirs exactly); 0 unless the advancing front
  /// missed a broken circle, which the tests assert never happens
  std::size_t delaunay_repair_flips = 0;
  /// Streaming mode (`Advancing_front_mesher_2::set_output_sink()`) only:
  /// sweeps over the triangles in memory that looked for finished ones
  std::size_t stream_sweeps = 0;
  /// largest number of mesh triangles held in memory at any time
  /// (streaming mode; the whole mesh otherwise)
  std::size_t largest_triangles_in_memory = 0;
  /// A finished triangle has gone to the sink: its circle was far enough
  /// behind the front that no later point was expected to reach it. New
  /// points whose cavity reached one all the same, and which would
  /// otherwise have been accepted, are refused (the edge is closed on an
  /// existing point instead), so that the mesh stays a constrained Delaunay
  /// triangulation: this counts them. 0 in every test and benchmark; with
  /// it at 0 the triangles are exactly those of the run without streaming.
  std::size_t points_refused_for_finished_triangles = 0;
  /// of those, the points inside the circle of the finished triangle (the
  /// run without streaming would have broken it)
  std::size_t finished_triangles_broken = 0;
  /// Streaming mode: finished triangles kept in memory for another sweep
  /// because an edge to a triangle still in memory was not Delaunay (when
  /// both have finished, the edge is flipped); 0 in every test
  std::size_t finished_triangles_held = 0;
  /// Streaming mode: edges of finished triangles that were not Delaunay
  /// against a triangle already written to the sink, which cannot be
  /// repaired (the output is then not constrained Delaunay there); 0 in
  /// every test
  std::size_t finished_edges_not_delaunay = 0;
  /// checkpoints written (see `Advancing_front_mesher_2::set_checkpoint()`)
  std::size_t checkpoints_written = 0;
  /// number of vertices and in-domain faces of the result
  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;
  /// wall-clock seconds: initialisation (domain marking, front) and meshing
  double init_time = 0;
  double meshing_time = 0;
  /// time per phase; all zero unless phase timing was switched on
  Phase_times phase_times;
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_STATISTICS_H
