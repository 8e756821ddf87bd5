// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_READ_POLY_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_READ_POLY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Poly_line_reader.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Poly_sections.h>

#include <boost/io/ios_state.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <ios>
#include <istream>
#include <limits>
#include <locale>
#include <ostream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads a planar straight-line graph in Triangle's `.poly` format
(https://www.cs.cmu.edu/~quake/triangle.poly.html) from `in`.

The reader is strict on purpose: a mesher fed a silently misread boundary
produces a plausible but wrong mesh, which is much harder to trace back than
an error naming the faulty line. Accepted input:
- `#` starts a comment anywhere on a line; blank lines are skipped;
- a header `<#vertices> <dimension> <#attributes> <#boundary markers>` with
  dimension 2 and 0 or 1 markers, followed by exactly that many vertex lines
  `id x y [attributes...] [marker]`. Ids start at 0 or 1 (the first one
  decides, as in Triangle) and are consecutive;
- a segment header `<#segments> <#boundary markers>` and the segment lines
  `id v1 v2 [marker]`, whose endpoints are vertex ids;
- a hole header `<#holes>` and the hole lines `id x y`;
- optionally a region header `<#regions>` and the region lines
  `id x y attribute [maximum area]`; as in Triangle, a line without its
  maximum area uses its attribute as the maximum area too;
- nothing but comments and blank lines after the last section.

Every line must hold exactly the number of values its section calls for:
unlike Triangle, the reader does not default omitted header fields, since a
short line is more often damage than shorthand. Every value must be a
complete number (integers where ids, counts and markers are expected), every
coordinate, attribute and area finite. Segment endpoints must be existing
vertices and distinct. Segment, hole and region ids follow the same rule as
vertex ids (Triangle ignores them, but ids out of order betray a damaged
file). Counts are at most 2147483647 (Triangle's `int`), attributes per
vertex at most 100000, and a line without its comment at most 1 MiB, so that
no input makes the reader allocate without bound. The input is read to its
end, to check that nothing follows the last section.

A header announcing 0 vertices means, as in Triangle, that the vertices are
in a `.node` file with the same base name: `file_name` with its `.poly`
extension replaced by `.node` (or with `.node` appended if it has none). That
file is read with the same rules and its errors name it and its own lines.

\param in the stream to read; it is read through its stream buffer, so its
formatting flags and locale do not matter
\param file_name the name used in error messages and to locate the `.node`
file

Vertex attributes are checked and dropped; boundary markers of vertices and
segments and the regions are kept (`Poly_data::point_markers`,
`Poly_data::segment_markers`, `Poly_data::regions`).

\returns the points, the segments as 0-based indices into the points, the
hole seeds, the markers and the regions

\throws Poly_read_error on any problem with the input
*/
inline Poly_data read_poly(std::istream& in, const std::string& file_name)
{
  internal::Poly_line_reader r(in, file_name);
  Poly_data data;
  data.origin.file = file_name;
  const long long vertex_base = internal::poly_read_vertex_section(r, file_name, data);
  internal::poly_read_segments(r, vertex_base, data);
  internal::poly_read_holes(r, data);
  internal::poly_read_regions(r, data);
  return data;
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads the Triangle `.poly` file `file_name`; see
`read_poly(std::istream&, const std::string&)` for the accepted format.

\param file_name path of the `.poly` file

\throws Poly_read_error with the message "cannot open file" when the file
cannot be opened, and on any problem with its content
*/
inline Poly_data read_poly(const std::string& file_name)
{
  // Binary mode: line ends are handled by the reader itself, and the line
  // numbers must match what an editor shows.
  std::ifstream in(file_name.c_str(), std::ios::in | std::ios::binary);
  if(!in)
    throw Poly_read_error(file_name, 0, "cannot open file");
  return read_poly(in, file_name);
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes `data` in Triangle's `.poly` format with 1-based ids and no vertex
attributes; boundary markers of points and segments are written when
`data` has them, and the region section when it has regions.

Coordinates are written with `max_digits10` significant digits and in the
classic locale, so that `read_poly()` gives back exactly the same doubles
whatever the stream's formatting state; that state is restored afterwards.

\param os the output stream
\param data the graph to write

\throws std::invalid_argument if a coordinate, attribute or area is not
finite, a segment has an endpoint out of range or joins a point to itself,
or a marker list is neither empty nor one per item, since `read_poly()`
would reject the file
*/
inline void write_poly(std::ostream& os, const Poly_data& data)
{
  const std::size_t n = data.points.size();
  for(const std::array<double, 2>& p : data.points)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]))
      throw std::invalid_argument("write_poly: point coordinate is not finite");
  for(const std::array<std::size_t, 2>& s : data.segments) {
    if(s[0] >= n || s[1] >= n)
      throw std::invalid_argument("write_poly: segment endpoint out of range");
    if(s[0] == s[1])
      throw std::invalid_argument("write_poly: segment joins a point to itself");
  }
  for(const std::array<double, 2>& h : data.holes)
    if(!std::isfinite(h[0]) || !std::isfinite(h[1]))
      throw std::invalid_argument("write_poly: hole coordinate is not finite");
  if(!data.point_markers.empty() && data.point_markers.size() != n)
    throw std::invalid_argument("write_poly: point_markers must be empty or hold one marker per point");
  if(!data.segment_markers.empty() && data.segment_markers.size() != data.segments.size())
    throw std::invalid_argument("write_poly: segment_markers must be empty or hold one marker per segment");
  for(const Poly_data::Region& r : data.regions)
    if(!std::isfinite(r.seed[0]) || !std::isfinite(r.seed[1]) || !std::isfinite(r.attribute) ||
       !std::isfinite(r.max_area))
      throw std::invalid_argument("write_poly: region seed, attribute or area is not finite");

  // formatting and locale only: restoring the error state would hide a failed write
  boost::io::ios_base_all_saver format_saver(os);
  boost::io::ios_locale_saver locale_saver(os);
  os.imbue(std::locale::classic());
  os.flags(std::ios_base::dec);
  os.precision(std::numeric_limits<double>::max_digits10);
  os.width(0);

  const bool point_markers = !data.point_markers.empty(), segment_markers = !data.segment_markers.empty();
  os << n << " 2 0 " << (point_markers ? 1 : 0) << '\n';
  for(std::size_t i = 0; i < n; ++i) {
    os << (i + 1) << ' ' << data.points[i][0] << ' ' << data.points[i][1];
    if(point_markers) os << ' ' << data.point_markers[i];
    os << '\n';
  }
  os << data.segments.size() << ' ' << (segment_markers ? 1 : 0) << '\n';
  for(std::size_t i = 0; i < data.segments.size(); ++i) {
    os << (i + 1) << ' ' << (data.segments[i][0] + 1) << ' ' << (data.segments[i][1] + 1);
    if(segment_markers) os << ' ' << data.segment_markers[i];
    os << '\n';
  }
  os << data.holes.size() << '\n';
  for(std::size_t i = 0; i < data.holes.size(); ++i)
    os << (i + 1) << ' ' << data.holes[i][0] << ' ' << data.holes[i][1] << '\n';
  if(data.regions.empty()) return;
  os << data.regions.size() << '\n';
  for(std::size_t i = 0; i < data.regions.size(); ++i) {
    const Poly_data::Region& r = data.regions[i];
    os << (i + 1) << ' ' << r.seed[0] << ' ' << r.seed[1] << ' ' << r.attribute << ' ' << r.max_area << '\n';
  }
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes `data` to the file `file_name`; see
`write_poly(std::ostream&, const Poly_data&)`.

\param file_name path of the `.poly` file to create or overwrite
\param data the graph to write

\throws std::invalid_argument if `data` is not a valid graph
\throws std::runtime_error "cannot write FILE" when the file cannot be opened
or written
*/
inline void write_poly(const std::string& file_name, const Poly_data& data)
{
  std::ofstream os(file_name.c_str(), std::ios::out | std::ios::binary);
  if(!os)
    throw std::runtime_error("cannot write " + file_name);
  write_poly(os, data);
  os.flush();
  if(!os)
    throw std::runtime_error("cannot write " + file_name);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_READ_POLY_H
