// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_GMSH_MSH_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_GMSH_MSH_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_tagged_view.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstddef>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// A bounding box of points, as $Entities gives it (z = 0).
struct Msh_box
{
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  bool empty = true;
  void add(const std::array<double, 2>& p)
  {
    if(empty) {
      xmin = xmax = p[0];
      ymin = ymax = p[1];
      empty = false;
      return;
    }
    xmin = (std::min)(xmin, p[0]); xmax = (std::max)(xmax, p[0]);
    ymin = (std::min)(ymin, p[1]); ymax = (std::max)(ymax, p[1]);
  }
};

inline std::ostream& operator<<(std::ostream& os, const Msh_box& b)
{
  return os << b.xmin << ' ' << b.ymin << " 0 " << b.xmax << ' ' << b.ymax << " 0";
}

// The shortest decimal that reads back to `v`, for the names of groups.
inline std::string msh_number_name(double v)
{
  char b[32];
  return std::string(b, std::to_chars(b, b + sizeof(b), v).ptr);
}

// One entity of the tagged file: a curve per boundary marker, a surface per
// region attribute; its physical group has the marker or attribute as tag
// when that is a positive int (what Gmsh accepts), the next free tag above
// them otherwise.
struct Msh_group
{
  double key = 0;
  int physical = 0;
  std::string name;
  std::vector<std::size_t> items; // segments or triangles of the view
  Msh_box box;
};

inline std::vector<Msh_group> msh_groups(const std::map<double, std::vector<std::size_t> >& by_key,
                                         const std::string& prefix)
{
  std::vector<Msh_group> groups;
  int largest = 0;
  for(const auto& k : by_key)
    if(k.first >= 1 && k.first <= INT_MAX && k.first == std::floor(k.first))
      largest = (std::max)(largest, static_cast<int>(k.first));
  for(const auto& k : by_key) {
    Msh_group g;
    g.key = k.first;
    const bool own_tag = k.first >= 1 && k.first <= INT_MAX && k.first == std::floor(k.first);
    g.physical = own_tag ? static_cast<int>(k.first) : ++largest;
    g.name = prefix + msh_number_name(k.first);
    g.items = k.second;
    groups.push_back(g);
  }
  return groups;
}

// The untagged layout: one surface entity, no physical groups (Gmsh then
// keeps all elements, whereas a physical group would make it drop anything
// outside it).
template <class CDT>
void msh_write_plain(std::ostream& os, const Mesh_domain_view<CDT>& m)
{
  const std::size_t nv = m.points.size(), nf = m.triangles.size();
  Msh_box box;
  for(const std::array<double, 2>& p : m.points) box.add(p);

  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  // numPoints numCurves numSurfaces numVolumes, then the surface:
  // tag minX minY minZ maxX maxY maxZ numPhysicalTags numBoundingCurves
  os << "$Entities\n0 0 1 0\n"
     << "1 " << box << " 0 0\n"
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

// The tagged layout: a curve entity per segment marker holding the segments
// as 2-node lines, a surface entity per region attribute (one, "domain",
// without regions), each in a physical group named after it.
template <class CDT>
void msh_write_tagged(std::ostream& os, const Mesh_domain_view<CDT>& m)
{
  std::map<double, std::vector<std::size_t> > by_marker, by_attribute;
  for(std::size_t i = 0; i < m.segments.size(); ++i) by_marker[m.segment_markers[i]].push_back(i);
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
    by_attribute[m.has_regions ? m.triangle_attributes[t] : 1.].push_back(t);
  std::vector<Msh_group> curves = msh_groups(by_marker, "marker_");
  std::vector<Msh_group> surfaces = msh_groups(by_attribute, "region_");
  if(!m.has_regions && !surfaces.empty()) surfaces[0].name = "domain";
  for(Msh_group& c : curves)
    for(std::size_t i : c.items) {
      c.box.add(m.points[m.segments[i][0]]);
      c.box.add(m.points[m.segments[i][1]]);
    }
  for(Msh_group& s : surfaces)
    for(std::size_t t : s.items)
      for(std::size_t v : m.triangles[t]) s.box.add(m.points[v]);

  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  os << "$PhysicalNames\n" << (curves.size() + surfaces.size()) << '\n';
  for(const Msh_group& c : curves) os << "1 " << c.physical << " \"" << c.name << "\"\n";
  for(const Msh_group& s : surfaces) os << "2 " << s.physical << " \"" << s.name << "\"\n";
  os << "$EndPhysicalNames\n";

  // curve: tag box numPhysicalTags tags numBoundingPoints;
  // surface: tag box numPhysicalTags tags numBoundingCurves
  os << "$Entities\n0 " << curves.size() << ' ' << surfaces.size() << " 0\n";
  for(std::size_t c = 0; c < curves.size(); ++c)
    os << (c + 1) << ' ' << curves[c].box << " 1 " << curves[c].physical << " 0\n";
  for(std::size_t s = 0; s < surfaces.size(); ++s)
    os << (s + 1) << ' ' << surfaces[s].box << " 1 " << surfaces[s].physical << " 0\n";
  os << "$EndEntities\n";

  // All nodes in one block on the first surface: elements of any entity may
  // use them.
  const std::size_t nv = m.points.size();
  os << "$Nodes\n";
  if(nv == 0 || surfaces.empty()) {
    os << "0 0 0 0\n";
  } else {
    os << "1 " << nv << " 1 " << nv << '\n' << "2 1 0 " << nv << '\n';
    for(std::size_t i = 1; i <= nv; ++i) os << i << '\n';
    for(const std::array<double, 2>& p : m.points) os << p[0] << ' ' << p[1] << " 0\n";
  }
  os << "$EndNodes\n";

  const std::size_t ne = m.segments.size() + m.triangles.size();
  os << "$Elements\n";
  if(ne == 0) {
    os << "0 0 0 0\n";
  } else {
    os << (curves.size() + surfaces.size()) << ' ' << ne << " 1 " << ne << '\n';
    std::size_t tag = 0;
    for(std::size_t c = 0; c < curves.size(); ++c) {
      os << "1 " << (c + 1) << " 1 " << curves[c].items.size() << '\n';
      for(std::size_t i : curves[c].items)
        os << ++tag << ' ' << (m.segments[i][0] + 1) << ' ' << (m.segments[i][1] + 1) << '\n';
    }
    for(std::size_t s = 0; s < surfaces.size(); ++s) {
      os << "2 " << (s + 1) << " 2 " << surfaces[s].items.size() << '\n';
      for(std::size_t t : surfaces[s].items) {
        const std::array<std::size_t, 3>& tr = m.triangles[t];
        os << ++tag << ' ' << (tr[0] + 1) << ' ' << (tr[1] + 1) << ' ' << (tr[2] + 1) << '\n';
      }
    }
  }
  os << "$EndElements\n";
}

} // namespace internal

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
  internal::mesh_write_view(os, cdt, static_cast<const Markers_and_regions_2<CDT>*>(nullptr),
                            internal::msh_write_plain<CDT>);
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` with their markers and regions in
the Gmsh MSH 4.1 ASCII format, as `gmsh -2` writes a `.geo` with physical
groups:
- one curve entity per segment marker (the markers of
  `Markers_and_regions_2`), holding the segments of the mesh with that
  marker as 2-node line elements (type 1), in the physical group
  `marker_M`;
- one surface entity per region attribute, holding the triangles of the
  regions with that attribute, in the physical group `region_A` (triangles
  outside every region have attribute 0); without regions, one surface in
  the physical group `domain`.

A physical group's tag is its marker or attribute when that is a positive
integer, and otherwise the next free tag above those. All nodes are in one
block on the first surface; node tags are 1-based and contiguous, element
tags too (lines first). Vertices and triangles are selected and numbered as
in `write_OFF()`.

\param os the output stream
\param cdt the meshed triangulation
\param tags its markers and regions, with `Markers_and_regions_2::mark_regions()`
called on the current faces of `cdt` when there are regions
*/
template <class CDT>
void write_gmsh_msh(std::ostream& os, const CDT& cdt, const Markers_and_regions_2<CDT>& tags)
{
  internal::mesh_write_view(os, cdt, &tags, internal::msh_write_tagged<CDT>);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_GMSH_MSH_H
