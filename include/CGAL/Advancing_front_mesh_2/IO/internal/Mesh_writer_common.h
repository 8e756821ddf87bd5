// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_MESH_WRITER_COMMON_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_MESH_WRITER_COMMON_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>

#include <CGAL/number_utils.h>

#include <boost/io/ios_state.hpp>

#include <array>
#include <charconv>
#include <cstdint>
#include <cstddef>
#include <fstream>
#include <ios>
#include <limits>
#include <locale>
#include <ostream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// Longest outputs of std::to_chars: "-2.2250738585072014e-308" has 24
// characters, a 64-bit unsigned integer 20.
constexpr std::size_t text_max_double_chars = 32;
constexpr std::size_t text_max_uint_chars = 20;

// The shortest decimal that reads back to the same double, in the "C"
// locale whatever the global one is: files read back exactly, and are
// about half the size of max_digits10 output for round numbers.
inline char* text_format_double(char* p, double v)
{
  return std::to_chars(p, p + text_max_double_chars, v).ptr;
}

inline char* text_format_uint(char* p, std::uint64_t v)
{
  return std::to_chars(p, p + text_max_uint_chars, v).ptr;
}

// Text written to a stream through a buffer of our own, numbers formatted
// by text_format_*(): at a million triangles, iostream's formatting of
// doubles with max_digits10 digits (glibc's exact printf) and its per-call
// sentries took a second, a quarter of the whole run. The buffer goes to
// the stream when full and by flush(); a writer calls flush() so that the
// stream's state is final when it returns (the destructor flushes too, and
// swallows an exception of a stream with exceptions() set, which must not
// leave a destructor).
class Text_output
{
public:
  explicit Text_output(std::ostream& os) : os_(os) {}
  Text_output(const Text_output&) = delete;
  Text_output& operator=(const Text_output&) = delete;
  // a writer flushes before it returns; here only what an exception left
  ~Text_output()
  {
    try {
      flush();
    } catch(...) {
      // the stream reports the failure by its state
    }
  }

  Text_output& put(char c)
  {
    room(1);
    buf_[used_++] = c;
    return *this;
  }

  Text_output& put(const char* s)
  {
    for(; *s != 0; ++s) put(*s);
    return *this;
  }

  Text_output& put(const std::string& s)
  {
    for(char c : s) put(c);
    return *this;
  }

  Text_output& put_uint(std::uint64_t v)
  {
    room(text_max_uint_chars);
    used_ = std::size_t(text_format_uint(buf_.data() + used_, v) - buf_.data());
    return *this;
  }

  Text_output& put_int(long long v)
  {
    room(text_max_uint_chars + 1);
    used_ = std::size_t(std::to_chars(buf_.data() + used_, buf_.data() + capacity, v).ptr - buf_.data());
    return *this;
  }

  Text_output& put_double(double v)
  {
    room(text_max_double_chars);
    used_ = std::size_t(text_format_double(buf_.data() + used_, v) - buf_.data());
    return *this;
  }

  void flush()
  {
    const std::size_t n = used_;
    used_ = 0; // not written again when the stream throws
    if(n > 0) os_.write(buf_.data(), std::streamsize(n));
  }

private:
  static constexpr std::size_t capacity = 1 << 16;

  void room(std::size_t n)
  {
    if(capacity - used_ < n) flush();
  }

  std::ostream& os_;
  std::vector<char> buf_ = std::vector<char>(capacity);
  std::size_t used_ = 0;
};

// What every writer needs: the in-domain triangles and only the vertices they
// use, numbered in order of first appearance, so that two writes of the same
// triangulation give identical files and the numbering of .node and .ele
// agree.
template <class CDT>
struct Mesh_domain_view
{
  std::vector<std::array<double, 2> > points;
  std::vector<typename CDT::Vertex_handle> vertices; // parallel to `points`
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<typename CDT::Face_handle> faces; // parallel to `triangles`
  // The constrained edges beside the domain, each once: a boundary edge
  // with the domain on its left.
  std::vector<std::array<std::size_t, 2> > segments;
  std::vector<std::pair<typename CDT::Face_handle, int> > segment_edges; // parallel to `segments`

  // Filled by mesh_collect_tags() (Mesh_tagged_view.h) when the writer was
  // given markers and regions.
  bool tagged = false;
  std::vector<int> point_markers, segment_markers;
  std::vector<double> triangle_attributes;
  std::vector<std::size_t> triangle_regions;
  bool has_regions = false;
};

template <class CDT>
void mesh_collect_domain(const CDT& cdt, Mesh_domain_view<CDT>& m)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  // the numbers by address in flat tables: CGAL::Unique_hash_map's chained
  // lists took a fifth of writing a million-triangle mesh
  CGAL::Advancing_front_mesh_2::internal::Flat_hash_map<const void*, std::size_t> index(nullptr);
  index.reserve(cdt.number_of_vertices());
  m.points.reserve(cdt.number_of_vertices());
  m.vertices.reserve(cdt.number_of_vertices());
  m.triangles.reserve(cdt.number_of_faces());
  m.faces.reserve(cdt.number_of_faces());
  for(typename CDT::Finite_faces_iterator fit = cdt.finite_faces_begin();
      fit != cdt.finite_faces_end(); ++fit) {
    if(!fit->is_in_domain())
      continue;
    Face_handle f = fit;
    std::array<std::size_t, 3> t;
    for(int i = 0; i < 3; ++i) {
      const Vertex_handle v = f->vertex(i);
      const std::size_t* k = index.find(&*v);
      if(k == nullptr) {
        k = &index.insert(&*v, m.points.size());
        m.points.push_back(std::array<double, 2>{{CGAL::to_double(v->point().x()),
                                                  CGAL::to_double(v->point().y())}});
        m.vertices.push_back(v);
      }
      t[i] = *k;
    }
    m.triangles.push_back(t);
    m.faces.push_back(f);
  }
  // an edge between two domain faces is listed from the face seen first:
  // the faces' numbers are only needed for such edges
  CGAL::Advancing_front_mesh_2::internal::Flat_hash_map<const void*, std::size_t> face_index(nullptr);
  auto number_of = [&](Face_handle g) {
    if(face_index.empty()) {
      face_index.reserve(m.faces.size());
      for(std::size_t t = 0; t < m.faces.size(); ++t) face_index.insert(&*m.faces[t], t);
    }
    const std::size_t* k = face_index.find(&*g);
    return k == nullptr ? none : *k;
  };
  for(std::size_t t = 0; t < m.faces.size(); ++t) {
    const Face_handle f = m.faces[t];
    for(int i = 0; i < 3; ++i) {
      if(!f->is_constrained(i)) continue;
      const Face_handle g = f->neighbor(i);
      if(!cdt.is_infinite(g) && g->is_in_domain() && number_of(g) < t) continue;
      m.segments.push_back({{*index.find(&*f->vertex(CDT::ccw(i))), *index.find(&*f->vertex(CDT::cw(i)))}});
      m.segment_edges.emplace_back(f, i);
    }
  }
}

// Doubles are written with max_digits10 digits so that reading the file back
// gives the very same values, and in the classic locale so that a global
// locale set by the application cannot insert thousands separators or a
// decimal comma. Callers save and restore the stream state around this.
inline void mesh_set_exact_format(std::ostream& os)
{
  os.imbue(std::locale::classic());
  os.flags(std::ios_base::dec);
  os.precision(std::numeric_limits<double>::max_digits10);
  os.width(0);
}

// The exact number format for the lifetime of the scope, the stream's
// formatting and locale restored afterwards (not its error state: that
// would hide a failed write).
class Mesh_exact_format_scope
{
public:
  explicit Mesh_exact_format_scope(std::ostream& os) : format_(os), locale_(os) { mesh_set_exact_format(os); }

private:
  boost::io::ios_base_all_saver format_;
  boost::io::ios_locale_saver locale_;
};

template <class Writer>
void mesh_write_file(const std::string& file_name, Writer writer)
{
  // Binary mode: '\n' line ends on every platform, and VTU appends raw data.
  std::ofstream os(file_name.c_str(), std::ios::out | std::ios::binary);
  if(!os)
    throw std::runtime_error("cannot write " + file_name);
  writer(os);
  os.flush();
  if(!os)
    throw std::runtime_error("cannot write " + file_name);
}

// The format of a file is chosen by its extension, in any case; a dot in a
// directory name is not an extension.
inline std::string mesh_lower_extension(const std::string& file_name)
{
  const std::size_t slash = file_name.find_last_of("/\\");
  const std::size_t dot = file_name.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string ext = file_name.substr(dot + 1);
  for(char& c : ext)
    if(c >= 'A' && c <= 'Z')
      c = static_cast<char>(c - 'A' + 'a');
  return ext;
}

} // namespace internal

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_MESH_WRITER_COMMON_H
