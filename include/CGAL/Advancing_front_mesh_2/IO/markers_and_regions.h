// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_MARKERS_AND_REGIONS_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_MARKERS_AND_REGIONS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <cstddef>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

/*!
\ingroup PkgAdvancingFrontMesh2IO

The markers and regions of the planar straight-line graph `data`, on the
vertices and constrained edges `insert_poly()` made of it (`inserted`):
- each point's marker on its vertex; of points merged into one vertex, the
  first with a marker other than 0 gives it;
- each kept segment's marker on every edge it became (split at the points
  inside it); segments are given in file order, which decides between the
  markers of the segments at a vertex (see `Markers_and_regions_2`);
- the regions, in file order.

Markers are set only when the file has them; the rules of
`Markers_and_regions_2` then give boundary vertices and edges the marker 1
and interior ones 0, as Triangle does.

\tparam CDT the triangulation `insert_poly()` filled
*/
template <class CDT>
Markers_and_regions_2<CDT> markers_and_regions(const Poly_data& data, const Poly_insertion<CDT>& inserted)
{
  typedef typename CDT::Point Point;
  Markers_and_regions_2<CDT> tags;
  // last to first: the first point with a marker other than 0 is set last
  for(std::size_t i = data.point_markers.size(); i-- > 0;)
    if(data.point_markers[i] != 0) tags.set_vertex_marker(inserted.vertices[i], data.point_markers[i]);
  if(!data.segment_markers.empty())
    for(const auto& piece : inserted.segment_pieces)
      tags.set_constraint_marker(piece.a, piece.b, data.segment_markers[piece.segment]);
  for(const Poly_data::Region& r : data.regions)
    tags.add_region(Point(r.seed[0], r.seed[1]), r.attribute, r.max_area);
  return tags;
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_MARKERS_AND_REGIONS_H
