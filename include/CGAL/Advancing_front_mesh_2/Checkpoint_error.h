// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_CHECKPOINT_ERROR_H
#define CGAL_ADVANCING_FRONT_MESH_2_CHECKPOINT_ERROR_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Thrown by `Advancing_front_mesher_2::refine_mesh()`,
`step_by_step_refine_mesh()` and `write_checkpoint()` when a checkpoint
cannot be written (a full disk, a directory that cannot be written).
Unlike other errors during meshing, it leaves the mesher as it was right
before the checkpoint: the front is not closed and the sink not finished,
the previous checkpoint file is intact, and calling `refine_mesh()` again
goes on meshing (retrying the checkpoint at the next sweep) with the same
result as a run without the error. `what()` names the file.
*/
class Checkpoint_error : public std::runtime_error
{
public:
  explicit Checkpoint_error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_CHECKPOINT_ERROR_H
