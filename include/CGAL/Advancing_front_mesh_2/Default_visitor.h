// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_DEFAULT_VISITOR_H
#define CGAL_ADVANCING_FRONT_MESH_2_DEFAULT_VISITOR_H

#include <CGAL/license/Advancing_front_mesh_2.h>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

The visitor used when none is given: every hook does nothing, so the
compiler removes the calls. A user visitor derives from it and overrides
what it needs (hooks are found statically, no virtual functions).

\cgalModels `AdvancingFrontMeshVisitor_2`
*/
struct Default_visitor
{
  /// called once after the front has been built
  template <class Mesher> void on_init(const Mesher&) {}
  /// called after a new point has been inserted
  template <class Vertex_handle> void on_point_inserted(Vertex_handle) {}
  /// called after a triangle has been created
  template <class Face_handle> void on_face_created(Face_handle) {}
  /// called just before a triangle is removed (its circle was broken)
  template <class Face_handle> void on_face_removed(Face_handle) {}
  /// streaming mode only: called for a finished triangle just before it is
  /// handed to the sink and removed from the triangulation
  template <class Face_handle> void on_face_finished(Face_handle) {}
  /// called after each processed front edge with the meshed fraction of
  /// the domain area, in [0, 1]
  void on_progress(double /*fraction*/) {}
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_DEFAULT_VISITOR_H
