// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_QUALITY_HISTOGRAM_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_QUALITY_HISTOGRAM_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>

#include <boost/io/ios_state.hpp>

#include <algorithm>
#include <cstddef>
#include <iomanip>
#include <locale>
#include <ostream>
#include <sstream>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes the radius ratio histogram of `quality` (20 bins of width 0.05, as a
share of the triangles) and the angle histogram (18 bins of 10 degrees, as a
share of the angles) as one SVG picture, with the main figures in the
caption.
*/
inline void write_quality_histogram_SVG(std::ostream& os, const Mesh_quality& quality, const std::string& title = "")
{
  // formatting and locale only: restoring the error state would hide a failed write
  boost::io::ios_base_all_saver format_saver(os);
  boost::io::ios_locale_saver locale_saver(os);
  os.imbue(std::locale::classic());
  os << std::fixed << std::setprecision(1);
  const double panel_w = 420, panel_h = 220, left = 50, top = 40, gap = 70;
  const double width = 2 * panel_w + gap + 2 * left, height = top + panel_h + 70;
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << width << "\" height=\"" << height
     << "\" font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  std::ostringstream caption;
  caption.imbue(std::locale::classic());
  caption << std::setprecision(4) << quality.number_of_triangles << " triangles; radius ratio mean "
          << quality.mean_radius_ratio << ", min " << quality.min_radius_ratio << ", "
          << 100 * quality.share_above_0_9 << "% above 0.9; angles " << quality.min_angle_degrees << " to "
          << quality.max_angle_degrees << " degrees";
  const std::string escaped = internal::svg_escape(title.empty() ? std::string("Mesh quality") : title);
  os << "<text x=\"" << left << "\" y=\"20\" font-size=\"14\">" << escaped
     << "</text>\n<text x=\"" << left << "\" y=\"" << height - 12 << "\">" << caption.str() << "</text>\n";

  auto panel = [&](double x0, const std::size_t* counts, std::size_t n, double total, const char* colour,
                   const char* label, double axis_max, int ticks) {
    double largest = 0;
    for(std::size_t k = 0; k < n; ++k) largest = (std::max)(largest, double(counts[k]) / total);
    const double y_max = largest > 0 ? largest : 1;
    const double bar = panel_w / double(n);
    os << "<rect x=\"" << x0 << "\" y=\"" << top << "\" width=\"" << panel_w << "\" height=\"" << panel_h
       << "\" fill=\"none\" stroke=\"#999\"/>\n";
    for(std::size_t k = 0; k < n; ++k) {
      const double hgt = panel_h * (double(counts[k]) / total) / y_max;
      os << "<rect x=\"" << x0 + bar * double(k) + 1 << "\" y=\"" << top + panel_h - hgt << "\" width=\""
         << bar - 2 << "\" height=\"" << hgt << "\" fill=\"" << colour << "\"/>\n";
    }
    for(int t = 0; t <= ticks; ++t) {
      const double x = x0 + panel_w * t / ticks;
      os << "<text x=\"" << x << "\" y=\"" << top + panel_h + 16 << "\" text-anchor=\"middle\">"
         << std::setprecision(axis_max > 10 ? 0 : 1) << axis_max * t / ticks << "</text>\n";
    }
    os << std::setprecision(1) << "<text x=\"" << x0 + panel_w / 2 << "\" y=\"" << top + panel_h + 34
       << "\" text-anchor=\"middle\">" << label << "</text>\n<text x=\"" << x0 + 4 << "\" y=\"" << top + 14
       << "\">" << 100 * y_max << "%</text>\n";
  };
  const double triangles = (std::max)(1., double(quality.number_of_triangles));
  panel(left, quality.radius_ratio_histogram.data(), quality.radius_ratio_histogram.size(), triangles, "#4a7fb5",
        "radius ratio 2r/R (share of triangles)", 1., 10);
  panel(left + panel_w + gap, quality.angle_histogram.data(), quality.angle_histogram.size(), 3 * triangles,
        "#b5804a", "angle in degrees (share of angles)", 180., 6);
  os << "</svg>\n";
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_WRITE_QUALITY_HISTOGRAM_H
