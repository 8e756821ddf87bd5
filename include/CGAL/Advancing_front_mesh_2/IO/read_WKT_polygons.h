// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_READ_WKT_POLYGONS_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_READ_WKT_POLYGONS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/polygons_to_poly.h>

#include <CGAL/IO/WKT.h>
#include <CGAL/Polygon_with_holes_2.h>
#include <CGAL/Simple_cartesian.h>

#include <cctype>
#include <cstddef>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// The rings of a CGAL polygon with holes, as Polygon_rings.
template <class Polygon>
Polygon_rings wkt_rings(const Polygon& polygon, std::size_t line)
{
  Polygon_rings out;
  out.line = line;
  auto ring = [](const auto& boundary) {
    std::vector<std::array<double, 2> > r;
    for(auto p = boundary.vertices_begin(); p != boundary.vertices_end(); ++p) r.push_back({{p->x(), p->y()}});
    return r;
  };
  out.rings.push_back(ring(polygon.outer_boundary()));
  for(auto h = polygon.holes_begin(); h != polygon.holes_end(); ++h) out.rings.push_back(ring(*h));
  return out;
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads polygons with holes in the Well-Known Text format (OGC Simple
Features) from `in`, one geometry per line, with CGAL's own WKT reader
(`CGAL::IO::read_polygon_WKT()`, `CGAL::IO::read_multi_polygon_WKT()`), and
turns them into a planar straight-line graph with
`poly_data_from_polygons()`: the domain is the union of the polygons, minus
their holes.

Strict, as `read_poly()`: blank lines and lines starting with `#` are
skipped; every other line must be one `POLYGON` or `MULTIPOLYGON` (upper
case, as CGAL's reader wants) that CGAL reads in full; at least one polygon
must be given. Anything else (another geometry type, a syntax error, a
coordinate that is not a finite number, a ring of fewer than three distinct
points) is refused naming the line.

\throws Poly_read_error on any problem, with the file name and line
*/
inline Poly_data read_WKT_polygons(std::istream& in, const std::string& file_name)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Polygon_with_holes_2<K> Polygon;
  std::vector<Polygon_rings> polygons;
  std::string line;
  std::size_t line_number = 0;
  while(std::getline(in, line)) {
    ++line_number;
    std::size_t first = 0;
    while(first < line.size() && std::isspace(static_cast<unsigned char>(line[first]))) ++first;
    if(first == line.size() || line[first] == '#') continue;
    const std::string text = line.substr(first);
    std::istringstream one(text);
    bool ok = false;
    if(text.compare(0, 12, "MULTIPOLYGON") == 0) {
      std::vector<Polygon> many;
      ok = CGAL::IO::read_multi_polygon_WKT(one, many) && !many.empty();
      for(const Polygon& p : many) polygons.push_back(internal::wkt_rings(p, line_number));
    } else if(text.compare(0, 7, "POLYGON") == 0) {
      Polygon p;
      ok = CGAL::IO::read_polygon_WKT(one, p) && !p.outer_boundary().is_empty();
      if(ok) polygons.push_back(internal::wkt_rings(p, line_number));
    } else {
      std::string word = text.substr(0, text.find_first_of(" \t("));
      if(word.size() > 40) word = word.substr(0, 40) + "...";
      throw Poly_read_error(file_name, line_number,
                            "expected a WKT POLYGON or MULTIPOLYGON, found '" + word + "'");
    }
    if(!ok) throw Poly_read_error(file_name, line_number, "not a valid WKT polygon (CGAL's WKT reader refused it)");
  }
  if(in.bad()) throw Poly_read_error(file_name, line_number, "read error");
  if(polygons.empty()) throw Poly_read_error(file_name, 0, "no POLYGON or MULTIPOLYGON in the file");
  return poly_data_from_polygons(polygons, file_name);
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads the WKT file `file_name`; see
`read_WKT_polygons(std::istream&, const std::string&)`.

\throws Poly_read_error "cannot open file", or on any problem with its content
*/
inline Poly_data read_WKT_polygons(const std::string& file_name)
{
  std::ifstream in(file_name.c_str(), std::ios::in | std::ios::binary);
  if(!in) throw Poly_read_error(file_name, 0, "cannot open file");
  return read_WKT_polygons(in, file_name);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_READ_WKT_POLYGONS_H
