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

// The header users include for the mesh writers: write_mesh() below, and
// through the headers it includes write_OFF(), write_triangle_node_ele(),
// write_gmsh_msh() (write_mesh_formats.h) and write_SVG() with SVG_options
// (write_SVG.h). Mesh_quality.h is not used here; it stays because this
// header has always provided it.
#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh_formats.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_SVG.h>

#include <CGAL/IO/io.h>
#include <CGAL/IO/write_VTU.h>

#include <boost/io/ios_state.hpp>

#include <ostream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

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
