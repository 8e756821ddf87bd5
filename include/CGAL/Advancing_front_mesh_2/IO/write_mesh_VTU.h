// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_VTU_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_VTU_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_tagged_view.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <array>
#include <cstddef>
#include <ostream>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// A VTK unstructured grid in ASCII: the view's points (z = 0), its
// triangles (type 5) and, when tagged, its segments as lines (type 3) after
// them, with the markers as point and cell data and the region attribute
// as cell data.
template <class CDT>
void mesh_write_vtu(std::ostream& os, const Mesh_domain_view<CDT>& m)
{
  const std::size_t nt = m.triangles.size(), ns = m.tagged ? m.segments.size() : 0;
  os << "<?xml version=\"1.0\"?>\n"
     << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
     << "<UnstructuredGrid>\n"
     << "<Piece NumberOfPoints=\"" << m.points.size() << "\" NumberOfCells=\"" << (nt + ns) << "\">\n";
  os << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for(const std::array<double, 2>& p : m.points) os << p[0] << ' ' << p[1] << " 0\n";
  os << "</DataArray>\n</Points>\n";
  os << "<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for(const std::array<std::size_t, 3>& t : m.triangles) os << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  for(std::size_t i = 0; i < ns; ++i) os << m.segments[i][0] << ' ' << m.segments[i][1] << '\n';
  os << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for(std::size_t t = 1; t <= nt; ++t) os << 3 * t << '\n';
  for(std::size_t i = 1; i <= ns; ++i) os << 3 * nt + 2 * i << '\n';
  os << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for(std::size_t t = 0; t < nt; ++t) os << "5\n";
  for(std::size_t i = 0; i < ns; ++i) os << "3\n";
  os << "</DataArray>\n</Cells>\n";
  if(m.tagged) {
    os << "<PointData Scalars=\"marker\">\n<DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">\n";
    for(int k : m.point_markers) os << k << '\n';
    os << "</DataArray>\n</PointData>\n";
    os << "<CellData Scalars=\"marker\">\n<DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">\n";
    for(std::size_t t = 0; t < nt; ++t) os << "0\n";
    for(int k : m.segment_markers) os << k << '\n';
    os << "</DataArray>\n";
    if(m.has_regions) {
      os << "<DataArray type=\"Float64\" Name=\"region\" format=\"ascii\">\n";
      for(double a : m.triangle_attributes) os << a << '\n';
      for(std::size_t i = 0; i < ns; ++i) os << "0\n";
      os << "</DataArray>\n";
    }
    os << "</CellData>\n";
  }
  os << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` as a VTK unstructured grid (`.vtu`,
ASCII): the points with z = 0 and one triangle cell (type 5) per triangle,
counter-clockwise, vertices and triangles selected and numbered as in
`write_OFF()` (only the vertices the triangles use).

\tparam CDT as in `write_OFF()`

\param os the output stream
\param cdt the meshed triangulation
*/
template <class CDT>
void write_mesh_VTU(std::ostream& os, const CDT& cdt)
{
  internal::mesh_write_view(os, cdt, static_cast<const Markers_and_regions_2<CDT>*>(nullptr),
                            internal::mesh_write_vtu<CDT>);
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` with their markers and regions as a
VTK unstructured grid (`.vtu`, ASCII): the triangles as in
`write_mesh_VTU(std::ostream&, const CDT&)`, then the segments of the mesh
(the constrained edges beside the domain) as line cells (type 3), with
- point data `marker`: the marker of each vertex;
- cell data `marker`: the marker of each segment, 0 for the triangles;
- cell data `region` (when `tags` has regions): the region attribute of
  each triangle (0 outside every region), 0 for the segments.

The markers are those of `Markers_and_regions_2`.

\param os the output stream
\param cdt the meshed triangulation
\param tags its markers and regions, with `Markers_and_regions_2::mark_regions()`
called on the current faces of `cdt` when there are regions
*/
template <class CDT>
void write_mesh_VTU(std::ostream& os, const CDT& cdt, const Markers_and_regions_2<CDT>& tags)
{
  internal::mesh_write_view(os, cdt, &tags, internal::mesh_write_vtu<CDT>);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_VTU_H
