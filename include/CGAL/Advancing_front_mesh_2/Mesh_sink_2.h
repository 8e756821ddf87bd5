// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_MESH_SINK_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_MESH_SINK_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Receives the finished part of a mesh while it is being generated (streaming
mode, see `Advancing_front_mesher_2::set_output_sink()`).

A triangle is finished when no point the mesher may still insert can break
its circle: it is handed to the sink and dropped from memory. The mesher
numbers the vertices itself: vertex `i` is passed to `add_vertex()` once,
with `i` = 0, 1, 2, ... in order, before the first triangle that uses it.
Triangles are passed counter-clockwise, by these numbers. Every triangle of
the final mesh is passed exactly once; so is every vertex of the mesh
(isolated input points inside the domain are vertices of triangles too).

The class is a usable sink that discards everything; derive from it and
override what you need. The streaming file writers of
`Advancing_front_mesh_2::IO::Streaming_mesh_writer` derive from it.

\tparam Point the triangulation's point type
*/
template <class Point>
class Mesh_sink_2
{
public:
  virtual ~Mesh_sink_2() = default;

  /// receives vertex `index` (numbered from 0 without gaps)
  virtual void add_vertex(std::size_t /*index*/, const Point& /*p*/) {}

  /// receives a finished triangle, counter-clockwise
  virtual void add_triangle(std::size_t /*i*/, std::size_t /*j*/, std::size_t /*k*/) {}

  /*!
  receives a finished triangle, counter-clockwise, with the points of its
  vertices: the mesher calls this one. By default it calls
  `add_triangle(i, j, k)`; a sink that needs the geometry of the triangles
  without keeping every vertex in memory overrides it (as
  `IO::Streaming_tagging_sink_2` does to find the region of each triangle).
  */
  virtual void add_finished_triangle(std::size_t i, std::size_t j, std::size_t k, const Point& /*a*/,
                                     const Point& /*b*/, const Point& /*c*/)
  {
    add_triangle(i, j, k);
  }

  /*!
  Called when the mesher writes a checkpoint: makes everything received so
  far durable, and returns what a sink of the same type needs to continue
  the output later exactly from this point (it is stored in the checkpoint
  and given back by `Advancing_front_mesher_2::resume()`).

  \throws std::logic_error by default: a sink that cannot continue an
  output cannot take part in a checkpoint.
  */
  virtual std::string checkpoint_state()
  {
    throw std::logic_error("this mesh sink cannot continue its output after a restart, so it cannot checkpoint");
  }
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_MESH_SINK_2_H
