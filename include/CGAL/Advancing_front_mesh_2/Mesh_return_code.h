// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_MESH_RETURN_CODE_H
#define CGAL_ADVANCING_FRONT_MESH_2_MESH_RETURN_CODE_H

#include <CGAL/license/Advancing_front_mesh_2.h>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

The normal outcomes of a run. In every case the triangulation is a valid
constrained Delaunay triangulation whose in-domain faces cover the domain:
when a limit stops the advancing front early, the rest of the front is
closed on existing points only (no new points), so the unfinished part is
coarser than asked but still a valid mesh.
*/
enum Mesh_return_code
{
  MESH_COMPLETE = 0,         ///< the front emptied normally
  ITERATION_LIMIT_REACHED,   ///< `number_of_iterations` front edges were processed
  TIME_LIMIT_REACHED,        ///< `maximum_running_time` seconds elapsed
  /// streaming mode only: stopped right after writing a checkpoint, as
  /// asked by `Advancing_front_mesher_2::set_checkpoint()`. Unlike the other
  /// outcomes, the mesh is not complete: the sink holds the finished part,
  /// the checkpoint the rest of the state; calling `refine_mesh()` again, or
  /// `resume()` from the checkpoint in a later run, goes on meshing.
  STOPPED_AT_CHECKPOINT
};

/*!
\ingroup PkgAdvancingFrontMesh2Ref

The name of a return code, as spelled in the enumeration
(`"MESH_COMPLETE"`, ...): for logs and reports.
*/
inline const char* to_string(Mesh_return_code rc)
{
  switch(rc) {
    case MESH_COMPLETE: return "MESH_COMPLETE";
    case ITERATION_LIMIT_REACHED: return "ITERATION_LIMIT_REACHED";
    case TIME_LIMIT_REACHED: return "TIME_LIMIT_REACHED";
    case STOPPED_AT_CHECKPOINT: return "STOPPED_AT_CHECKPOINT";
  }
  return "unknown Mesh_return_code";
}

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_MESH_RETURN_CODE_H
