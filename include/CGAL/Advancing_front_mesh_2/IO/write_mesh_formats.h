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

#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_tagged_view.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_gmsh_msh.h>
#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/centroid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// Triangle's .node: with tags, one boundary marker per vertex.
template <class CDT>
void mesh_write_node(std::ostream& os, const Mesh_domain_view<CDT>& m)
{
  Text_output out(os);
  out.put_uint(m.points.size()).put(" 2 0 ").put(m.tagged ? '1' : '0').put('\n');
  for(std::size_t i = 0; i < m.points.size(); ++i) {
    out.put_uint(i + 1).put(' ').put_double(m.points[i][0]).put(' ').put_double(m.points[i][1]);
    if(m.tagged) out.put(' ').put_int(m.point_markers[i]);
    out.put('\n');
  }
  out.flush();
}

// Triangle's .ele: with regions, the regional attribute of each triangle.
template <class CDT>
void mesh_write_ele(std::ostream& os, const Mesh_domain_view<CDT>& m)
{
  Text_output out(os);
  out.put_uint(m.triangles.size()).put(" 3 ").put(m.has_regions ? '1' : '0').put('\n');
  for(std::size_t i = 0; i < m.triangles.size(); ++i) {
    const std::array<std::size_t, 3>& t = m.triangles[i];
    out.put_uint(i + 1).put(' ').put_uint(t[0] + 1).put(' ').put_uint(t[1] + 1).put(' ').put_uint(t[2] + 1);
    if(m.has_regions) out.put(' ').put_double(m.triangle_attributes[i]);
    out.put('\n');
  }
  out.flush();
}

// Triangle's .edge, of the segments only: with tags, their markers.
template <class CDT>
void mesh_write_edge(std::ostream& os, const Mesh_domain_view<CDT>& m)
{
  Text_output out(os);
  out.put_uint(m.segments.size()).put(' ').put(m.tagged ? '1' : '0').put('\n');
  for(std::size_t i = 0; i < m.segments.size(); ++i) {
    out.put_uint(i + 1).put(' ').put_uint(m.segments[i][0] + 1).put(' ').put_uint(m.segments[i][1] + 1);
    if(m.tagged) out.put(' ').put_int(m.segment_markers[i]);
    out.put('\n');
  }
  out.flush();
}


// write_OFF() without a Mesh_domain_view: the triangles' vertex numbers in
// `Index` (32 bits below 2^32 vertices), and the points written from a
// second walk over the faces in the same order (a vertex is written where
// its number first appears) instead of copied. At a million triangles the
// view's copies (60 MB) were a third of the run's peak memory; this keeps
// the numbering table and 3 indices a triangle. The file is the one the
// view gives, byte for byte (test_io_write_off checks both widths).
template <class Index, class CDT>
void mesh_write_OFF_lean(std::ostream& os, const CDT& cdt)
{
  CGAL::Advancing_front_mesh_2::internal::Flat_hash_map<const void*, Index> index(nullptr);
  index.reserve(cdt.number_of_vertices());
  std::vector<std::array<Index, 3> > triangles;
  triangles.reserve(cdt.number_of_faces());
  Index next = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    std::array<Index, 3> t;
    for(int i = 0; i < 3; ++i) {
      const void* v = &*f->vertex(i);
      const Index* k = index.find(v);
      t[i] = k != nullptr ? *k : index.insert(v, next++);
    }
    triangles.push_back(t);
  }
  Text_output out(os);
  out.put("OFF\n").put_uint(next).put(' ').put_uint(triangles.size()).put(" 0\n");
  Index written = 0;
  std::size_t t = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end() && written < next; ++f) {
    if(!f->is_in_domain()) continue;
    for(int i = 0; i < 3; ++i)
      if(triangles[t][i] == written) {
        const auto& p = f->vertex(i)->point();
        out.put_double(CGAL::to_double(p.x())).put(' ').put_double(CGAL::to_double(p.y())).put(" 0\n");
        ++written;
      }
    ++t;
  }
  for(const std::array<Index, 3>& tr : triangles)
    out.put("3 ").put_uint(tr[0]).put(' ').put_uint(tr[1]).put(' ').put_uint(tr[2]).put('\n');
  out.flush();
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` in the OFF format: the header `OFF`,
the line `nv nf 0`, the vertices as `x y 0` and the faces as `3 i j k`
(0-based, counter-clockwise).

Only finite faces with `is_in_domain()` are written, and only the vertices
they use, numbered in order of first appearance when iterating over the
finite faces. Coordinates are written as the shortest decimals that read
back to the same doubles (`std::to_chars()`), whatever the stream's locale
and formatting; the stream's state is left as it was.

\tparam CDT a `Constrained_Delaunay_triangulation_2` or
`Constrained_triangulation_plus_2` whose face base is a model of
`DelaunayMeshFaceBase_2`

\param os the output stream
\param cdt the meshed triangulation
*/
template <class CDT>
void write_OFF(std::ostream& os, const CDT& cdt)
{
  if(cdt.number_of_vertices() < (std::numeric_limits<std::uint32_t>::max)())
    internal::mesh_write_OFF_lean<std::uint32_t>(os, cdt);
  else
    internal::mesh_write_OFF_lean<std::uint64_t>(os, cdt);
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

Writes the in-domain triangles of `cdt` with their markers and regions in
Triangle's `.node`, `.ele` and `.edge` formats, to three streams, as
Triangle writes them with `-pA` (and `-e` restricted to the segments):
- `.node`: one boundary marker per vertex;
- `.ele`: when `tags` has regions, one attribute per triangle, the
  attribute of its region (0 outside every region);
- `.edge`: the segments of the mesh (the constrained edges beside the
  domain, a boundary edge with the domain on its left) and their markers.

The markers are those of `Markers_and_regions_2`; vertices and triangles are
selected and numbered as in `write_OFF()`.

\tparam CDT as in `write_OFF()`

\param node_os receives the `.node` content
\param ele_os receives the `.ele` content
\param edge_os receives the `.edge` content
\param cdt the meshed triangulation
\param tags its markers and regions, with `Markers_and_regions_2::mark_regions()`
called on the current faces of `cdt` when there are regions
*/
template <class CDT>
void write_triangle_node_ele(std::ostream& node_os, std::ostream& ele_os, std::ostream& edge_os,
                             const CDT& cdt, const Markers_and_regions_2<CDT>& tags)
{
  internal::Mesh_domain_view<CDT> m;
  internal::mesh_collect(cdt, &tags, m);
  internal::mesh_write_node(node_os, m);
  internal::mesh_write_ele(ele_os, m);
  internal::mesh_write_edge(edge_os, m);
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

Writes the in-domain triangles of `cdt` with their markers and regions to
the files `basename.node`, `basename.ele` and `basename.edge`; see
`write_triangle_node_ele(std::ostream&, std::ostream&, std::ostream&, const CDT&, const Markers_and_regions_2<CDT>&)`.

\throws std::runtime_error "cannot write FILE" when a file cannot be opened
or written
*/
template <class CDT>
void write_triangle_node_ele(const std::string& basename, const CDT& cdt, const Markers_and_regions_2<CDT>& tags)
{
  internal::Mesh_domain_view<CDT> m;
  internal::mesh_collect(cdt, &tags, m);
  internal::mesh_write_file(basename + ".node",
                            [&](std::ostream& os) { internal::mesh_write_node(os, m); });
  internal::mesh_write_file(basename + ".ele",
                            [&](std::ostream& os) { internal::mesh_write_ele(os, m); });
  internal::mesh_write_file(basename + ".edge",
                            [&](std::ostream& os) { internal::mesh_write_edge(os, m); });
}

namespace internal {

// A point strictly inside each bounded region outside the domain (a hole of
// the mesh): the centroid of its largest face, checked with the exact
// orientation predicate in doubles (a face whose rounded centroid is not
// strictly inside is passed over).
template <class CDT>
std::vector<std::array<double, 2> > mesh_hole_points(const CDT& cdt)
{
  typedef typename CDT::Face_handle Face_handle;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Ek;
  std::vector<std::array<double, 2> > holes;
  CGAL::Unique_hash_map<Face_handle, bool> seen(false, cdt.number_of_faces());
  auto ep = [](const typename CDT::Vertex_handle v) {
    return Ek::Point_2(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()));
  };
  for(auto f0 = cdt.all_faces_begin(); f0 != cdt.all_faces_end(); ++f0) {
    const Face_handle start = f0;
    if(seen[start] || (!cdt.is_infinite(start) && start->is_in_domain())) continue;
    std::vector<Face_handle> component, stack(1, start);
    seen[start] = true;
    bool bounded = true;
    while(!stack.empty()) {
      const Face_handle f = stack.back();
      stack.pop_back();
      component.push_back(f);
      if(cdt.is_infinite(f)) bounded = false;
      for(int i = 0; i < 3; ++i) {
        const Face_handle g = f->neighbor(i);
        if(cdt.is_constrained(std::make_pair(f, i)) || seen[g]) continue;
        seen[g] = true;
        stack.push_back(g);
      }
    }
    if(!bounded) continue;
    std::sort(component.begin(), component.end(), [&](Face_handle a, Face_handle b) {
      const double area_a = std::abs(CGAL::area(ep(a->vertex(0)), ep(a->vertex(1)), ep(a->vertex(2))));
      const double area_b = std::abs(CGAL::area(ep(b->vertex(0)), ep(b->vertex(1)), ep(b->vertex(2))));
      return area_a > area_b;
    });
    for(const Face_handle f : component) {
      const Ek::Point_2 a = ep(f->vertex(0)), b = ep(f->vertex(1)), c = ep(f->vertex(2));
      const Ek::Point_2 g = CGAL::centroid(a, b, c);
      const CGAL::Orientation o = CGAL::orientation(a, b, c);
      if(o != CGAL::COLLINEAR && CGAL::orientation(a, b, g) == o && CGAL::orientation(b, c, g) == o &&
         CGAL::orientation(c, a, g) == o) {
        holes.push_back({{g.x(), g.y()}});
        break;
      }
    }
  }
  return holes;
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the boundary of the meshed domain of `cdt` in Triangle's `.poly`
format, so that it can be meshed again or handed to another mesher: the end
points of the segments of the mesh (the constrained edges beside the
domain) with their markers, the segments with their markers, one hole seed
inside each bounded region that is not meshed, and the regions of `tags`
(seed, attribute, area limit). `read_poly()` reads it back; meshing it
gives the same domain.

\tparam CDT as in `write_OFF()`

\param os the output stream
\param cdt the meshed triangulation
\param tags its markers and regions

\throws std::invalid_argument as `write_poly()`
*/
template <class CDT>
void write_boundary_poly(std::ostream& os, const CDT& cdt, const Markers_and_regions_2<CDT>& tags)
{
  internal::Mesh_domain_view<CDT> m;
  internal::mesh_collect_domain(cdt, m);
  Poly_data poly;
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  std::vector<std::size_t> renumbered(m.points.size(), none);
  for(std::size_t i = 0; i < m.segments.size(); ++i) {
    std::array<std::size_t, 2> s;
    for(int k = 0; k < 2; ++k) {
      std::size_t& r = renumbered[m.segments[i][k]];
      if(r == none) {
        r = poly.points.size();
        poly.points.push_back(m.points[m.segments[i][k]]);
        poly.point_markers.push_back(tags.vertex_marker(cdt, m.vertices[m.segments[i][k]]));
      }
      s[k] = r;
    }
    poly.segments.push_back(s);
    poly.segment_markers.push_back(tags.edge_marker(cdt, m.segment_edges[i].first, m.segment_edges[i].second));
  }
  poly.holes = internal::mesh_hole_points(cdt);
  for(const auto& r : tags.regions()) {
    Poly_data::Region region;
    region.seed = {{CGAL::to_double(r.seed.x()), CGAL::to_double(r.seed.y())}};
    region.attribute = r.attribute;
    region.max_area = r.max_area;
    poly.regions.push_back(region);
  }
  write_poly(os, poly);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_FORMATS_H
