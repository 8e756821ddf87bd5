// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>

#include <CGAL/IO/io.h>
#include <CGAL/IO/write_VTU.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/number_utils.h>

#include <boost/io/ios_state.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <initializer_list>
#include <ios>
#include <limits>
#include <locale>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

/*!
\ingroup PkgAdvancingFrontMesh2IO

Options of `write_SVG()`.
*/
struct SVG_options
{
  /// width of the picture in pixels; the height follows from the aspect ratio
  double width_px = 1200;
  /// written as the SVG `<title>`, which viewers show as the document name
  std::string title;
  /// multiplies the default stroke widths, e.g. to thin the lines of a dense mesh
  double stroke_scale = 1.0;
  /// when `true`, only the window `[xmin, xmax] x [ymin, ymax]` (in mesh
  /// coordinates) is drawn, to zoom on a detail of a large mesh
  bool has_window = false;
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  /// when `true`, triangles are filled by their radius ratio 2r/R: dark red
  /// below 0.3, red below 0.5, orange below 0.7, yellow below 0.8, light
  /// green below 0.9, green below 0.95, pale blue from 0.95 (equilateral);
  /// one path element per colour keeps large meshes fast to write and view
  bool color_by_quality = false;
};

namespace internal {

// What every writer needs: the in-domain triangles and only the vertices they
// use, numbered in order of first appearance, so that two writes of the same
// triangulation give identical files and the numbering of .node and .ele
// agree.
template <class CDT>
struct Mesh_domain_view
{
  std::vector<std::array<double, 2> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<typename CDT::Face_handle> faces; // parallel to `triangles`
};

template <class CDT>
void mesh_collect_domain(const CDT& cdt, Mesh_domain_view<CDT>& m)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  CGAL::Unique_hash_map<Vertex_handle, std::size_t> index(none, cdt.number_of_vertices());
  for(typename CDT::Finite_faces_iterator fit = cdt.finite_faces_begin();
      fit != cdt.finite_faces_end(); ++fit) {
    if(!fit->is_in_domain())
      continue;
    Face_handle f = fit;
    std::array<std::size_t, 3> t;
    for(int i = 0; i < 3; ++i) {
      const Vertex_handle v = f->vertex(i);
      std::size_t& k = index[v];
      if(k == none) {
        k = m.points.size();
        m.points.push_back(std::array<double, 2>{{CGAL::to_double(v->point().x()),
                                                  CGAL::to_double(v->point().y())}});
      }
      t[i] = k;
    }
    m.triangles.push_back(t);
    m.faces.push_back(f);
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

// ---------------------------------------------------------------------------
// SVG helpers

struct Svg_box
{
  double xmin, ymin, xmax, ymax;
};

inline int svg_outcode(const std::array<double, 2>& p, const Svg_box& b)
{
  int c = 0;
  if(p[0] < b.xmin) c |= 1; else if(p[0] > b.xmax) c |= 2;
  if(p[1] < b.ymin) c |= 4; else if(p[1] > b.ymax) c |= 8;
  return c;
}

// Liang-Barsky. Clipping far-away endpoints keeps the numbers in the file
// within a few picture sizes: renderers work in single precision and draw
// garbage for coordinates far outside the viewport.
inline bool svg_clip_segment(std::array<double, 2>& p, std::array<double, 2>& q,
                             const Svg_box& b)
{
  const double dx = q[0] - p[0], dy = q[1] - p[1];
  const double pk[4] = {-dx, dx, -dy, dy};
  const double qk[4] = {p[0] - b.xmin, b.xmax - p[0], p[1] - b.ymin, b.ymax - p[1]};
  double t0 = 0, t1 = 1;
  for(int k = 0; k < 4; ++k) {
    if(pk[k] == 0) {
      if(qk[k] < 0)
        return false;
    } else {
      const double r = qk[k] / pk[k];
      if(pk[k] < 0) {
        if(r > t1) return false;
        if(r > t0) t0 = r;
      } else {
        if(r < t0) return false;
        if(r < t1) t1 = r;
      }
    }
  }
  const std::array<double, 2> a{{p[0] + t0 * dx, p[1] + t0 * dy}};
  const std::array<double, 2> c{{p[0] + t1 * dx, p[1] + t1 * dy}};
  p = a;
  q = c;
  return true;
}

// Sutherland-Hodgman against the four sides of a box. For points inside the
// box the winding number is preserved, which is all the nonzero fill rule
// looks at, so clipped boundary loops still fill the right region.
inline void svg_clip_polygon(std::vector<std::array<double, 2> >& poly,
                             const Svg_box& b)
{
  std::vector<std::array<double, 2> > out;
  for(int side = 0; side < 4 && !poly.empty(); ++side) {
    const int axis = side / 2;
    const double bound = (side == 0) ? b.xmin : (side == 1) ? b.xmax
                       : (side == 2) ? b.ymin : b.ymax;
    const bool keep_above = (side % 2 == 0);
    auto inside = [&](const std::array<double, 2>& p) {
      return keep_above ? p[axis] >= bound : p[axis] <= bound;
    };
    auto cut = [&](const std::array<double, 2>& p, const std::array<double, 2>& q) {
      const double t = (bound - p[axis]) / (q[axis] - p[axis]);
      std::array<double, 2> r;
      r[axis] = bound;
      r[1 - axis] = p[1 - axis] + t * (q[1 - axis] - p[1 - axis]);
      return r;
    };
    out.clear();
    const std::size_t n = poly.size();
    for(std::size_t i = 0; i < n; ++i) {
      const std::array<double, 2>& cur = poly[i];
      const std::array<double, 2>& prev = poly[(i + n - 1) % n];
      const bool cin = inside(cur), pin = inside(prev);
      if(cin) {
        if(!pin)
          out.push_back(cut(prev, cur));
        out.push_back(cur);
      } else if(pin) {
        out.push_back(cut(prev, cur));
      }
    }
    poly.swap(out);
  }
}

// Writes the `d` attribute of one <path> on an integer grid in picture
// space. Relative steps between grid points are exact, so the short deltas
// of small edges save space without accumulating rounding drift.
class Svg_path_writer
{
public:
  // `splittable` tells whether the subpaths may be spread over several
  // elements: not for a fill, where a hole only stays empty if its loop is in
  // the same element as the loop around it.
  Svg_path_writer(std::ostream& os, const std::string& attributes,
                  double x0, double y1, double scale, int decimals,
                  bool splittable)
    : os_(os), attributes_(attributes), x0_(x0), y1_(y1), decimals_(decimals),
      splittable_(splittable)
  {
    pow10_ = 1;
    for(int i = 0; i < decimals; ++i)
      pow10_ *= 10;
    grid_scale_ = scale * static_cast<double>(pow10_);
  }

  void move_to(const std::array<double, 2>& p)
  {
    // A new element every so often, since a stroke looks the same drawn in
    // one element or several: librsvg 2.54 (through libxml2) gives up on
    // files with many path data much longer than 256 KB, and each subpath
    // starts with an absolute move, so the split is free.
    if(splittable_ && opened_ && element_length_ > max_element_length)
      finish();
    long long gx, gy;
    to_grid(p, gx, gy);
    put_move(gx, gy);
    start_x_ = gx;
    start_y_ = gy;
  }

  void line_to(const std::array<double, 2>& p)
  {
    long long gx, gy;
    to_grid(p, gx, gy);
    // One polyline can be long enough to need splitting by itself.
    if(splittable_ && element_length_ > 2 * max_element_length) {
      finish();
      put_move(x_, y_);
    }
    maybe_break();
    if(last_command_ != 'l')
      put_command('l');
    put_number(gx - x_);
    put_number(gy - y_);
    x_ = gx;
    y_ = gy;
    maybe_flush();
  }

  void close()
  {
    put_command('z');
    x_ = start_x_;
    y_ = start_y_;
  }

  // Ends the element, if anything was drawn; an empty path is not written.
  void finish()
  {
    if(!opened_)
      return;
    buf_ += "\"/>\n";
    os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
    opened_ = false;
    element_length_ = 0;
  }

private:
  static constexpr std::size_t max_element_length = std::size_t(1) << 16;

  void put_move(long long gx, long long gy)
  {
    open();
    maybe_break();
    put_command('M');
    put_number(gx);
    put_number(gy);
    x_ = gx;
    y_ = gy;
  }

  void open()
  {
    if(opened_)
      return;
    opened_ = true;
    buf_ += "<path ";
    buf_ += attributes_;
    buf_ += " d=\"";
    last_command_ = 0;
    line_length_ = 0;
  }

  // Keeps lines short for text tools; whitespace is a valid separator.
  void maybe_break()
  {
    if(line_length_ > 120) {
      buf_ += '\n';
      line_length_ = 0;
      need_separator_ = false;
    }
  }

  void to_grid(const std::array<double, 2>& p, long long& gx, long long& gy) const
  {
    gx = std::llround((p[0] - x0_) * grid_scale_);
    gy = std::llround((y1_ - p[1]) * grid_scale_);
  }

  void put_command(char c)
  {
    buf_ += c;
    ++line_length_;
    ++element_length_;
    last_command_ = c;
    need_separator_ = false;
  }

  void put_number(long long g)
  {
    char tmp[48];
    int n = 0;
    const bool negative = g < 0;
    unsigned long long a = negative ? 0ULL - static_cast<unsigned long long>(g)
                                    : static_cast<unsigned long long>(g);
    const unsigned long long p = static_cast<unsigned long long>(pow10_);
    unsigned long long ip = a / p, fp = a % p;
    // Fraction digits, most significant first, without trailing zeros.
    char frac[24];
    int nf = 0;
    if(fp != 0) {
      for(int i = decimals_ - 1; i >= 0; --i) {
        frac[i] = static_cast<char>('0' + fp % 10);
        fp /= 10;
      }
      nf = decimals_;
      while(nf > 0 && frac[nf - 1] == '0')
        --nf;
    }
    char digits[24];
    int nd = 0;
    do {
      digits[nd++] = static_cast<char>('0' + ip % 10);
      ip /= 10;
    } while(ip != 0);
    if(negative)
      tmp[n++] = '-'; // the sign also separates it from the previous number
    else if(need_separator_)
      tmp[n++] = ' ';
    while(nd > 0)
      tmp[n++] = digits[--nd];
    if(nf > 0) {
      tmp[n++] = '.';
      for(int i = 0; i < nf; ++i)
        tmp[n++] = frac[i];
    }
    buf_.append(tmp, static_cast<std::size_t>(n));
    line_length_ += static_cast<std::size_t>(n);
    element_length_ += static_cast<std::size_t>(n);
    need_separator_ = true;
  }

  void maybe_flush()
  {
    if(buf_.size() >= (std::size_t(1) << 16)) {
      os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
      buf_.clear();
    }
  }

  std::ostream& os_;
  std::string attributes_;
  double x0_, y1_;
  int decimals_;
  bool splittable_;
  long long pow10_;
  double grid_scale_;
  std::string buf_;
  bool opened_ = false;
  bool need_separator_ = false;
  char last_command_ = 0;
  std::size_t line_length_ = 0;
  std::size_t element_length_ = 0;
  long long x_ = 0, y_ = 0, start_x_ = 0, start_y_ = 0;
};

// Draws undirected edges as few polylines as a greedy walk finds: a polyline
// costs one point per edge instead of two, which roughly halves the file for
// a large mesh. Edges wholly on one side outside `view` are skipped; edges
// reaching outside `clip` are clipped and drawn on their own.
inline void svg_draw_edges(const std::vector<std::array<double, 2> >& pts,
                           const std::vector<std::array<std::size_t, 2> >& edges,
                           const Svg_box& view, const Svg_box& clip,
                           Svg_path_writer& out)
{
  const std::size_t nv = pts.size();
  std::vector<std::size_t> chained;
  chained.reserve(edges.size());
  for(std::size_t e = 0; e < edges.size(); ++e) {
    const std::array<double, 2>& a = pts[edges[e][0]];
    const std::array<double, 2>& b = pts[edges[e][1]];
    if((svg_outcode(a, view) & svg_outcode(b, view)) != 0)
      continue;
    if(svg_outcode(a, clip) == 0 && svg_outcode(b, clip) == 0) {
      chained.push_back(e);
    } else {
      std::array<double, 2> p = a, q = b;
      if(svg_clip_segment(p, q, clip)) {
        out.move_to(p);
        out.line_to(q);
      }
    }
  }

  // Adjacency in compressed rows: vertex v's edges are adj[first[v]..first[v+1]).
  std::vector<std::size_t> first(nv + 1, 0);
  for(std::size_t k = 0; k < chained.size(); ++k) {
    ++first[edges[chained[k]][0] + 1];
    ++first[edges[chained[k]][1] + 1];
  }
  for(std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<std::size_t> adj(first[nv]);
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for(std::size_t k = 0; k < chained.size(); ++k) {
    adj[next[edges[chained[k]][0]]++] = k;
    adj[next[edges[chained[k]][1]]++] = k;
  }
  std::copy(first.begin(), first.end() - 1, next.begin());
  std::vector<char> used(chained.size(), 0);

  auto unused_edge_at = [&](std::size_t v, std::size_t& k) {
    while(next[v] < first[v + 1] && used[adj[next[v]]])
      ++next[v];
    if(next[v] == first[v + 1])
      return false;
    k = adj[next[v]];
    return true;
  };
  auto walk_from = [&](std::size_t v) {
    std::size_t k;
    while(unused_edge_at(v, k)) {
      out.move_to(pts[v]);
      std::size_t cur = v;
      while(unused_edge_at(cur, k)) {
        used[k] = 1;
        const std::array<std::size_t, 2>& e = edges[chained[k]];
        cur = (e[0] == cur) ? e[1] : e[0];
        out.line_to(pts[cur]);
      }
    }
  };
  // A walk can only end at an odd vertex, so starting from those first leaves
  // fewer, longer polylines.
  for(std::size_t v = 0; v < nv; ++v)
    if((first[v + 1] - first[v]) % 2 == 1)
      walk_from(v);
  for(std::size_t v = 0; v < nv; ++v)
    walk_from(v);
}

// Fills the domain through its boundary loops rather than triangle by
// triangle: the boundary is tiny compared to the mesh, and with every loop
// oriented with the domain on its left the nonzero rule fills exactly the
// domain, holes and islands included.
inline void svg_fill_domain(const std::vector<std::array<double, 2> >& pts,
                            const std::vector<std::array<std::size_t, 2> >& directed,
                            const Svg_box& view, const Svg_box& clip,
                            Svg_path_writer& out)
{
  const std::size_t nv = pts.size();
  std::vector<std::size_t> first(nv + 1, 0);
  for(const std::array<std::size_t, 2>& e : directed)
    ++first[e[0] + 1];
  for(std::size_t v = 0; v < nv; ++v)
    first[v + 1] += first[v];
  std::vector<std::size_t> adj(first[nv]);
  std::vector<std::size_t> next(first.begin(), first.end() - 1);
  for(std::size_t k = 0; k < directed.size(); ++k)
    adj[next[directed[k][0]]++] = k;
  std::copy(first.begin(), first.end() - 1, next.begin());
  std::vector<char> used(directed.size(), 0);

  std::vector<std::array<double, 2> > loop;
  for(std::size_t k0 = 0; k0 < directed.size(); ++k0) {
    if(used[k0])
      continue;
    used[k0] = 1;
    loop.clear();
    loop.push_back(pts[directed[k0][0]]);
    std::size_t cur = directed[k0][1];
    int code_and = svg_outcode(pts[directed[k0][0]], view);
    bool inside_clip = svg_outcode(pts[directed[k0][0]], clip) == 0;
    for(;;) {
      // As many boundary edges enter a vertex as leave it, so the walk ends
      // where it started.
      while(next[cur] < first[cur + 1] && used[adj[next[cur]]])
        ++next[cur];
      if(next[cur] == first[cur + 1])
        break;
      loop.push_back(pts[cur]);
      code_and &= svg_outcode(pts[cur], view);
      inside_clip = inside_clip && svg_outcode(pts[cur], clip) == 0;
      const std::size_t k = adj[next[cur]];
      used[k] = 1;
      cur = directed[k][1];
    }
    if(code_and != 0)
      continue; // wholly on one side outside the window
    if(!inside_clip)
      svg_clip_polygon(loop, clip);
    if(loop.size() < 3)
      continue;
    out.move_to(loop[0]);
    for(std::size_t i = 1; i < loop.size(); ++i)
      out.line_to(loop[i]);
    out.close();
  }
}

inline std::string svg_escape(const std::string& s)
{
  std::string r;
  for(char c : s) {
    switch(c) {
    case '&': r += "&amp;"; break;
    case '<': r += "&lt;"; break;
    case '>': r += "&gt;"; break;
    case '"': r += "&quot;"; break;
    default:
      // Control characters other than tab and line ends are not allowed in
      // XML 1.0 at all, even escaped.
      if(static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n' || c == '\r')
        r += c;
    }
  }
  return r;
}

inline std::string svg_number(double v)
{
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(7);
  os << v;
  return os.str();
}

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

/*!
\ingroup PkgAdvancingFrontMesh2IO

Draws the in-domain triangles of `cdt` as an SVG picture: a light fill for
the domain, the triangle edges in thin grey-blue and the constrained edges
bordering the domain in thick black on top. The y axis points up, as in the
mesh, and the view box fits the in-domain vertices, or the window of
`options`, with a small margin.

The output is meant to stay usable for meshes of millions of triangles: each
edge is drawn once, the edges are chained into polylines inside a `<path>`
per layer (split every 64 KB, since some SVG libraries fail on much longer
path data), the fill is drawn from the domain boundary only, and coordinates
are rounded on a grid of about six significant digits of the picture size,
far below what can be seen. With a window, edges wholly outside it are
skipped and those reaching far outside are clipped, so that a deep zoom
does not produce coordinates renderers cannot handle. The thin stroke width
adapts to the mean edge length so that a dense mesh does not turn into a
solid blot; `options.stroke_scale` scales both widths.

\tparam CDT as in `write_OFF()`

\param os the output stream
\param cdt the meshed triangulation
\param options picture size, title, stroke scale and optional window

\throws std::invalid_argument if `options.width_px` is not in (0, 1e7],
`options.stroke_scale` is not positive and finite, the window is empty or
not finite, or the coordinates are too large to be drawn
*/
template <class CDT>
void write_SVG(std::ostream& os, const CDT& cdt,
               const SVG_options& options = SVG_options())
{
  typedef typename CDT::Face_handle Face_handle;
  typedef std::array<double, 2> P;

  if(!(options.width_px > 0 && options.width_px <= 1e7))
    throw std::invalid_argument("write_SVG: width_px must be in (0, 1e7]");
  if(!(options.stroke_scale > 0 && std::isfinite(options.stroke_scale)))
    throw std::invalid_argument("write_SVG: stroke_scale must be positive and finite");
  if(options.has_window &&
     !(std::isfinite(options.xmin) && std::isfinite(options.xmax) &&
       std::isfinite(options.ymin) && std::isfinite(options.ymax) &&
       options.xmin < options.xmax && options.ymin < options.ymax))
    throw std::invalid_argument("write_SVG: the window must be finite and non-empty");

  internal::Mesh_domain_view<CDT> m;
  internal::mesh_collect_domain(cdt, m);
  const std::vector<P>& pts = m.points;
  const std::size_t nf = m.triangles.size();

  // Each undirected edge once: from the face where it is seen first, or from
  // the in-domain side. Face indices, not addresses, decide, so that the
  // output does not depend on where the faces happen to be allocated.
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  CGAL::Unique_hash_map<Face_handle, std::size_t> face_index(none, nf);
  for(std::size_t i = 0; i < nf; ++i)
    face_index[m.faces[i]] = i;
  std::vector<std::array<std::size_t, 2> > thin_edges, thick_edges, boundary;
  for(std::size_t fi = 0; fi < nf; ++fi) {
    const Face_handle f = m.faces[fi];
    for(int i = 0; i < 3; ++i) {
      const Face_handle n = f->neighbor(i);
      const bool n_in = !cdt.is_infinite(n) && n->is_in_domain();
      const std::array<std::size_t, 2> e{{m.triangles[fi][(i + 1) % 3],
                                          m.triangles[fi][(i + 2) % 3]}};
      if(n_in && face_index[n] < fi)
        continue;
      if(!n_in)
        boundary.push_back(e); // oriented with the domain on its left
      if(cdt.is_constrained(typename CDT::Edge(f, i)))
        thick_edges.push_back(e);
      else
        thin_edges.push_back(e);
    }
  }

  // The region drawn, in mesh coordinates.
  double xmin = 0, ymin = 0, xmax = 1, ymax = 1;
  if(options.has_window) {
    xmin = options.xmin; ymin = options.ymin; xmax = options.xmax; ymax = options.ymax;
  } else if(!pts.empty()) {
    xmin = xmax = pts[0][0];
    ymin = ymax = pts[0][1];
    for(const P& p : pts) {
      xmin = (std::min)(xmin, p[0]); xmax = (std::max)(xmax, p[0]);
      ymin = (std::min)(ymin, p[1]); ymax = (std::max)(ymax, p[1]);
    }
  }
  double span = (std::max)(xmax - xmin, ymax - ymin);
  if(!(span > 0))
    span = 1; // a degenerate mesh still gets a picture
  const double margin = 0.02 * span;
  const internal::Svg_box view{xmin - margin, ymin - margin, xmax + margin, ymax + margin};
  const double view_w = view.xmax - view.xmin, view_h = view.ymax - view.ymin;
  const internal::Svg_box clip{view.xmin - view_w, view.ymin - view_h,
                               view.xmax + view_w, view.ymax + view_h};

  // Every difference computed while clipping must be finite.
  double uxmin = clip.xmin, uymin = clip.ymin, uxmax = clip.xmax, uymax = clip.ymax;
  for(const P& p : pts) {
    uxmin = (std::min)(uxmin, p[0]); uxmax = (std::max)(uxmax, p[0]);
    uymin = (std::min)(uymin, p[1]); uymax = (std::max)(uymax, p[1]);
  }
  if(!std::isfinite(uxmax - uxmin) || !std::isfinite(uymax - uymin))
    throw std::invalid_argument("write_SVG: coordinates too large to be drawn");

  // The height is capped like the width, so that a very slender domain does
  // not produce a picture no viewer can open.
  double scale = options.width_px / view_w;
  if(view_h * scale > 1e7)
    scale = 1e7 / view_h;
  if(!(scale > 0) || !std::isfinite(scale))
    throw std::invalid_argument("write_SVG: the drawn region is too small");
  const double width = view_w * scale, height = view_h * scale;
  const double largest = (std::max)(width, height);
  int decimals = 5 - static_cast<int>(std::floor(std::log10(largest)));
  decimals = (std::max)(0, (std::min)(9, decimals));

  // Mean length of the drawn edges in pixels, for the thin stroke width.
  double sum = 0;
  std::size_t count = 0;
  for(const std::vector<std::array<std::size_t, 2> >* list : {&thin_edges, &thick_edges})
    for(const std::array<std::size_t, 2>& e : *list) {
      const P& a = pts[e[0]];
      const P& b = pts[e[1]];
      if((internal::svg_outcode(a, view) & internal::svg_outcode(b, view)) != 0)
        continue;
      sum += std::hypot(b[0] - a[0], b[1] - a[1]);
      ++count;
    }
  const double mean_px = count == 0 ? 10 : scale * sum / static_cast<double>(count);
  const double thin_w = options.stroke_scale * (std::max)(0.05, (std::min)(0.6, 0.08 * mean_px));
  const double thick_w = options.stroke_scale * 1.5;

  // formatting and locale only: restoring the error state would hide a failed write
  boost::io::ios_base_all_saver format_saver(os);
  boost::io::ios_locale_saver locale_saver(os);
  os.imbue(std::locale::classic());

  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\""
     << internal::svg_number(width) << "\" height=\"" << internal::svg_number(height)
     << "\" viewBox=\"0 0 " << internal::svg_number(width) << ' '
     << internal::svg_number(height) << "\">\n";
  if(!options.title.empty())
    os << "<title>" << internal::svg_escape(options.title) << "</title>\n";

  {
    internal::Svg_path_writer fill(os, "fill=\"#dde7f3\" fill-rule=\"nonzero\" stroke=\"none\"",
                                   view.xmin, view.ymax, scale, decimals, false);
    internal::svg_fill_domain(pts, boundary, view, clip, fill);
    fill.finish();
  }
  if(options.color_by_quality) {
    static const double upper[7] = {0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 2.};
    static const char* const colour[7] = {"#7f0000", "#e31a1c", "#fd8d3c", "#fed976",
                                          "#c7e9a0", "#74c476", "#d4e8f5"};
    std::vector<std::vector<std::size_t> > bins(7);
    for(std::size_t fi = 0; fi < nf; ++fi) {
      const P& a = pts[m.triangles[fi][0]];
      const P& b = pts[m.triangles[fi][1]];
      const P& c = pts[m.triangles[fi][2]];
      // drawn unclipped: only triangles within the clip box, all of whose
      // pixel coordinates are then small; the plain fill shows under others
      if(internal::svg_outcode(a, clip) | internal::svg_outcode(b, clip) | internal::svg_outcode(c, clip))
        continue;
      if(internal::svg_outcode(a, view) & internal::svg_outcode(b, view) & internal::svg_outcode(c, view))
        continue;
      const double rr = (std::max)(CGAL::Advancing_front_mesh_2::internal::radius_ratio(a[0], a[1], b[0], b[1], c[0], c[1]),
                                   CGAL::Advancing_front_mesh_2::internal::radius_ratio(a[0], a[1], c[0], c[1], b[0], b[1]));
      std::size_t k = 0;
      while(rr >= upper[k] && k < 6) ++k;
      bins[k].push_back(fi);
    }
    for(std::size_t k = 0; k < 7; ++k) {
      // split into elements of bounded length (each triangle is a closed
      // subpath of its own), which viewers need for large meshes
      internal::Svg_path_writer fill(os, std::string("fill=\"") + colour[k] + "\" stroke=\"none\"",
                                     view.xmin, view.ymax, scale, decimals, true);
      for(std::size_t fi : bins[k]) {
        fill.move_to(pts[m.triangles[fi][0]]);
        fill.line_to(pts[m.triangles[fi][1]]);
        fill.line_to(pts[m.triangles[fi][2]]);
        fill.close();
      }
      fill.finish();
    }
  }
  {
    internal::Svg_path_writer thin(os, "fill=\"none\" stroke=\"#6f88a6\" stroke-width=\"" +
                                       internal::svg_number(thin_w) +
                                       "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"",
                                   view.xmin, view.ymax, scale, decimals, true);
    internal::svg_draw_edges(pts, thin_edges, view, clip, thin);
    thin.finish();
  }
  {
    internal::Svg_path_writer thick(os, "fill=\"none\" stroke=\"#000000\" stroke-width=\"" +
                                        internal::svg_number(thick_w) +
                                        "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"",
                                    view.xmin, view.ymax, scale, decimals, true);
    internal::svg_draw_edges(pts, thick_edges, view, clip, thick);
    thick.finish();
  }
  os << "</svg>\n";
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the in-domain triangles of `cdt` to `file_name`, in the format given
by its extension (case-insensitive):
- `.off`: `write_OFF()`;
- `.vtu`: `CGAL::IO::write_VTU()` in ASCII mode with `max_digits10` digits.
  This writer is CGAL's: it lists all vertices of the triangulation, not only
  those of the domain, and adds the constrained edges as line cells;
- `.node` or `.ele`: `write_triangle_node_ele()`, which writes both files;
- `.msh`: `write_gmsh_msh()`;
- `.svg`: `write_SVG()` with default options.

\tparam CDT as in `write_OFF()`

\param file_name path of the file to create or overwrite
\param cdt the meshed triangulation

\throws std::invalid_argument if the extension is none of the above; nothing
is written then
\throws std::runtime_error "cannot write FILE" when a file cannot be opened
or written
*/
template <class CDT>
void write_mesh(const std::string& file_name, const CDT& cdt)
{
  const std::string ext = internal::mesh_lower_extension(file_name);
  if(ext == "off") {
    internal::mesh_write_file(file_name, [&](std::ostream& os) { write_OFF(os, cdt); });
  } else if(ext == "vtu") {
    internal::mesh_write_file(file_name, [&](std::ostream& os) {
      // ASCII, because CGAL 5.5's binary mode leaves out the closing
      // </AppendedData> tag, so that XML parsers (meshio, for one) reject the
      // file, and dumps the bytes of the kernel's FT as if they were doubles,
      // which is garbage for any kernel but Epick.
      // formatting and locale only: restoring the error state would hide a failed write
      boost::io::ios_base_all_saver format_saver(os);
      boost::io::ios_locale_saver locale_saver(os);
      internal::mesh_set_exact_format(os);
      CGAL::IO::write_VTU(os, cdt, CGAL::IO::ASCII);
    });
  } else if(ext == "node" || ext == "ele") {
    write_triangle_node_ele(file_name.substr(0, file_name.size() - ext.size() - 1), cdt);
  } else if(ext == "msh") {
    internal::mesh_write_file(file_name, [&](std::ostream& os) { write_gmsh_msh(os, cdt); });
  } else if(ext == "svg") {
    internal::mesh_write_file(file_name, [&](std::ostream& os) { write_SVG(os, cdt); });
  } else {
    throw std::invalid_argument("write_mesh: unknown extension of '" + file_name +
                                "' (expected .off, .vtu, .node, .ele, .msh or .svg)");
  }
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_MESH_H
