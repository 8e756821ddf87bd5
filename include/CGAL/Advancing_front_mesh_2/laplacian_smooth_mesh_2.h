// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_LAPLACIAN_SMOOTH_MESH_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_LAPLACIAN_SMOOTH_MESH_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Smoothing_statistics.h>
#include <CGAL/Advancing_front_mesh_2/internal/Laplacian_smoother.h>
#include <CGAL/Named_function_parameters.h>

namespace CGAL {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Improves the shape of the triangles of a mesh as in Fig. 13 of Mavriplis
(1992): constrained Laplacian smoothing of the interior vertices, then edge
swapping that restores the constrained Delaunay property, alternated a few
times.

Only in-domain faces (`is_in_domain()`) are considered. A vertex moves only
if every face around it is a finite in-domain face, no constrained edge is
incident to it, and the `vertex_is_constrained_map` does not hold it: the
boundary, isolated input points and everything outside the domain never
move. Each movable vertex, in turn, is tried at the centroid of its
neighbours, then halfway there; a move is accepted only if every triangle
around the vertex stays positively oriented (exact predicate of the
triangulation's traits) and neither the smallest radius ratio 2r/R nor the
smallest angle around the vertex decreases (computed in double precision).
An accepted move is followed at once by Lawson's flips about the vertex, on
the edges between in-domain faces, until the triangulation is constrained
Delaunay again (the input segments are never flipped); if a triangle the
flips made is worse, by either measure, than the worst of the star before the
move, the flips are undone and the vertex goes back. So smoothing never
inverts a triangle and never makes the worst triangle of the mesh worse by
either measure (Lawson's flips alone could lower the smallest radius ratio).
Few edges need flipping after smoothing, as the paper notes; a final Lawson
pass after each pass of smoothing finds nothing left to flip. These
guarantees assume that the input is constrained Delaunay over its in-domain
faces, as the results of `CGAL::advancing_front_mesh_2()` and of Mesh_2 are;
otherwise the first pass's final Lawson flips make it so, unguarded.

Works on the result of `CGAL::advancing_front_mesh_2()` and on a CGAL Mesh_2
result (`CGAL::refine_Delaunay_mesh_2()`) alike.

\tparam CDT a `CGAL::Constrained_Delaunay_triangulation_2` (or
`Constrained_triangulation_plus_2`) whose faces have `is_in_domain()`, for
example `CGAL::Delaunay_mesh_face_base_2`.

\param cdt the mesh, modified in place
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the number of smoothing + swapping passes}
    \cgalParamDefault{5}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDescription{a readable property map from `CDT::Vertex_handle`
      to `bool`: vertices mapped to `true` never move, in addition to those on
      constrained edges (use it for isolated input points)}
    \cgalParamDefault{no vertex held}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns what was done: passes, moves, flips.
*/
template <class CDT, class NamedParameters = parameters::Default_named_parameters>
Advancing_front_mesh_2::Smoothing_statistics
laplacian_smooth_mesh_2(CDT& cdt, const NamedParameters& np = parameters::default_values())
{
  return Advancing_front_mesh_2::internal::smooth_with<Advancing_front_mesh_2::internal::Laplacian_moves>(cdt, np);
}

} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_LAPLACIAN_SMOOTH_MESH_2_H
