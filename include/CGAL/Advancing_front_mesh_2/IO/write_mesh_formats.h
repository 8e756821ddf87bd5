// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_FORMATS_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_FORMATS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>

#include <boost/io/ios_state.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <ostream>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

template <class CDT>
void mesh_write_node(std::ostream& os, const Mesh_domain_view<CDT>& m)
{
  // formatting and locale only: restoring the error state would hide a failed write
  boost::io::ios_base_all_saver format_saver(os);
  boost::io::ios_locale_saver locale_saver(os);
  mesh_set_exact_format(os);
  os << m.points.size() << " 2 0 0\n";
  for(std::size_t i = 0; i < m.points.size(); ++i)
    os << (i + 1) << ' ' << m.points[i][0] << ' ' << m.points[i][1] << '\n';
}

template <class CDT>
void mesh_write_ele(std::ostream& os, const Mesh_domain_view<CDT>& m)
{
  // formatting and locale only: restoring the error state would hide a failed write
  boost::io::ios_base_all_saver format_saver(os);
  boost::io::ios_locale_saver locale_saver(os);
  mesh_set_exact_format(os);
  os << m.triangles.size() << " 3 0\n";
  for(std::size_t i = 0; i < m.triangles.size(); ++i) {
    const std::array<std::size_t, 3>& t = m.triangles[i];
    os << (i + 1) << ' ' << (t[0] + 1) << ' ' << (t[1] + 1) << ' ' << (t[2] + 1) << '\n';
  }
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` in the OFF format: the header `OFF`,
the line `nv nf 0`, the vertices as `x y 0` and the faces as `3 i j k`
(0-based, counter-clockwise).

Only finite faces with `is_in_domain()` are written, and only the vertices
they use, numbered in order of first appearance when iterating over the
finite faces. Coordinates are written with `max_digits10` digits, so they
read back exactly. The stream's formatting state is restored afterwards.

\tparam CDT a `Constrained_Delaunay_triangulation_2` or
`Constrained_triangulation_plus_2` whose face base is a model of
`DelaunayMeshFaceBase_2`

\param os the output stream
\param cdt the meshed triangulation
*/
template <class CDT>
void write_OFF(std::ostream& os, const CDT& cdt)
{
  internal::Mesh_domain_view<CDT> m;
  internal::mesh_collect_domain(cdt, m);
  // formatting and locale only: restoring the error state would hide a failed write
  boost::io::ios_base_all_saver format_saver(os);
  boost::io::ios_locale_saver locale_saver(os);
  internal::mesh_set_exact_format(os);
  os << "OFF\n" << m.points.size() << ' ' << m.triangles.size() << " 0\n";
  for(const std::array<double, 2>& p : m.points)
    os << p[0] << ' ' << p[1] << " 0\n";
  for(const std::array<std::size_t, 3>& t : m.triangles)
    os << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` in Triangle's `.node` and `.ele`
formats (1-based ids, no attributes, no boundary markers), to two streams.

Both are written from a single traversal so that the vertex ids used in
`ele_os` are those of `node_os`; vertices and triangles are selected and
numbered as in `write_OFF()`.

\tparam CDT as in `write_OFF()`

\param node_os receives the `.node` content
\param ele_os receives the `.ele` content
\param cdt the meshed triangulation
*/
template <class CDT>
void write_triangle_node_ele(std::ostream& node_os, std::ostream& ele_os,
                             const CDT& cdt)
{
  internal::Mesh_domain_view<CDT> m;
  internal::mesh_collect_domain(cdt, m);
  internal::mesh_write_node(node_os, m);
  internal::mesh_write_ele(ele_os, m);
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` to the files `basename.node` and
`basename.ele`; see
`write_triangle_node_ele(std::ostream&, std::ostream&, const CDT&)`.

\tparam CDT as in `write_OFF()`

\param basename path of the files without their extension
\param cdt the meshed triangulation

\throws std::runtime_error "cannot write FILE" when a file cannot be opened
or written
*/
template <class CDT>
void write_triangle_node_ele(const std::string& basename, const CDT& cdt)
{
  internal::Mesh_domain_view<CDT> m;
  internal::mesh_collect_domain(cdt, m);
  internal::mesh_write_file(basename + ".node",
                            [&](std::ostream& os) { internal::mesh_write_node(os, m); });
  internal::mesh_write_file(basename + ".ele",
                            [&](std::ostream& os) { internal::mesh_write_ele(os, m); });
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` in the Gmsh MSH 4.1 ASCII format.

The file holds one surface entity (tag 1) whose bounding box is that of the
written vertices, one node block on that entity without parametric
coordinates, and one element block of 3-node triangles (type 2); node and
element tags are 1-based and contiguous. No physical groups are written:
Gmsh then keeps all elements, whereas a physical group would make it drop
anything outside it. Vertices and triangles are selected and numbered as in
`write_OFF()`.

\tparam CDT as in `write_OFF()`

\param os the output stream
\param cdt the meshed triangulation
*/
template <class CDT>
void write_gmsh_msh(std::ostream& os, const CDT& cdt)
{
  internal::Mesh_domain_view<CDT> m;
  internal::mesh_collect_domain(cdt, m);
  // formatting and locale only: restoring the error state would hide a failed write
  boost::io::ios_base_all_saver format_saver(os);
  boost::io::ios_locale_saver locale_saver(os);
  internal::mesh_set_exact_format(os);

  const std::size_t nv = m.points.size(), nf = m.triangles.size();
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  if(nv != 0) {
    xmin = xmax = m.points[0][0];
    ymin = ymax = m.points[0][1];
    for(const std::array<double, 2>& p : m.points) {
      xmin = (std::min)(xmin, p[0]); xmax = (std::max)(xmax, p[0]);
      ymin = (std::min)(ymin, p[1]); ymax = (std::max)(ymax, p[1]);
    }
  }

  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  // numPoints numCurves numSurfaces numVolumes, then the surface:
  // tag minX minY minZ maxX maxY maxZ numPhysicalTags numBoundingCurves
  os << "$Entities\n0 0 1 0\n"
     << "1 " << xmin << ' ' << ymin << " 0 " << xmax << ' ' << ymax << " 0 0 0\n"
     << "$EndEntities\n";

  // numEntityBlocks numNodes minNodeTag maxNodeTag; an empty mesh has no block.
  os << "$Nodes\n";
  if(nv == 0) {
    os << "0 0 0 0\n";
  } else {
    os << "1 " << nv << " 1 " << nv << '\n'
       << "2 1 0 " << nv << '\n'; // entityDim entityTag parametric numNodesInBlock
    for(std::size_t i = 1; i <= nv; ++i)
      os << i << '\n';
    for(const std::array<double, 2>& p : m.points)
      os << p[0] << ' ' << p[1] << " 0\n";
  }
  os << "$EndNodes\n";

  os << "$Elements\n";
  if(nf == 0) {
    os << "0 0 0 0\n";
  } else {
    os << "1 " << nf << " 1 " << nf << '\n'
       << "2 1 2 " << nf << '\n'; // entityDim entityTag elementType numElementsInBlock
    for(std::size_t i = 0; i < nf; ++i) {
      const std::array<std::size_t, 3>& t = m.triangles[i];
      os << (i + 1) << ' ' << (t[0] + 1) << ' ' << (t[1] + 1) << ' ' << (t[2] + 1) << '\n';
    }
  }
  os << "$EndElements\n";
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_FORMATS_H
