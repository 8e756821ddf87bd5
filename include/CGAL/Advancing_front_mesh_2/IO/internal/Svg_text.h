// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_TEXT_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_TEXT_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <locale>
#include <sstream>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// The title is the user's text: it must not be able to break the XML.
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

// The numbers of the header and of the stroke widths: seven digits are far
// below what can be seen, and the classic locale keeps a global one from
// writing a decimal comma.
inline std::string svg_number(double v)
{
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(7);
  os << v;
  return os.str();
}

} // namespace internal

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_TEXT_H
