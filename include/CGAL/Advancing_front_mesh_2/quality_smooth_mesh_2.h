// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_QUALITY_SMOOTH_MESH_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_QUALITY_SMOOTH_MESH_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Smoothing_statistics.h>
#include <CGAL/Advancing_front_mesh_2/internal/Quality_smoother.h>
#include <CGAL/Named_function_parameters.h>

namespace CGAL {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Improves the shape of the triangles of a mesh by a local optimisation of
each interior vertex's position, alternated with edge swapping that restores
the constrained Delaunay property: on graded meshes it raises the mean
radius ratio more than `CGAL::laplacian_smooth_mesh_2()` (see the user
manual's measurements), at about twice its cost per pass.

Each movable vertex, in turn, is tried at six positions: the centroid of its
neighbours (Laplacian smoothing) at full, half and quarter step, the
area-weighted mean of the circumcentres of its triangles (the update of the
optimal Delaunay triangulation, Chen and Xu 2004) at full and half step, and
halfway between the two full steps. Among those where every triangle around
the vertex stays positively oriented (exact predicate of the triangulation's
traits), the smallest radius ratio 2r/R around the vertex does not decrease
and the sum of the radius ratios around it increases, the vertex goes to the
one with the largest sum. Lawson's flips about the vertex follow at once, on
the edges between in-domain faces, until the triangulation is constrained
Delaunay again (the input segments are never flipped); if a triangle the
flips made has a smaller radius ratio than the worst of the star before the
move, the flips are undone and the next position is tried. So smoothing never
inverts a triangle and never lowers the smallest radius ratio of the mesh;
unlike `CGAL::laplacian_smooth_mesh_2()` it does not guard the smallest
angle separately (a star's smallest angle may decrease while its radius
ratios do not). Radius ratios are computed in double precision.

Which vertices move, and what the guarantees assume, is as for
`CGAL::laplacian_smooth_mesh_2()`: only interior vertices of the domain's
in-domain faces, on no constrained edge and not held by the
`vertex_is_constrained_map`, on a mesh that is constrained Delaunay over its
in-domain faces. Works on the result of `CGAL::advancing_front_mesh_2()` and
on a CGAL Mesh_2 result alike.

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
quality_smooth_mesh_2(CDT& cdt, const NamedParameters& np = parameters::default_values())
{
  return Advancing_front_mesh_2::internal::smooth_with<Advancing_front_mesh_2::internal::Quality_moves>(cdt, np);
}

} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_QUALITY_SMOOTH_MESH_2_H
