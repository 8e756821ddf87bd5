// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_POLY_SECTIONS_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_POLY_SECTIONS_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>
#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Poly_line_reader.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <fstream>
#include <ios>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

struct Poly_node_header
{
  std::size_t vertices;
  std::size_t attributes;
  std::size_t markers;
};

inline std::string poly_count_phrase(std::size_t n, const char* singular,
                                     const char* plural)
{
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// Shared by .poly and .node files, which start with the same header line.
inline Poly_node_header poly_read_node_header(Poly_line_reader& r)
{
  if(!r.next())
    r.fail("file holds no data, expected the header "
           "'<#vertices> <dimension> <#attributes> <#boundary markers>'");
  r.expect_size(4, "the header '<#vertices> <dimension> <#attributes> "
                   "<#boundary markers>'");
  Poly_node_header h;
  h.vertices = r.count(0, "vertex count");
  const long long dim = r.integer(1, "dimension");
  if(dim != 2)
    r.fail("dimension must be 2, got " + std::to_string(dim));
  const long long attributes = r.integer(2, "attribute count");
  if(attributes < 0)
    r.fail("attribute count " + std::to_string(attributes) + " is negative");
  if(attributes > poly_max_attributes)
    r.fail("attribute count " + std::to_string(attributes) +
           " is too large (at most " + std::to_string(poly_max_attributes) + ")");
  h.attributes = static_cast<std::size_t>(attributes);
  const long long markers = r.integer(3, "boundary marker count");
  if(markers != 0 && markers != 1)
    r.fail("number of boundary markers must be 0 or 1, got " +
           std::to_string(markers));
  h.markers = static_cast<std::size_t>(markers);
  return h;
}

// Checks the id in the first column. Triangle lets the first id choose
// between 0- and 1-based numbering; requiring the others to follow in order
// catches lines that were lost, duplicated or shuffled.
inline void poly_check_id(Poly_line_reader& r, const char* what,
                          std::size_t index, long long& base)
{
  const long long id = r.integer(0, (std::string(what) + " id").c_str());
  if(index == 0) {
    if(id != 0 && id != 1)
      r.fail(std::string("first ") + what + " id must be 0 or 1, got " +
             std::to_string(id));
    base = id;
  } else if(id != base + static_cast<long long>(index)) {
    r.fail(std::string(what) + " id " + std::to_string(id) +
           " is out of order, expected " +
           std::to_string(base + static_cast<long long>(index)));
  }
}

// Reads the vertex lines announced by `h`; returns the first vertex id, which
// segment endpoints are numbered from.
inline long long poly_read_vertices(Poly_line_reader& r,
                                    const Poly_node_header& h,
                                    Poly_data& data)
{
  const std::size_t n_tokens = 3 + h.attributes + h.markers;
  const std::string line_desc =
    "vertex line (id, x, y" +
    (h.attributes == 0 ? std::string() : ", " + poly_count_phrase(h.attributes, "attribute", "attributes")) +
    (h.markers == 0 ? std::string() : ", 1 boundary marker") + ")";
  long long base = 0;
  data.points.reserve(data.points.size() + (std::min)(h.vertices, std::size_t(1) << 20));
  for(std::size_t i = 0; i < h.vertices; ++i) {
    if(!r.next())
      r.fail("expected " + poly_count_phrase(h.vertices, "vertex", "vertices") +
             ", file ends after " + std::to_string(i));
    r.expect_size(n_tokens, line_desc);
    poly_check_id(r, "vertex", i, base);
    const double x = r.real(1, "coordinate");
    const double y = r.real(2, "coordinate");
    for(std::size_t a = 0; a < h.attributes; ++a)
      r.real(3 + a, "attribute");
    if(h.markers != 0)
      data.point_markers.push_back(r.marker(3 + h.attributes));
    data.points.push_back(std::array<double, 2>{{x, y}});
    data.origin.point_lines.push_back(r.line());
  }
  data.origin.point_file = r.file();
  data.origin.first_point_id = base;
  return base;
}

inline std::string poly_node_file_name(const std::string& poly_file)
{
  const std::string ext = ".poly";
  if(poly_file.size() >= ext.size() &&
     poly_file.compare(poly_file.size() - ext.size(), ext.size(), ext) == 0)
    return poly_file.substr(0, poly_file.size() - ext.size()) + ".node";
  return poly_file + ".node";
}

// The vertices of a .poly file whose header announces 0 are in its .node
// file, which is read with its own reader so that its errors name it and
// its lines; returns the first vertex id.
inline long long poly_read_node_file(const std::string& file_name, std::size_t header_line,
                                     Poly_data& data)
{
  const std::string node_name = poly_node_file_name(file_name);
  std::ifstream node_in(node_name.c_str(), std::ios::in | std::ios::binary);
  if(!node_in)
    throw Poly_read_error(node_name, 0,
                          "cannot open file (needed because " + file_name +
                          ":" + std::to_string(header_line) +
                          " announces 0 vertices, meaning they are in a .node file)");
  Poly_line_reader nr(node_in, node_name);
  const Poly_node_header node_header = poly_read_node_header(nr);
  const long long vertex_base = poly_read_vertices(nr, node_header, data);
  if(nr.next())
    nr.fail("unexpected content after the last vertex");
  return vertex_base;
}

// The first section of a .poly file; returns the first vertex id, which
// segment endpoints are numbered from.
inline long long poly_read_vertex_section(Poly_line_reader& r, const std::string& file_name,
                                          Poly_data& data)
{
  const Poly_node_header header = poly_read_node_header(r);
  if(header.vertices != 0)
    return poly_read_vertices(r, header, data);
  return poly_read_node_file(file_name, r.line(), data);
}

// Column `column` of a segment line, as a 0-based index into the
// `n_vertices` vertices numbered from `vertex_base`.
inline std::size_t poly_read_segment_endpoint(Poly_line_reader& r, std::size_t column,
                                              long long vertex_base, std::size_t n_vertices)
{
  const long long v = r.integer(column, "segment endpoint");
  if(n_vertices == 0)
    r.fail("segment endpoint " + std::to_string(v) +
           " is out of range (there are no vertices)");
  // Written so that no subtraction can overflow for extreme values.
  if(v < vertex_base ||
     v > vertex_base + static_cast<long long>(n_vertices) - 1)
    r.fail("segment endpoint " + std::to_string(v) +
           " is out of range (vertex ids are " + std::to_string(vertex_base) +
           ".." + std::to_string(vertex_base + static_cast<long long>(n_vertices) - 1) +
           ")");
  return static_cast<std::size_t>(v - vertex_base);
}

inline void poly_read_segments(Poly_line_reader& r, long long vertex_base, Poly_data& data)
{
  const std::size_t n_vertices = data.points.size();
  if(!r.next())
    r.fail("expected the segment header '<#segments> <#boundary markers>', "
           "file ends");
  r.expect_size(2, "the segment header '<#segments> <#boundary markers>'");
  const std::size_t n_segments = r.count(0, "segment count");
  const long long segment_markers = r.integer(1, "boundary marker count");
  if(segment_markers != 0 && segment_markers != 1)
    r.fail("number of boundary markers must be 0 or 1, got " +
           std::to_string(segment_markers));
  const std::size_t seg_tokens = 3 + static_cast<std::size_t>(segment_markers);
  const std::string seg_desc = segment_markers == 0
                               ? "segment line (id, v1, v2)"
                               : "segment line (id, v1, v2, boundary marker)";
  data.segments.reserve((std::min)(n_segments, std::size_t(1) << 20));
  long long segment_base = 0;
  for(std::size_t i = 0; i < n_segments; ++i) {
    if(!r.next())
      r.fail("expected " + poly_count_phrase(n_segments, "segment", "segments") +
             ", file ends after " + std::to_string(i));
    r.expect_size(seg_tokens, seg_desc);
    poly_check_id(r, "segment", i, segment_base);
    std::array<std::size_t, 2> seg;
    for(int k = 0; k < 2; ++k)
      seg[k] = poly_read_segment_endpoint(r, 1 + k, vertex_base, n_vertices);
    if(seg[0] == seg[1])
      r.fail("segment joins vertex " +
             std::to_string(static_cast<long long>(seg[0]) + vertex_base) +
             " to itself");
    if(segment_markers != 0)
      data.segment_markers.push_back(r.marker(3));
    data.segments.push_back(seg);
    data.origin.segment_lines.push_back(r.line());
  }
  data.origin.first_segment_id = segment_base;
}

inline void poly_read_holes(Poly_line_reader& r, Poly_data& data)
{
  if(!r.next())
    r.fail("expected the hole header '<#holes>', file ends");
  r.expect_size(1, "the hole header '<#holes>'");
  const std::size_t n_holes = r.count(0, "hole count");
  data.holes.reserve((std::min)(n_holes, std::size_t(1) << 20));
  long long hole_base = 0;
  for(std::size_t i = 0; i < n_holes; ++i) {
    if(!r.next())
      r.fail("expected " + poly_count_phrase(n_holes, "hole", "holes") +
             ", file ends after " + std::to_string(i));
    r.expect_size(3, "hole line (id, x, y)");
    poly_check_id(r, "hole", i, hole_base);
    const double x = r.real(1, "coordinate");
    const double y = r.real(2, "coordinate");
    data.holes.push_back(std::array<double, 2>{{x, y}});
    data.origin.hole_lines.push_back(r.line());
  }
  data.origin.first_hole_id = hole_base;
}

// Regional attributes and area limits, kept. Nothing may follow them, or
// the holes if they are left out.
inline void poly_read_regions(Poly_line_reader& r, Poly_data& data)
{
  if(!r.next())
    return;
  if(r.size() != 1)
    r.fail("expected the optional region header '<#regions>' or the end of "
           "the file, found " + poly_count_phrase(r.size(), "value", "values"));
  const std::size_t n_regions = r.count(0, "region count");
  long long region_base = 0;
  for(std::size_t i = 0; i < n_regions; ++i) {
    if(!r.next())
      r.fail("expected " + poly_count_phrase(n_regions, "region", "regions") +
             ", file ends after " + std::to_string(i));
    if(r.size() != 4 && r.size() != 5)
      r.fail("region line (id, x, y, attribute[, maximum area]) has " +
             poly_count_phrase(r.size(), "value", "values") +
             ", expected 4 or 5");
    poly_check_id(r, "region", i, region_base);
    Poly_data::Region region;
    region.seed[0] = r.real(1, "coordinate");
    region.seed[1] = r.real(2, "coordinate");
    region.attribute = r.real(3, "region attribute");
    // as Triangle: without a fifth value, the fourth is also the area limit
    region.max_area = r.size() == 5 ? r.real(4, "maximum area") : region.attribute;
    data.regions.push_back(region);
    data.origin.region_lines.push_back(r.line());
  }
  data.origin.first_region_id = region_base;
  if(r.next())
    r.fail("unexpected content after the last section");
}

} // namespace internal

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_POLY_SECTIONS_H
