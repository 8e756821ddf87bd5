// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_POLY_READ_ERROR_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_POLY_READ_ERROR_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

/*!
\ingroup PkgAdvancingFrontMesh2IO

Thrown by `read_poly()` for any problem with its input: a file that cannot
be opened, a missing or truncated section, a malformed or out-of-range value;
and by `insert_poly()` for a graph that cannot be meshed as it stands
(crossing or overlapping segments, a zero-length segment, a misplaced hole
seed, an open boundary, nothing left to mesh).

The position is kept apart from the message so that a caller (an editor
integration, a test) can point at the offending line without parsing
`what()`, which is formatted as `FILE:LINE: problem`, or `FILE: problem`
when no line applies (`line() == 0`), like compiler diagnostics.
*/
class Poly_read_error : public std::runtime_error
{
public:
  /*!
  \param file name of the file in which the problem was found
  \param line 1-based line number, or 0 when the problem concerns no line
  \param problem description of the problem, without the position
  */
  Poly_read_error(const std::string& file, std::size_t line,
                  const std::string& problem)
    : std::runtime_error(format(file, line, problem)),
      file_(file), line_(line), problem_(problem)
  {}

  /// name of the file in which the problem was found
  const std::string& file() const noexcept { return file_; }

  /// 1-based line number of the problem, 0 when no line applies
  std::size_t line() const noexcept { return line_; }

  /// the problem alone, without file and line
  const std::string& problem() const noexcept { return problem_; }

private:
  static std::string format(const std::string& file, std::size_t line,
                            const std::string& problem)
  {
    std::string s = file;
    if(line != 0) {
      s += ':';
      s += std::to_string(line);
    }
    s += ": ";
    s += problem;
    return s;
  }

  std::string file_;
  std::size_t line_;
  std::string problem_;
};

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_POLY_READ_ERROR_H
