// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_SVG_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_SVG_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Double_geometry.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Svg_clipping.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Svg_drawing.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Svg_path_writer.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Svg_text.h>

#include <CGAL/Unique_hash_map.h>

#include <boost/io/ios_state.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <locale>
#include <ostream>
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
  /// green below 0.9, green below 0.95, pale blue from 0.95 (equilateral),
  /// with a key to the colours in the top left corner; one path element
  /// per colour keeps large meshes fast to write and view
  bool color_by_quality = false;
};

namespace internal {

// Refused before anything is written.
inline void svg_check_options(const SVG_options& options)
{
  if(!(options.width_px > 0 && options.width_px <= 1e7))
    throw std::invalid_argument("write_SVG: width_px must be in (0, 1e7]");
  if(!(options.stroke_scale > 0 && std::isfinite(options.stroke_scale)))
    throw std::invalid_argument("write_SVG: stroke_scale must be positive and finite");
  if(options.has_window &&
     !(std::isfinite(options.xmin) && std::isfinite(options.xmax) &&
       std::isfinite(options.ymin) && std::isfinite(options.ymax) &&
       options.xmin < options.xmax && options.ymin < options.ymax))
    throw std::invalid_argument("write_SVG: the window must be finite and non-empty");
}

// The edges of the in-domain triangles, as pairs of indices into the
// points of the Mesh_domain_view, sorted into the layers drawn.
struct Svg_edge_layers
{
  std::vector<std::array<std::size_t, 2> > thin;     // not constrained
  std::vector<std::array<std::size_t, 2> > thick;    // constrained
  std::vector<std::array<std::size_t, 2> > boundary; // of the domain, for its fill
};

template <class CDT>
Svg_edge_layers svg_edge_layers(const CDT& cdt, const Mesh_domain_view<CDT>& m)
{
  typedef typename CDT::Face_handle Face_handle;
  const std::size_t nf = m.triangles.size();
  Svg_edge_layers layers;

  // Each undirected edge once: from the face where it is seen first, or from
  // the in-domain side. Face indices, not addresses, decide, so that the
  // output does not depend on where the faces happen to be allocated.
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  CGAL::Unique_hash_map<Face_handle, std::size_t> face_index(none, nf);
  for(std::size_t i = 0; i < nf; ++i)
    face_index[m.faces[i]] = i;
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
        layers.boundary.push_back(e); // oriented with the domain on its left
      if(cdt.is_constrained(typename CDT::Edge(f, i)))
        layers.thick.push_back(e);
      else
        layers.thin.push_back(e);
    }
  }
  return layers;
}

// Where the picture lies in mesh coordinates, and its size in pixels.
struct Svg_frame
{
  Svg_box view;         // what is drawn: the region with a margin
  Svg_box clip;         // beyond which lines are clipped
  double scale;         // pixels per unit of the mesh
  double width, height; // of the picture, in pixels
  int decimals;         // of the path coordinates, in pixels
};

// The region drawn, in mesh coordinates: the window, or the box of the
// points; with a margin.
inline Svg_box svg_view_box(const SVG_options& options,
                            const std::vector<std::array<double, 2> >& pts)
{
  typedef std::array<double, 2> P;
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
  return Svg_box{xmin - margin, ymin - margin, xmax + margin, ymax + margin};
}

// Every difference computed while clipping must be finite.
inline void svg_check_clippable(const std::vector<std::array<double, 2> >& pts,
                                const Svg_box& clip)
{
  typedef std::array<double, 2> P;
  double uxmin = clip.xmin, uymin = clip.ymin, uxmax = clip.xmax, uymax = clip.ymax;
  for(const P& p : pts) {
    uxmin = (std::min)(uxmin, p[0]); uxmax = (std::max)(uxmax, p[0]);
    uymin = (std::min)(uymin, p[1]); uymax = (std::max)(uymax, p[1]);
  }
  if(!std::isfinite(uxmax - uxmin) || !std::isfinite(uymax - uymin))
    throw std::invalid_argument("write_SVG: coordinates too large to be drawn");
}

inline Svg_frame svg_frame(const SVG_options& options,
                           const std::vector<std::array<double, 2> >& pts)
{
  Svg_frame f;
  f.view = svg_view_box(options, pts);
  const Svg_box& view = f.view;
  const double view_w = view.xmax - view.xmin, view_h = view.ymax - view.ymin;
  f.clip = Svg_box{view.xmin - view_w, view.ymin - view_h,
                   view.xmax + view_w, view.ymax + view_h};
  svg_check_clippable(pts, f.clip);

  // The height is capped like the width, so that a very slender domain does
  // not produce a picture no viewer can open.
  double scale = options.width_px / view_w;
  if(view_h * scale > 1e7)
    scale = 1e7 / view_h;
  if(!(scale > 0) || !std::isfinite(scale))
    throw std::invalid_argument("write_SVG: the drawn region is too small");
  f.scale = scale;
  f.width = view_w * scale;
  f.height = view_h * scale;
  const double largest = (std::max)(f.width, f.height);
  int decimals = 5 - static_cast<int>(std::floor(std::log10(largest)));
  f.decimals = (std::max)(0, (std::min)(9, decimals));
  return f;
}

// Mean length of the drawn edges in pixels, for the thin stroke width.
inline double svg_mean_edge_pixels(const std::vector<std::array<double, 2> >& pts,
                                   const Svg_edge_layers& layers, const Svg_frame& f)
{
  typedef std::array<double, 2> P;
  double sum = 0;
  std::size_t count = 0;
  for(const std::vector<std::array<std::size_t, 2> >* list : {&layers.thin, &layers.thick})
    for(const std::array<std::size_t, 2>& e : *list) {
      const P& a = pts[e[0]];
      const P& b = pts[e[1]];
      if((svg_outcode(a, f.view) & svg_outcode(b, f.view)) != 0)
        continue;
      sum += std::hypot(b[0] - a[0], b[1] - a[1]);
      ++count;
    }
  return count == 0 ? 10 : f.scale * sum / static_cast<double>(count);
}

inline void svg_write_header(std::ostream& os, const Svg_frame& f, const std::string& title)
{
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\""
     << svg_number(f.width) << "\" height=\"" << svg_number(f.height)
     << "\" viewBox=\"0 0 " << svg_number(f.width) << ' '
     << svg_number(f.height) << "\">\n";
  if(!title.empty())
    os << "<title>" << svg_escape(title) << "</title>\n";
}

inline void svg_write_domain_fill(std::ostream& os,
                                  const std::vector<std::array<double, 2> >& pts,
                                  const std::vector<std::array<std::size_t, 2> >& boundary,
                                  const Svg_frame& f)
{
  Svg_path_writer fill(os, "fill=\"#dde7f3\" fill-rule=\"nonzero\" stroke=\"none\"",
                       f.view.xmin, f.view.ymax, f.scale, f.decimals, false);
  svg_fill_domain(pts, boundary, f.view, f.clip, fill);
  fill.finish();
}

// The triangles drawn in each colour of SVG_options::color_by_quality, by
// their index in the Mesh_domain_view.
template <class CDT>
std::vector<std::vector<std::size_t> > svg_quality_bins(const Mesh_domain_view<CDT>& m,
                                                        const Svg_frame& f)
{
  typedef std::array<double, 2> P;
  static const double upper[7] = {0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 2.};
  const std::vector<P>& pts = m.points;
  std::vector<std::vector<std::size_t> > bins(7);
  for(std::size_t fi = 0; fi < m.triangles.size(); ++fi) {
    const P& a = pts[m.triangles[fi][0]];
    const P& b = pts[m.triangles[fi][1]];
    const P& c = pts[m.triangles[fi][2]];
    // drawn unclipped: only triangles within the clip box, all of whose
    // pixel coordinates are then small; the plain fill shows under others
    if(svg_outcode(a, f.clip) | svg_outcode(b, f.clip) | svg_outcode(c, f.clip))
      continue;
    if(svg_outcode(a, f.view) & svg_outcode(b, f.view) & svg_outcode(c, f.view))
      continue;
    const double rr = (std::max)(CGAL::Advancing_front_mesh_2::internal::radius_ratio(a[0], a[1], b[0], b[1], c[0], c[1]),
                                 CGAL::Advancing_front_mesh_2::internal::radius_ratio(a[0], a[1], c[0], c[1], b[0], b[1]));
    std::size_t k = 0;
    while(rr >= upper[k] && k < 6) ++k;
    bins[k].push_back(fi);
  }
  return bins;
}

template <class CDT>
void svg_write_quality_fill(std::ostream& os, const Mesh_domain_view<CDT>& m,
                            const Svg_frame& f)
{
  static const char* const colour[7] = {"#7f0000", "#e31a1c", "#fd8d3c", "#fed976",
                                        "#c7e9a0", "#74c476", "#d4e8f5"};
  const std::vector<std::vector<std::size_t> > bins = svg_quality_bins(m, f);
  for(std::size_t k = 0; k < 7; ++k) {
    // split into elements of bounded length (each triangle is a closed
    // subpath of its own), which viewers need for large meshes
    Svg_path_writer fill(os, std::string("fill=\"") + colour[k] + "\" stroke=\"none\"",
                         f.view.xmin, f.view.ymax, f.scale, f.decimals, true);
    for(std::size_t fi : bins[k]) {
      fill.move_to(m.points[m.triangles[fi][0]]);
      fill.line_to(m.points[m.triangles[fi][1]]);
      fill.line_to(m.points[m.triangles[fi][2]]);
      fill.close();
    }
    fill.finish();
  }
}

// The key to the quality colours, in the top left corner above the mesh: a
// white box with one swatch and range per colour, scaled with the picture.
inline void svg_write_quality_legend(std::ostream& os, const Svg_frame& f)
{
  static const char* const colour[7] = {"#7f0000", "#e31a1c", "#fd8d3c", "#fed976",
                                        "#c7e9a0", "#74c476", "#d4e8f5"};
  static const char* const range[7] = {"below 0.3", "0.3 - 0.5", "0.5 - 0.7", "0.7 - 0.8",
                                       "0.8 - 0.9", "0.9 - 0.95", "0.95 - 1"};
  const double u = (std::max)(8., f.width / 70); // one text line
  os << "<g font-family=\"sans-serif\" font-size=\"" << svg_number(0.8 * u) << "\">\n"
     << "<rect x=\"" << svg_number(0.5 * u) << "\" y=\"" << svg_number(0.5 * u) << "\" width=\"" << svg_number(7.5 * u)
     << "\" height=\"" << svg_number(9.2 * u) << "\" fill=\"#ffffff\" fill-opacity=\"0.9\" stroke=\"#000000\" "
     << "stroke-width=\"" << svg_number(0.05 * u) << "\"/>\n"
     << "<text x=\"" << svg_number(u) << "\" y=\"" << svg_number(1.6 * u) << "\">radius ratio 2r/R</text>\n";
  for(int k = 6; k >= 0; --k) {
    const double y = (2.2 + (6 - k)) * u;
    os << "<rect x=\"" << svg_number(u) << "\" y=\"" << svg_number(y) << "\" width=\"" << svg_number(1.4 * u)
       << "\" height=\"" << svg_number(0.8 * u) << "\" fill=\"" << colour[k] << "\" stroke=\"#000000\" stroke-width=\""
       << svg_number(0.03 * u) << "\"/>\n"
       << "<text x=\"" << svg_number(2.8 * u) << "\" y=\"" << svg_number(y + 0.75 * u) << "\">" << range[k]
       << "</text>\n";
  }
  os << "</g>\n";
}

inline void svg_write_edge_layer(std::ostream& os,
                                 const std::vector<std::array<double, 2> >& pts,
                                 const std::vector<std::array<std::size_t, 2> >& edges,
                                 const char* colour, double stroke_width, const Svg_frame& f)
{
  Svg_path_writer layer(os, std::string("fill=\"none\" stroke=\"") + colour + "\" stroke-width=\"" +
                              svg_number(stroke_width) +
                              "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"",
                        f.view.xmin, f.view.ymax, f.scale, f.decimals, true);
  svg_draw_edges(pts, edges, f.view, f.clip, layer);
  layer.finish();
}

} // namespace internal

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
  internal::svg_check_options(options);

  internal::Mesh_domain_view<CDT> m;
  internal::mesh_collect_domain(cdt, m);
  const internal::Svg_edge_layers edges = internal::svg_edge_layers(cdt, m);
  const internal::Svg_frame frame = internal::svg_frame(options, m.points);
  const double mean_px = internal::svg_mean_edge_pixels(m.points, edges, frame);
  const double thin_w = options.stroke_scale * (std::max)(0.05, (std::min)(0.6, 0.08 * mean_px));
  const double thick_w = options.stroke_scale * 1.5;

  // formatting and locale only: restoring the error state would hide a failed write
  boost::io::ios_base_all_saver format_saver(os);
  boost::io::ios_locale_saver locale_saver(os);
  os.imbue(std::locale::classic());

  internal::svg_write_header(os, frame, options.title);
  internal::svg_write_domain_fill(os, m.points, edges.boundary, frame);
  if(options.color_by_quality)
    internal::svg_write_quality_fill(os, m, frame);
  internal::svg_write_edge_layer(os, m.points, edges.thin, "#6f88a6", thin_w, frame);
  internal::svg_write_edge_layer(os, m.points, edges.thick, "#000000", thick_w, frame);
  if(options.color_by_quality)
    internal::svg_write_quality_legend(os, frame);
  os << "</svg>\n";
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_SVG_H
