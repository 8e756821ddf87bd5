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
#include <CGAL/Advancing_front_mesh_2/IO/internal/Vtu_layout.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <CGAL/Named_function_parameters.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// A VTK unstructured grid (layout of Vtu_layout.h): the view's points
// (z = 0), its triangles (type 5) and, when tagged, its segments as lines
// (type 3) after them, with the markers as point and cell data and the
// region attribute as cell data; raw appended binary, or ASCII.
template <class CDT>
void mesh_write_vtu(std::ostream& os, const Mesh_domain_view<CDT>& m, bool binary)
{
  const std::uint64_t nv = m.points.size(), nt = m.triangles.size(), ns = m.tagged ? m.segments.size() : 0;
  std::vector<Vtu_array> arrays;
  // In binary, each array is made in a buffer and written at once.
  std::string raw;
  auto flush_raw = [&] {
    os.write(raw.data(), static_cast<std::streamsize>(raw.size()));
    raw.clear();
  };
  arrays.push_back({Vtu_section::POINTS, "type=\"Float64\" NumberOfComponents=\"3\"", 24 * nv, [&] {
    for(const std::array<double, 2>& p : m.points) {
      if(!binary) { os << p[0] << ' ' << p[1] << " 0\n"; continue; }
      vtu_append_raw(raw, p[0]); vtu_append_raw(raw, p[1]); vtu_append_raw(raw, 0.);
    }
    flush_raw();
  }});
  arrays.push_back({Vtu_section::CELLS, "type=\"Int64\" Name=\"connectivity\"", 8 * (3 * nt + 2 * ns), [&] {
    for(const std::array<std::size_t, 3>& t : m.triangles) {
      if(!binary) { os << t[0] << ' ' << t[1] << ' ' << t[2] << '\n'; continue; }
      for(std::size_t v : t) vtu_append_raw(raw, std::int64_t(v));
    }
    for(std::size_t i = 0; i < ns; ++i) {
      if(!binary) { os << m.segments[i][0] << ' ' << m.segments[i][1] << '\n'; continue; }
      for(std::size_t v : m.segments[i]) vtu_append_raw(raw, std::int64_t(v));
    }
    flush_raw();
  }});
  arrays.push_back({Vtu_section::CELLS, "type=\"Int64\" Name=\"offsets\"", 8 * (nt + ns), [&] {
    for(std::uint64_t t = 1; t <= nt; ++t) {
      if(!binary) os << 3 * t << '\n';
      else vtu_append_raw(raw, std::int64_t(3 * t));
    }
    for(std::uint64_t i = 1; i <= ns; ++i) {
      if(!binary) os << 3 * nt + 2 * i << '\n';
      else vtu_append_raw(raw, std::int64_t(3 * nt + 2 * i));
    }
    flush_raw();
  }});
  arrays.push_back({Vtu_section::CELLS, "type=\"UInt8\" Name=\"types\"", nt + ns, [&] {
    if(!binary) {
      for(std::uint64_t t = 0; t < nt; ++t) os << "5\n";
      for(std::uint64_t i = 0; i < ns; ++i) os << "3\n";
      return;
    }
    raw.assign(nt, char(5));
    raw.append(ns, char(3));
    flush_raw();
  }});
  if(m.tagged) {
    arrays.push_back({Vtu_section::POINT_DATA, "type=\"Int32\" Name=\"marker\"", 4 * nv, [&] {
      for(int k : m.point_markers) {
        if(!binary) os << k << '\n';
        else vtu_append_raw(raw, std::int32_t(k));
      }
      flush_raw();
    }});
    arrays.push_back({Vtu_section::CELL_DATA, "type=\"Int32\" Name=\"marker\"", 4 * (nt + ns), [&] {
      for(std::uint64_t t = 0; t < nt; ++t) {
        if(!binary) os << "0\n";
        else vtu_append_raw(raw, std::int32_t(0));
      }
      for(int k : m.segment_markers) {
        if(!binary) os << k << '\n';
        else vtu_append_raw(raw, std::int32_t(k));
      }
      flush_raw();
    }});
    if(m.has_regions)
      arrays.push_back({Vtu_section::CELL_DATA, "type=\"Float64\" Name=\"region\"", 8 * (nt + ns), [&] {
        for(double a : m.triangle_attributes) {
          if(!binary) os << a << '\n';
          else vtu_append_raw(raw, a);
        }
        for(std::uint64_t i = 0; i < ns; ++i) {
          if(!binary) os << "0\n";
          else vtu_append_raw(raw, 0.);
        }
        flush_raw();
      }});
  }
  struct Out
  {
    std::ostream& os;
    void put(const char* s, std::size_t n) { os.write(s, static_cast<std::streamsize>(n)); }
  } out{os};
  vtu_write(out, nv, nt + ns, arrays, binary);
}

template <class CDT, class NamedParameters>
void mesh_write_vtu(std::ostream& os, const CDT& cdt, const Markers_and_regions_2<CDT>* tags,
                    const NamedParameters& np)
{
  const bool binary = parameters::choose_parameter(parameters::get_parameter(np, internal_np::use_binary_mode), true);
  mesh_write_view(os, cdt, tags, [binary](std::ostream& o, const Mesh_domain_view<CDT>& m) {
    mesh_write_vtu(o, m, binary);
  });
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` as a VTK unstructured grid (`.vtu`):
the points with z = 0 and one triangle cell (type 5) per triangle,
counter-clockwise, vertices and triangles selected and numbered as in
`write_OFF()` (only the vertices the triangles use).

By default the arrays are binary: one raw appended block (`<AppendedData
encoding="raw">`), each array preceded by its size in bytes as a UInt64
(`header_type="UInt64"`), in the byte order of the writing machine (given
by `byte_order`), with 64-bit connectivity and offsets. VTK, ParaView and
meshio read it; it is about 40% of the size of the ASCII file and faster to
write and read. With `use_binary_mode(false)` the arrays are ASCII, the
numbers written so that they read back exactly. Open a file stream in
binary mode (`std::ios::binary`) for the binary layout.

\tparam CDT as in `write_OFF()`
\tparam NamedParameters a sequence of named parameters

\param os the output stream
\param cdt the meshed triangulation
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{use_binary_mode}
    \cgalParamDescription{whether the arrays are written in binary (raw appended) or in ASCII}
    \cgalParamType{Boolean}
    \cgalParamDefault{`true`}
  \cgalParamNEnd
\cgalNamedParamsEnd
*/
template <class CDT, class NamedParameters = parameters::Default_named_parameters>
void write_mesh_VTU(std::ostream& os, const CDT& cdt, const NamedParameters& np = parameters::default_values())
{
  internal::mesh_write_vtu(os, cdt, static_cast<const Markers_and_regions_2<CDT>*>(nullptr), np);
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` with their markers and regions as a
VTK unstructured grid (`.vtu`, binary unless `use_binary_mode(false)`): the
triangles as in `write_mesh_VTU(std::ostream&, const CDT&, const NamedParameters&)`, then the segments of the mesh
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
\param np as in `write_mesh_VTU(std::ostream&, const CDT&, const NamedParameters&)`
*/
template <class CDT, class NamedParameters = parameters::Default_named_parameters>
void write_mesh_VTU(std::ostream& os, const CDT& cdt, const Markers_and_regions_2<CDT>& tags,
                    const NamedParameters& np = parameters::default_values())
{
  internal::mesh_write_vtu(os, cdt, &tags, np);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_VTU_H
