// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

// Loaders for the real geometries of the read-only shared data folder
// (../shared/data beside the checkout; see its SOURCES.md for the origin
// and the format of every file). Test code only: the project has strict
// readers elsewhere, these exist so that the tests do not depend on them.
//
// Every loader throws std::runtime_error naming the file (and the line,
// where there is one) on any problem: missing file, malformed line, index
// out of range, or a result that is not a simple PSLG with valid hole seeds.
// Loaders that take `std::vector<std::string>* fixes` append one line per
// repair they made to the data (nothing is repaired silently).

#ifndef AFM_SHARED_DATA_H
#define AFM_SHARED_DATA_H

#include <afm_geometries.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace afm_shared_data {

using afm_geometry::Loop;
using afm_geometry::Point;
using afm_geometry::Poly_data;

namespace detail {

// Line reader: strips '\r', counts lines, and reports errors as
// "file:line: message".
class Line_reader
{
public:
  explicit Line_reader(const std::string& path) : path_(path), in_(path)
  {
    if(!in_)
      throw std::runtime_error(path + ": cannot open file");
  }

  // Next line (false at end of file).
  bool next(std::string& line)
  {
    if(!std::getline(in_, line))
      return false;
    ++line_no_;
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    return true;
  }

  [[noreturn]] void fail(const std::string& msg) const
  {
    throw std::runtime_error(path_ + ":" + std::to_string(line_no_) + ": " + msg);
  }

  std::size_t line_no() const { return line_no_; }
  const std::string& path() const { return path_; }

private:
  std::string path_;
  std::ifstream in_;
  std::size_t line_no_ = 0;
};

inline bool blank(const std::string& s)
{
  return s.find_first_not_of(" \t") == std::string::npos;
}

inline std::vector<std::string> split(const std::string& s, const std::string& seps)
{
  std::vector<std::string> out;
  std::size_t i = 0;
  while(i < s.size()) {
    const std::size_t j = s.find_first_of(seps, i);
    const std::size_t end = j == std::string::npos ? s.size() : j;
    if(end > i)
      out.push_back(s.substr(i, end - i));
    i = end + 1;
  }
  return out;
}

inline std::string trim(const std::string& s)
{
  const std::size_t b = s.find_first_not_of(" \t");
  if(b == std::string::npos)
    return std::string();
  const std::size_t e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

inline bool parse_double(const std::string& tok, double& v)
{
  std::istringstream is(tok);
  is.imbue(std::locale::classic());
  is >> v;
  return !is.fail() && is.eof() && std::isfinite(v);
}

inline bool parse_index(const std::string& tok, long long& v)
{
  std::istringstream is(tok);
  is.imbue(std::locale::classic());
  is >> v;
  return !is.fail() && is.eof();
}

inline double number(const Line_reader& r, const std::string& tok)
{
  double v;
  if(!parse_double(tok, v))
    r.fail("expected a number, got \"" + tok + "\"");
  return v;
}

inline long long integer(const Line_reader& r, const std::string& tok)
{
  long long v;
  if(!parse_index(tok, v))
    r.fail("expected an integer, got \"" + tok + "\"");
  return v;
}

// Removes consecutive duplicates (cyclically); reports what it removed.
inline Loop remove_consecutive_duplicates(const Loop& in, const std::string& what, std::vector<std::string>* fixes)
{
  Loop out;
  std::size_t removed = 0;
  for(const Point& p : in) {
    if(!out.empty() && out.back() == p) {
      ++removed;
      continue;
    }
    out.push_back(p);
  }
  while(out.size() > 1 && out.back() == out.front()) {
    out.pop_back();
    ++removed;
  }
  if(removed > 0 && fixes != nullptr)
    fixes->push_back(what + ": removed " + std::to_string(removed) + " consecutive duplicate point(s)");
  return out;
}

inline void check_result(const Poly_data& pd, const std::string& what)
{
  std::string why;
  if(!afm_geometry::is_simple_pslg(pd, &why))
    throw std::runtime_error(what + ": not a simple PSLG: " + why);
  if(!afm_geometry::hole_seeds_valid(pd, &why))
    throw std::runtime_error(what + ": invalid loops or hole seeds: " + why);
}

// All coordinate pairs of an airfoil .dat file, as they stand.
inline Loop read_xy_points(const std::string& path, bool has_name_line)
{
  Line_reader r(path);
  std::string line;
  bool name_pending = has_name_line;
  Loop pts;
  while(r.next(line)) {
    if(blank(line))
      continue;
    if(name_pending) {
      name_pending = false;
      continue;
    }
    const std::vector<std::string> tok = split(line, " \t,");
    if(tok.size() != 2)
      r.fail("expected \"x y\", got \"" + line + "\"");
    pts.push_back({number(r, tok[0]), number(r, tok[1])});
  }
  return pts;
}

} // namespace detail

/// A contour from an airfoil .dat file: one "x y" pair per line (blank
/// lines ignored), preceded by a name line if `has_name_line` (Selig
/// style). A repeated last point equal to the first is dropped; an open
/// contour (first != last) is returned as it is: the loop builder closes it
/// with a segment last -> first.
inline Loop read_xy_dat(const std::string& path, bool has_name_line)
{
  Loop pts = detail::read_xy_points(path, has_name_line);
  if(pts.size() > 1 && pts.front() == pts.back())
    pts.pop_back();
  if(pts.size() < 3)
    throw std::runtime_error(path + ": fewer than 3 distinct contour points");
  return pts;
}

namespace detail {

// Reads one airfoil element, removes duplicates, reports an open contour
// (closed by the loop builder with a segment) and checks that the loop is
// simple. Returns it clockwise (hole orientation).
inline Loop read_element(const std::string& path, bool has_name_line, const std::string& name,
                         std::vector<std::string>* fixes)
{
  const Loop raw = read_xy_points(path, has_name_line);
  if(raw.size() < 3)
    throw std::runtime_error(path + ": fewer than 3 contour points");
  const std::string what = name + " (" + path + ")";
  if(raw.front() != raw.back() && fixes != nullptr) {
    std::ostringstream os;
    os << what << ": open contour (gap " << std::hypot(raw.back()[0] - raw.front()[0], raw.back()[1] - raw.front()[1])
       << " between last and first point), closed with a segment";
    fixes->push_back(os.str());
  }
  Loop l = raw;
  if(l.front() == l.back())
    l.pop_back();
  l = remove_consecutive_duplicates(l, what, fixes);
  if(l.size() < 3)
    throw std::runtime_error(path + ": fewer than 3 distinct contour points");
  Poly_data single;
  afm_geometry::append_loop(single, l);
  std::string why;
  if(!afm_geometry::is_simple_pslg(single, &why))
    throw std::runtime_error(path + ": the " + name + " contour is not a simple loop: " + why);
  if(afm_geometry::signed_area(l) > 0 && fixes != nullptr)
    fixes->push_back(what + ": reversed to clockwise (hole orientation)");
  return afm_geometry::cw(l);
}

inline Poly_data elements_in_far_field(const std::vector<Loop>& elements, double far_radius, std::size_t n_far,
                                       const std::string& what)
{
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for(const Loop& l : elements)
    for(const Point& p : l)
      for(int k = 0; k < 2; ++k) {
        lo[k] = std::min(lo[k], p[k]);
        hi[k] = std::max(hi[k], p[k]);
      }
  const Point c{0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])};
  const double half_diag = 0.5 * std::hypot(hi[0] - lo[0], hi[1] - lo[1]);
  if(!(far_radius * std::cos(afm_geometry::pi / double(std::max<std::size_t>(n_far, 3))) > 1.5 * half_diag))
    throw std::runtime_error(what + ": far-field radius too small");
  std::vector<Loop> loops{afm_geometry::circle(c, far_radius, n_far)};
  for(const Loop& l : elements)
    loops.push_back(l);
  Poly_data pd = afm_geometry::polygon_with_holes(loops);
  check_result(pd, what);
  return pd;
}

} // namespace detail

/// McDonnell-Douglas 30P-30N (slat, main, flap) from
/// `data_dir`/30p30n_linuxguy123/30P-30N-{Slat,Main,Flap}-raw.dat as three
/// holes in a circular far field (radius `far_radius`, `n_far` points,
/// centred on the configuration's bounding box). The flap contour is open
/// (blunt base) and is closed with a segment. `data_dir` is the shared data
/// folder (afm_test::shared_data_dir()).
inline Poly_data thirty_p_thirty_n(const std::string& data_dir, double far_radius = 20, std::size_t n_far = 96,
                                   std::vector<std::string>* fixes = nullptr)
{
  const std::string d = data_dir + "/30p30n_linuxguy123/";
  std::vector<Loop> el;
  el.push_back(detail::read_element(d + "30P-30N-Slat-raw.dat", false, "30P-30N slat", fixes));
  el.push_back(detail::read_element(d + "30P-30N-Main-raw.dat", false, "30P-30N main", fixes));
  el.push_back(detail::read_element(d + "30P-30N-Flap-raw.dat", false, "30P-30N flap", fixes));
  return detail::elements_in_far_field(el, far_radius, n_far, d + "30P-30N-*-raw.dat");
}

/// NLR 7301 main element + flap (`data_dir`/nlr7301_viiflow/NLR7301.dat and
/// NLR7301FLAP.dat, Selig format with a name line, common frame) as two
/// holes in a circular far field.
inline Poly_data nlr7301_with_flap(const std::string& data_dir, double far_radius = 20, std::size_t n_far = 96,
                                   std::vector<std::string>* fixes = nullptr)
{
  const std::string d = data_dir + "/nlr7301_viiflow/";
  std::vector<Loop> el;
  el.push_back(detail::read_element(d + "NLR7301.dat", true, "NLR 7301 main", fixes));
  el.push_back(detail::read_element(d + "NLR7301FLAP.dat", true, "NLR 7301 flap", fixes));
  return detail::elements_in_far_field(el, far_radius, n_far, d + "NLR7301*.dat");
}

/// JIGSAW .msh geometry (MESH2D poly-data, e.g. mesh2d/lake.msh): `#`
/// comments, `mshid=`, `ndims=2`, `point=N` followed by N lines `x;y;tag`,
/// `edge2=M` followed by M lines `i;j;tag` (0-based). The edges must form
/// closed, non-intersecting loops. Nesting follows the even-odd rule:
/// loops at odd depth are holes and get one seed each (inside the hole,
/// outside the loops nested in it); outer loops are made counter-clockwise
/// and holes clockwise. Points used by no edge are kept (after the loop
/// points) only if they lie strictly inside the domain and are not already
/// present; the others are dropped.
inline Poly_data mesh2d_jigsaw(const std::string& path)
{
  detail::Line_reader r(path);
  std::string line;
  std::vector<Point> pts;
  std::vector<std::array<std::size_t, 2> > edges;
  bool have_points = false, have_edges = false;
  while(r.next(line)) {
    const std::string t = detail::trim(line);
    if(t.empty() || t[0] == '#')
      continue;
    const std::size_t eq = t.find('=');
    if(eq == std::string::npos)
      r.fail("expected \"keyword=value\", got \"" + t + "\"");
    std::string key = detail::trim(t.substr(0, eq));
    std::transform(key.begin(), key.end(), key.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const std::string val = detail::trim(t.substr(eq + 1));
    if(key == "mshid") {
      continue;
    } else if(key == "ndims") {
      if(detail::integer(r, val) != 2)
        r.fail("only ndims=2 is supported");
    } else if(key == "point" || key == "edge2") {
      const long long n = detail::integer(r, val);
      if(n < 0)
        r.fail("negative count");
      const bool is_point = key == "point";
      if((is_point && have_points) || (!is_point && have_edges))
        r.fail("repeated section " + key);
      (is_point ? have_points : have_edges) = true;
      for(long long k = 0; k < n; ++k) {
        if(!r.next(line))
          r.fail("unexpected end of file in section " + key);
        const std::vector<std::string> tok = detail::split(detail::trim(line), ";");
        if(tok.size() != 3)
          r.fail("expected 3 fields separated by ';', got \"" + line + "\"");
        if(is_point) {
          pts.push_back({detail::number(r, tok[0]), detail::number(r, tok[1])});
        } else {
          const long long i = detail::integer(r, tok[0]), j = detail::integer(r, tok[1]);
          if(!have_points || i < 0 || j < 0 || i >= (long long)pts.size() || j >= (long long)pts.size())
            r.fail("edge vertex index out of range");
          if(i == j)
            r.fail("degenerate edge");
          edges.push_back({std::size_t(i), std::size_t(j)});
        }
      }
    } else {
      r.fail("unsupported section \"" + key + "\"");
    }
  }
  if(!have_points || !have_edges)
    throw std::runtime_error(path + ": missing point= or edge2= section");

  Poly_data all;
  all.points = pts;
  all.segments = edges;
  std::vector<std::vector<std::size_t> > idx;
  std::string why;
  if(!afm_geometry::extract_loop_indices(all, idx, &why))
    throw std::runtime_error(path + ": edges do not form closed loops: " + why);
  std::vector<Loop> loops;
  std::vector<bool> on_loop(pts.size(), false);
  for(const auto& l : idx) {
    Loop pl;
    for(std::size_t v : l) {
      pl.push_back(pts[v]);
      on_loop[v] = true;
    }
    loops.push_back(std::move(pl));
  }
  {
    Poly_data loops_only;
    for(const Loop& l : loops)
      afm_geometry::append_loop(loops_only, l);
    if(!afm_geometry::is_simple_pslg(loops_only, &why))
      throw std::runtime_error(path + ": loops are not simple: " + why);
  }
  Poly_data pd = afm_geometry::from_nested_loops(loops);
  // Isolated points.
  std::vector<Point> present(pd.points);
  std::sort(present.begin(), present.end());
  for(std::size_t i = 0; i < pts.size(); ++i) {
    if(on_loop[i])
      continue;
    const Point& p = pts[i];
    if(std::binary_search(present.begin(), present.end(), p))
      continue; // duplicate of a loop vertex or of a kept point
    int depth = 0;
    bool on_boundary = false;
    for(const Loop& l : loops) {
      if(afm_geometry::distance_to_loop(p, l) == 0) {
        on_boundary = true;
        break;
      }
      if(afm_geometry::point_in_polygon(p, l))
        ++depth;
    }
    if(on_boundary || depth % 2 == 0)
      continue;
    pd.points.push_back(p);
    present.insert(std::upper_bound(present.begin(), present.end(), p), p);
  }
  detail::check_result(pd, path);
  return pd;
}

/// Minimal reader for Triangle's .poly files with the vertices inline
/// (e.g. triangle_drufat/A.poly): `#` comments; header `n dim attrs markers`;
/// vertex lines `id x y [attributes] [marker]`; `m markers`; segment lines
/// `id a b [marker]`; `h`; hole lines `id x y`; the optional regions are
/// ignored. Indices are made 0-based using the first vertex id (0 or 1).
/// No geometric check is made (files such as box.poly or face.poly are not
/// made of closed loops).
inline Poly_data triangle_poly(const std::string& path)
{
  detail::Line_reader r(path);
  auto next_tokens = [&](const char* what) {
    std::string line;
    while(r.next(line)) {
      const std::size_t hash = line.find('#');
      if(hash != std::string::npos)
        line.erase(hash);
      std::vector<std::string> tok = detail::split(line, " \t,");
      if(!tok.empty())
        return tok;
    }
    r.fail(std::string("unexpected end of file, expected ") + what);
  };
  auto count = [&](const std::string& tok) {
    const long long v = detail::integer(r, tok);
    if(v < 0)
      r.fail("negative count");
    return std::size_t(v);
  };
  Poly_data pd;
  std::vector<std::string> tok = next_tokens("the vertex header");
  if(tok.size() < 2)
    r.fail("vertex header needs at least 2 fields");
  const std::size_t nv = count(tok[0]);
  if(detail::integer(r, tok[1]) != 2)
    r.fail("dimension must be 2");
  if(nv == 0)
    r.fail("vertices in a separate .node file are not supported");
  const std::size_t n_attr = tok.size() > 2 ? count(tok[2]) : 0;
  const std::size_t n_mark = tok.size() > 3 ? count(tok[3]) : 0;
  long long base = 0;
  for(std::size_t k = 0; k < nv; ++k) {
    tok = next_tokens("a vertex line");
    if(tok.size() < 3 || tok.size() > 3 + n_attr + n_mark)
      r.fail("malformed vertex line");
    const long long id = detail::integer(r, tok[0]);
    if(k == 0) {
      if(id != 0 && id != 1)
        r.fail("first vertex id must be 0 or 1");
      base = id;
    }
    if(id != base + (long long)k)
      r.fail("vertex ids must be consecutive");
    pd.points.push_back({detail::number(r, tok[1]), detail::number(r, tok[2])});
  }
  tok = next_tokens("the segment header");
  const std::size_t ns = count(tok[0]);
  for(std::size_t k = 0; k < ns; ++k) {
    tok = next_tokens("a segment line");
    if(tok.size() < 3 || tok.size() > 4)
      r.fail("malformed segment line");
    const long long a = detail::integer(r, tok[1]) - base, b = detail::integer(r, tok[2]) - base;
    if(a < 0 || b < 0 || a >= (long long)nv || b >= (long long)nv)
      r.fail("segment vertex index out of range");
    pd.segments.push_back({std::size_t(a), std::size_t(b)});
  }
  tok = next_tokens("the hole count");
  const std::size_t nh = count(tok[0]);
  for(std::size_t k = 0; k < nh; ++k) {
    tok = next_tokens("a hole line");
    if(tok.size() != 3)
      r.fail("malformed hole line");
    pd.holes.push_back({detail::number(r, tok[1]), detail::number(r, tok[2])});
  }
  return pd;
}

} // namespace afm_shared_data

#endif // AFM_SHARED_DATA_H
