// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_STREAMING_ASSEMBLY_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_STREAMING_ASSEMBLY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/internal/Streaming_files.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Vtu_layout.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_gmsh_msh.h>

#include <array>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {
namespace internal {

// The final files of Streaming_mesh_writer, made by close() from the part
// files and what the writer counted: the records written while streaming
// and the layouts of the in-memory writers around them.

// What the writer knows at close(): counts, bounding box, content, and the
// segments (kept in memory) and triangles per region attribute.
struct Streaming_totals
{
  std::uint64_t nv, nt;
  double xmin, ymin, xmax, ymax;
  const Streaming_content& content;
  const std::vector<std::array<std::uint64_t, 2> >& segments;
  const std::vector<int>& segment_markers;
  const std::vector<std::size_t>& group_counts;
};

template <class T>
void streaming_put_raw(Streaming_file& f, T v)
{
  char* c = f.reserve(sizeof(T));
  std::memcpy(c, &v, sizeof(T));
  f.commit(c + sizeof(T));
}

inline void streaming_put_line(Streaming_file& f, const char* s, std::size_t n)
{
  char* c = f.reserve(n + 1);
  std::memcpy(c, s, n);
  c[n] = '\n';
  f.commit(c + n + 1);
}

inline void streaming_copy(Streaming_file& out, const Streaming_file& part)
{
  streaming_copy_part(out, part.path(), part.size());
}

inline void streaming_put_int(Streaming_file& f, long long v)
{
  char* c = f.reserve(text_max_uint_chars + 2);
  f.commit(std::to_chars(c, c + text_max_uint_chars + 2, v).ptr);
}

// The .node and .ele parts get their counts: they are the temporary files
// of the final ones (no copy of the largest files); the .edge file is
// written from the segments.
inline void streaming_finish_node_ele(Streaming_output& o, const Streaming_totals& t)
{
  typedef Streaming_output Output;
  streaming_patch_count(o.vertices().path(), t.nv);
  streaming_patch_count(o.triangles().path(), t.nt);
  if(!t.content.tagged) return;
  Streaming_file edge(Output::temporary(o.base + ".edge"));
  edge.create();
  edge.put_uint(t.segments.size());
  edge.put(" 1\n");
  for(std::size_t s = 0; s < t.segments.size(); ++s) {
    edge.put_uint(s + 1); edge.put(" ", 1);
    edge.put_uint(t.segments[s][0] + 1); edge.put(" ", 1);
    edge.put_uint(t.segments[s][1] + 1); edge.put(" ", 1);
    streaming_put_int(edge, t.segment_markers[s]);
    edge.put("\n", 1);
  }
  edge.close(true);
}

inline void streaming_put_box(Streaming_file& out, const Streaming_totals& t)
{
  out.put_double(t.xmin); out.put(" ", 1); out.put_double(t.ymin); out.put(" 0 ", 3);
  out.put_double(t.xmax); out.put(" ", 1); out.put_double(t.ymax); out.put(" 0", 2);
}

inline void streaming_put_msh_nodes(Streaming_file& out, Streaming_output& o, const Streaming_totals& t)
{
  out.put("$Nodes\n");
  if(t.nv == 0) {
    out.put("0 0 0 0\n");
  } else {
    out.put("1 "); out.put_uint(t.nv); out.put(" 1 "); out.put_uint(t.nv);
    out.put("\n2 1 0 "); out.put_uint(t.nv); out.put("\n");
    for(std::uint64_t i = 1; i <= t.nv; ++i) {
      char* p = out.reserve(text_max_uint_chars + 1);
      p = text_format_uint(p, i);
      *p++ = '\n';
      out.commit(p);
    }
    streaming_copy(out, o.vertices());
  }
  out.put("$EndNodes\n");
}

// The layout of write_gmsh_msh().
inline void streaming_write_msh(Streaming_file& out, Streaming_output& o, const Streaming_totals& t)
{
  out.put("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  out.put("$Entities\n0 0 1 0\n1 ");
  streaming_put_box(out, t);
  out.put(" 0 0\n$EndEntities\n");
  streaming_put_msh_nodes(out, o, t);
  out.put("$Elements\n");
  if(t.nt == 0) {
    out.put("0 0 0 0\n");
  } else {
    out.put("1 "); out.put_uint(t.nt); out.put(" 1 "); out.put_uint(t.nt);
    out.put("\n2 1 2 "); out.put_uint(t.nt); out.put("\n");
    streaming_copy(out, o.triangles());
  }
  out.put("$EndElements\n");
}

// The layout of write_gmsh_msh() with markers and regions: a curve per
// segment marker, a surface per region attribute that has triangles (one,
// "domain", without regions), each in its physical group.
inline void streaming_write_tagged_msh(Streaming_file& out, Streaming_output& o, const Streaming_totals& t)
{
  std::map<double, std::vector<std::size_t> > by_marker, by_attribute;
  for(std::size_t s = 0; s < t.segments.size(); ++s) by_marker[t.segment_markers[s]].push_back(s);
  // the items of a surface: its group (its part file)
  if(t.content.has_regions()) {
    for(std::size_t g = 0; g < t.content.attributes.size(); ++g)
      if(t.group_counts[g] > 0) by_attribute[t.content.attributes[g]].push_back(g);
  } else if(t.nt > 0) {
    by_attribute[1.].push_back(0);
  }
  std::vector<Msh_group> curves = msh_groups(by_marker, "marker_");
  std::vector<Msh_group> surfaces = msh_groups(by_attribute, "region_");
  if(!t.content.has_regions() && !surfaces.empty()) surfaces[0].name = "domain";

  out.put("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  out.put("$PhysicalNames\n"); out.put_uint(curves.size() + surfaces.size()); out.put("\n");
  for(int dim = 1; dim <= 2; ++dim)
    for(const Msh_group& g : dim == 1 ? curves : surfaces) {
      out.put(dim == 1 ? "1 " : "2 "); streaming_put_int(out, g.physical);
      out.put(" \""); out.put(g.name); out.put("\"\n");
    }
  out.put("$EndPhysicalNames\n");
  out.put("$Entities\n0 "); out.put_uint(curves.size()); out.put(" "); out.put_uint(surfaces.size());
  out.put(" 0\n");
  for(int dim = 1; dim <= 2; ++dim) {
    const std::vector<Msh_group>& groups = dim == 1 ? curves : surfaces;
    for(std::size_t e = 0; e < groups.size(); ++e) {
      out.put_uint(e + 1); out.put(" ", 1); streaming_put_box(out, t);
      out.put(" 1 "); streaming_put_int(out, groups[e].physical); out.put(" 0\n");
    }
  }
  out.put("$EndEntities\n");
  if(surfaces.empty()) {
    out.put("$Nodes\n0 0 0 0\n$EndNodes\n");
  } else {
    streaming_put_msh_nodes(out, o, t);
  }
  const std::uint64_t ne = t.segments.size() + t.nt;
  out.put("$Elements\n");
  if(ne == 0) {
    out.put("0 0 0 0\n");
  } else {
    out.put_uint(curves.size() + surfaces.size()); out.put(" "); out.put_uint(ne);
    out.put(" 1 "); out.put_uint(ne); out.put("\n");
    for(std::size_t c = 0; c < curves.size(); ++c) {
      out.put("1 "); out.put_uint(c + 1); out.put(" 1 "); out.put_uint(curves[c].items.size()); out.put("\n");
      for(std::size_t s : curves[c].items) {
        out.put_uint(t.nt + s + 1); out.put(" ", 1);
        out.put_uint(t.segments[s][0] + 1); out.put(" ", 1);
        out.put_uint(t.segments[s][1] + 1); out.put("\n", 1);
      }
    }
    for(std::size_t s = 0; s < surfaces.size(); ++s) {
      std::uint64_t n = 0;
      for(std::size_t g : surfaces[s].items) n += t.content.has_regions() ? t.group_counts[g] : t.nt;
      out.put("2 "); out.put_uint(s + 1); out.put(" 2 "); out.put_uint(n); out.put("\n");
      for(std::size_t g : surfaces[s].items) streaming_copy(out, o.triangles(g));
    }
  }
  out.put("$EndElements\n");
}

// The layout of write_mesh_VTU() (Vtu_layout.h), in the numbering received.
inline void streaming_write_vtu(Streaming_file& out, Streaming_output& o, const Streaming_totals& t)
{
  typedef Vtu_section Section;
  const bool binary = t.content.binary;
  const std::uint64_t nt = t.nt, ns = t.content.tagged ? t.segments.size() : 0;
  // one line or one raw value per item
  auto put_value = [&out, binary](auto v) {
    if(binary) {
      streaming_put_raw(out, v);
    } else {
      char b[text_max_double_chars + 1];
      char* e = std::to_chars(b, b + sizeof(b) - 1, v).ptr;
      *e++ = '\n';
      out.put(b, static_cast<std::size_t>(e - b));
    }
  };
  std::vector<Vtu_array> arrays;
  arrays.push_back({Section::POINTS, "type=\"Float64\" NumberOfComponents=\"3\"", 24 * t.nv,
                    [&] { streaming_copy(out, o.vertices()); }});
  arrays.push_back({Section::CELLS, "type=\"Int64\" Name=\"connectivity\"", 8 * (3 * nt + 2 * ns), [&] {
    streaming_copy(out, o.triangles());
    for(std::uint64_t s = 0; s < ns; ++s) {
      if(binary) {
        streaming_put_raw(out, std::int64_t(t.segments[s][0]));
        streaming_put_raw(out, std::int64_t(t.segments[s][1]));
      } else {
        out.put_uint(t.segments[s][0]); out.put(" ", 1); out.put_uint(t.segments[s][1]); out.put("\n", 1);
      }
    }
  }});
  arrays.push_back({Section::CELLS, "type=\"Int64\" Name=\"offsets\"", 8 * (nt + ns), [&] {
    for(std::uint64_t k = 1; k <= nt; ++k) put_value(std::int64_t(3 * k));
    for(std::uint64_t s = 1; s <= ns; ++s) put_value(std::int64_t(3 * nt + 2 * s));
  }});
  arrays.push_back({Section::CELLS, "type=\"UInt8\" Name=\"types\"", nt + ns, [&] {
    for(std::uint64_t k = 0; k < nt; ++k) binary ? streaming_put_raw(out, std::uint8_t(5)) : out.put("5\n", 2);
    for(std::uint64_t s = 0; s < ns; ++s) binary ? streaming_put_raw(out, std::uint8_t(3)) : out.put("3\n", 2);
  }});
  if(t.content.tagged) {
    arrays.push_back({Section::POINT_DATA, "type=\"Int32\" Name=\"marker\"", 4 * t.nv,
                      [&] { streaming_copy(out, o.vertex_markers->file); }});
    arrays.push_back({Section::CELL_DATA, "type=\"Int32\" Name=\"marker\"", 4 * (nt + ns), [&] {
      for(std::uint64_t k = 0; k < nt; ++k) put_value(std::int32_t(0));
      for(int m : t.segment_markers) put_value(std::int32_t(m));
    }});
    if(t.content.has_regions())
      arrays.push_back({Section::CELL_DATA, "type=\"Float64\" Name=\"region\"", 8 * (nt + ns), [&] {
        streaming_copy(out, o.triangle_attributes->file);
        for(std::uint64_t s = 0; s < ns; ++s) put_value(0.);
      }});
  }
  vtu_write(out, t.nv, nt + ns, arrays, binary);
}

} // namespace internal
} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_STREAMING_ASSEMBLY_H
