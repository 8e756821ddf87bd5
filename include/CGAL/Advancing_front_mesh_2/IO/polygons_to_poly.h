// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_POLYGONS_TO_POLY_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_POLYGONS_TO_POLY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh_formats.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_2.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

/*!
\ingroup PkgAdvancingFrontMesh2IO

A polygon with holes as GIS formats give it: its rings (the first the outer
boundary, the others holes), each a list of points without the repeated
closing point, and the line of the file it was read from (0 if none).
*/
struct Polygon_rings
{
  std::vector<std::vector<std::array<double, 2> > > rings;
  std::size_t line = 0;
};

namespace internal {

// The regions of the rings by nesting: a face is in the domain when an odd
// number of rings separate it from the outside (inside a polygon, or on an
// island inside a hole), so a hole seed can be found inside each hole.
// Crossing rings are split here only to find the seeds; insert_poly()
// refuses them later with their lines.
inline std::vector<std::array<double, 2> > polygon_hole_seeds(const Poly_data& d)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<K>,
                                               CGAL::Delaunay_mesh_face_base_2<K> > Tds;
  typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag> CDT;
  CDT cdt;
  std::vector<CDT::Vertex_handle> v;
  for(const auto& p : d.points) v.push_back(cdt.insert(K::Point_2(p[0], p[1])));
  for(const auto& s : d.segments)
    if(v[s[0]] != v[s[1]]) cdt.insert_constraint(v[s[0]], v[s[1]]);
  if(cdt.dimension() < 2) return {};
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(false);
  // flood by nesting level from the outside, as CGAL's polygon triangulation example
  std::vector<std::pair<CDT::Face_handle, int> > next(1, {cdt.infinite_face(), 0});
  CGAL::Unique_hash_map<CDT::Face_handle, int> level(-1, cdt.number_of_faces());
  while(!next.empty()) {
    std::vector<std::pair<CDT::Face_handle, int> > deeper;
    for(const auto& start : next) {
      if(level[start.first] != -1) continue;
      std::vector<CDT::Face_handle> stack(1, start.first);
      level[start.first] = start.second;
      while(!stack.empty()) {
        const CDT::Face_handle f = stack.back();
        stack.pop_back();
        f->set_in_domain(level[f] % 2 == 1);
        for(int i = 0; i < 3; ++i) {
          const CDT::Face_handle g = f->neighbor(i);
          if(level[g] != -1) continue;
          if(cdt.is_constrained(std::make_pair(f, i))) {
            deeper.emplace_back(g, level[f] + 1);
          } else {
            level[g] = level[f];
            stack.push_back(g);
          }
        }
      }
    }
    next.swap(deeper);
  }
  return mesh_hole_points(cdt);
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

The planar straight-line graph of polygons with holes: every ring a closed
chain of segments, and a hole seed inside every hole (a region that an even
number of rings, at least two, separate from the outside: the holes of the
polygons, minus the islands inside them). Points repeated one after the
other in a ring are dropped. `insert_poly()` then checks the graph (rings
that cross or overlap, which make no valid domain, are refused there) and
names the problems by the lines the polygons were read from.

\param polygons the polygons
\param file_name the file they come from, for the messages

\throws Poly_read_error naming the file and line of a polygon with a
coordinate that is not finite, or with a ring of fewer than three distinct
points
*/
inline Poly_data poly_data_from_polygons(const std::vector<Polygon_rings>& polygons, const std::string& file_name)
{
  Poly_data d;
  d.origin.file = d.origin.point_file = file_name;
  d.origin.first_point_id = d.origin.first_segment_id = 1;
  for(std::size_t p = 0; p < polygons.size(); ++p) {
    const Polygon_rings& polygon = polygons[p];
    if(polygon.rings.empty())
      throw Poly_read_error(file_name, polygon.line, "polygon " + std::to_string(p + 1) + " has no ring");
    for(std::size_t r = 0; r < polygon.rings.size(); ++r) {
      std::vector<std::array<double, 2> > ring;
      for(const auto& q : polygon.rings[r]) {
        if(!std::isfinite(q[0]) || !std::isfinite(q[1]))
          throw Poly_read_error(file_name, polygon.line,
                                "polygon " + std::to_string(p + 1) + " has a coordinate that is not a finite number");
        if(ring.empty() || ring.back() != q) ring.push_back(q);
      }
      while(ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
      if(ring.size() < 3)
        throw Poly_read_error(file_name, polygon.line,
                              "polygon " + std::to_string(p + 1) + ": ring " + std::to_string(r + 1) +
                                " has fewer than 3 distinct points");
      const std::size_t base = d.points.size();
      for(std::size_t i = 0; i < ring.size(); ++i) {
        d.points.push_back(ring[i]);
        d.origin.point_lines.push_back(polygon.line);
        d.segments.push_back({{base + i, base + (i + 1) % ring.size()}});
        d.origin.segment_lines.push_back(polygon.line);
      }
    }
  }
  d.holes = internal::polygon_hole_seeds(d);
  return d;
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_POLYGONS_TO_POLY_H
