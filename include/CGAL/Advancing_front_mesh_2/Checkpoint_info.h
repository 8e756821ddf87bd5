// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_CHECKPOINT_INFO_H
#define CGAL_ADVANCING_FRONT_MESH_2_CHECKPOINT_INFO_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <cstddef>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

What `Advancing_front_mesher_2::read_checkpoint_info()` and
`Advancing_front_mesher_2::resume()` return: the beginning of a checkpoint,
which a program needs to prepare a resumed run.
*/
struct Checkpoint_info
{
  std::string user_data;     ///< as given to `set_checkpoint()`
  std::string sink_state;    ///< what the sink's `checkpoint_state()` returned
  std::size_t vertices_written = 0, triangles_written = 0; ///< given to the sink before the checkpoint
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_CHECKPOINT_INFO_H
