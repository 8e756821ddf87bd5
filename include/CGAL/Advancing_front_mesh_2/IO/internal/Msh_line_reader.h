// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_MSH_LINE_READER_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_MSH_LINE_READER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Poly_line_reader.h>

#include <charconv>
#include <cmath>
#include <cstddef>
#include <istream>
#include <limits>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {
namespace internal {

// Lines of a .msh file are short, except those of $Entities that list the
// bounding curves of a surface; the bound only stops binary garbage without
// a newline from being buffered whole.
constexpr std::size_t msh_max_line_length = std::size_t(1) << 24;

// Reads a Gmsh .msh file line by line: the format has no comments, blank
// lines are skipped, and a line keeps its raw text for the quoted names of
// $PhysicalNames. Knows the file name and the current line so that every
// error can say where it is.
class Msh_line_reader
{
public:
  Msh_line_reader(std::istream& in, const std::string& file) : buf_(in.rdbuf()), file_(file)
  {
    // as Poly_line_reader: through the stream buffer, the stream's state untouched
    if(buf_ == nullptr || in.fail()) throw Poly_read_error(file_, 0, "cannot read from the stream");
  }

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_no_; }

  /// Advances to the next line that is not blank; false at the end of the input.
  bool next()
  {
    while(read_line()) {
      split();
      if(!tokens_.empty()) return true;
    }
    tokens_.clear();
    return false;
  }

  std::size_t size() const { return tokens_.size(); }

  std::string token(std::size_t i) const
  {
    return line_.substr(tokens_[i].first, tokens_[i].second - tokens_[i].first);
  }

  /// the text of the line after token `i`, without surrounding blanks
  std::string rest_after(std::size_t i) const
  {
    std::size_t b = tokens_[i].second, e = line_.size();
    while(b < e && is_blank(line_[b])) ++b;
    while(e > b && is_blank(line_[e - 1])) --e;
    return line_.substr(b, e - b);
  }

  /// whether the line is a section line (`$Name` or `$EndName`)
  bool at_section() const { return !tokens_.empty() && line_[tokens_[0].first] == '$'; }

  [[noreturn]] void fail(const std::string& problem) const { throw Poly_read_error(file_, line_no_, problem); }

  long long integer(std::size_t i, const char* what) const
  {
    const std::string t = token(i);
    long long v = 0;
    const Poly_integer_status status = poly_parse_integer(t, v);
    if(status == POLY_INTEGER_OUT_OF_RANGE) fail(std::string(what) + " " + poly_quote(t) + " is out of range");
    if(status != POLY_INTEGER_OK) {
      double d = 0;
      if(poly_parse_real(t, d)) fail(std::string(what) + " " + poly_quote(t) + " is not an integer");
      fail(std::string(what) + " " + poly_quote(t) + " is not a number");
    }
    return v;
  }

  // An integer between lo and hi.
  long long integer_in(std::size_t i, const char* what, long long lo, long long hi) const
  {
    const long long v = integer(i, what);
    if(v < lo || v > hi)
      fail(std::string(what) + " " + std::to_string(v) + " is out of range (" + std::to_string(lo) + " to " +
           std::to_string(hi) + ")");
    return v;
  }

  std::size_t count(std::size_t i, const char* what) const
  {
    const long long v = integer(i, what);
    if(v < 0) fail(std::string(what) + " " + std::to_string(v) + " is negative");
    if(v > poly_max_count)
      fail(std::string(what) + " " + std::to_string(v) + " is too large (at most " + std::to_string(poly_max_count) +
           ")");
    return static_cast<std::size_t>(v);
  }

  // A node or element tag: a positive integer.
  long long tag(std::size_t i, const char* what) const
  {
    const long long v = integer(i, what);
    if(v <= 0) fail(std::string(what) + " " + std::to_string(v) + " is not positive");
    return v;
  }

  // A physical tag, which Gmsh keeps in an int.
  int physical(std::size_t i) const
  {
    return static_cast<int>(integer_in(i, "physical tag", (std::numeric_limits<int>::min)(),
                                       (std::numeric_limits<int>::max)()));
  }

  double real(std::size_t i, const char* what) const
  {
    const std::string t = token(i);
    double v = 0;
    if(!poly_parse_real(t, v)) fail(std::string(what) + " " + poly_quote(t) + " is not a number");
    if(!std::isfinite(v)) fail(std::string(what) + " " + poly_quote(t) + " is not finite");
    return v;
  }

  void expect_size(std::size_t n, const std::string& what) const
  {
    if(tokens_.size() != n)
      fail(what + " has " + std::to_string(tokens_.size()) + " value" + (tokens_.size() == 1 ? "" : "s") +
           ", expected " + std::to_string(n));
  }

  // Advances to a data line of section `section`, described by `expected`
  // for the messages: neither the end of the file nor a section line may
  // come first.
  void data_line(const std::string& section, const std::string& expected)
  {
    if(!next()) fail("file ends in section " + section + ", expected " + expected);
    if(at_section()) fail("expected " + expected + ", found " + poly_quote(token(0)));
  }

  // Advances to the line closing `section`, which must come now.
  void end_of_section(const std::string& section, const std::string& after)
  {
    const std::string end = "$End" + section.substr(1);
    if(!next()) fail("file ends in section " + section + ", expected " + end);
    if(size() != 1 || token(0) != end)
      fail("expected " + end + " after " + after + ", found " + poly_quote(token(0)));
  }

private:
  // Reads one physical line (the format has no comments); false at the end of input.
  bool read_line()
  {
    bool too_long = false;
    const bool got = poly_read_physical_line(buf_, msh_max_line_length, '\0', line_, line_no_, at_end_, too_long);
    if(too_long)
      fail("line is longer than " + std::to_string(msh_max_line_length) + " characters");
    return got;
  }

  static bool is_blank(char c) { return poly_is_blank(c); }

  void split() { poly_split_tokens(line_, tokens_); }

  std::streambuf* buf_;
  std::string file_;
  std::string line_;
  std::vector<std::pair<std::size_t, std::size_t> > tokens_;
  std::size_t line_no_ = 0;
  bool at_end_ = false;
};

} // namespace internal
} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_MSH_LINE_READER_H
