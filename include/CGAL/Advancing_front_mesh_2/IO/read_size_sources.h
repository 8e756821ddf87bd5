// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_READ_SIZE_SOURCES_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_READ_SIZE_SOURCES_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>

#include <array>
#include <fstream>
#include <istream>
#include <string>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads point sources of a size field (see `Poisson_sizing_field_2`): one
source per line, `x y h` (position and target edge length), separated by
blanks; `#` starts a comment that runs to the end of the line; blank lines
are skipped. Every value must be a complete finite number, and `h` positive.

\returns the sources as `{x, y, h}` in file order.
\throws Poly_read_error (the package's input-file error, with the file name
and 1-based line number) on any problem; an empty file is not an error.
*/
inline std::vector<std::array<double, 3> > read_size_sources(std::istream& in, const std::string& file_name)
{
  internal::Poly_line_reader r(in, file_name);
  std::vector<std::array<double, 3> > sources;
  while(r.next()) {
    r.expect_size(3, "a source line (x y h)");
    const double x = r.real(0, "x coordinate");
    const double y = r.real(1, "y coordinate");
    const double h = r.real(2, "size");
    if(!(h > 0))
      r.fail("size " + internal::poly_quote(r.token(2)) + " is not positive");
    sources.push_back({{x, y, h}});
  }
  return sources;
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads the size sources file `file_name`; see
`read_size_sources(std::istream&, const std::string&)`.

\throws Poly_read_error with the message "cannot open file" when the file
cannot be opened, and on any problem with its content
*/
inline std::vector<std::array<double, 3> > read_size_sources(const std::string& file_name)
{
  std::ifstream in(file_name.c_str(), std::ios::in | std::ios::binary);
  if(!in)
    throw Poly_read_error(file_name, 0, "cannot open file");
  return read_size_sources(in, file_name);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_READ_SIZE_SOURCES_H
