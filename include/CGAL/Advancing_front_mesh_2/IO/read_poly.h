// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_READ_POLY_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_READ_POLY_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_data.h>

#include <boost/io/ios_state.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <clocale>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <ios>
#include <istream>
#include <limits>
#include <locale>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <utility>
#include <vector>

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

namespace internal {

// Triangle stores counts in `int`, so a larger count cannot come from a
// genuine file; rejecting it early also keeps index arithmetic far from
// overflow.
constexpr long long poly_max_count = 2147483647LL;

// No real file has that many attributes per vertex; the bound keeps the
// expected token count of a vertex line from overflowing.
constexpr long long poly_max_attributes = 100000LL;

// Data lines are short; the bound stops binary garbage without a newline from
// being buffered whole. Comments are skipped while reading, so they do not
// count.
constexpr std::size_t poly_max_line_length = std::size_t(1) << 20;

// Quotes a token for an error message: the token may be binary garbage, which
// must neither flood the message nor put control bytes in a terminal.
inline std::string poly_quote(const std::string& token)
{
  static const char hex[] = "0123456789abcdef";
  const std::size_t max_shown = 40;
  std::string s = "'";
  for(std::size_t i = 0; i < token.size() && i < max_shown; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if(c >= 0x20 && c < 0x7f && c != '\\') {
      s += static_cast<char>(c);
    } else {
      s += "\\x";
      s += hex[c >> 4];
      s += hex[c & 0xf];
    }
  }
  if(token.size() > max_shown)
    s += "...";
  s += "'";
  return s;
}

inline bool poly_is_ascii_digit(char c) { return c >= '0' && c <= '9'; }

inline bool poly_is_ascii_letter(char c)
{
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}

enum Poly_integer_status { POLY_INTEGER_OK, POLY_NOT_INTEGER, POLY_INTEGER_OUT_OF_RANGE };

// The whole token must be an integer: strtoll alone would accept "12abc" as
// 12 and skip leading blanks of whatever the current locale calls blank.
inline Poly_integer_status poly_parse_integer(const std::string& token, long long& value)
{
  if(token.empty())
    return POLY_NOT_INTEGER;
  const char c0 = token[0];
  if(!(poly_is_ascii_digit(c0) || c0 == '+' || c0 == '-'))
    return POLY_NOT_INTEGER;
  errno = 0;
  char* end = nullptr;
  const long long v = std::strtoll(token.c_str(), &end, 10);
  if(end != token.c_str() + token.size())
    return POLY_NOT_INTEGER;
  if(errno == ERANGE)
    return POLY_INTEGER_OUT_OF_RANGE;
  value = v;
  return POLY_INTEGER_OK;
}

// The whole token must be a number. strtod follows the global C locale's
// decimal point while the format always uses '.', so the token is translated
// first; otherwise a program that called setlocale() would misread "0.5".
inline bool poly_parse_real(const std::string& token, double& value)
{
  if(token.empty())
    return false;
  const char c0 = token[0];
  if(!(poly_is_ascii_digit(c0) || c0 == '+' || c0 == '-' || c0 == '.' ||
       poly_is_ascii_letter(c0)))
    return false;

  std::string s = token;
  const std::lconv* lc = std::localeconv();
  const char* dp = (lc != nullptr) ? lc->decimal_point : nullptr;
  if(dp != nullptr && dp[0] != '\0' && std::strcmp(dp, ".") != 0) {
    // A locale decimal point inside the token is not part of the format.
    if(s.find(dp) != std::string::npos)
      return false;
    std::string t;
    t.reserve(s.size() + 4);
    for(char c : s) {
      if(c == '.')
        t += dp;
      else
        t += c;
    }
    s.swap(t);
  }

  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if(end != s.c_str() + s.size())
    return false;
  // Underflow to a tiny or zero value is an acceptable rounding; overflow
  // yields an infinity, which the callers reject as non-finite.
  value = v;
  return true;
}

// Reads a Triangle file line by line, dropping comments and blank lines, and
// knows the file name and current line so that every parse error can say
// where it is.
class Poly_line_reader
{
public:
  Poly_line_reader(std::istream& in, const std::string& file)
    : buf_(in.rdbuf()), file_(file)
  {
    // Reading through the stream buffer avoids a sentry per character, and
    // leaves the stream's state alone: setting eofbit could throw from a
    // stream with exceptions enabled. A stream already in a failed state must
    // not be read as if it were fine, though.
    if(buf_ == nullptr || in.fail())
      throw Poly_read_error(file_, 0, "cannot read from the stream");
  }

  const std::string& file() const { return file_; }

  /// line number of the current line, or of the last line after the end
  std::size_t line() const { return line_no_; }

  /// Advances to the next line holding data; false at the end of the input.
  bool next()
  {
    while(read_line()) {
      split();
      if(!tokens_.empty())
        return true;
    }
    tokens_.clear();
    return false;
  }

  std::size_t size() const { return tokens_.size(); }

  std::string token(std::size_t i) const
  {
    return line_.substr(tokens_[i].first, tokens_[i].second - tokens_[i].first);
  }

  [[noreturn]] void fail(const std::string& problem) const
  {
    throw Poly_read_error(file_, line_no_, problem);
  }

  long long integer(std::size_t i, const char* what) const
  {
    const std::string t = token(i);
    long long v = 0;
    const Poly_integer_status status = poly_parse_integer(t, v);
    if(status == POLY_INTEGER_OUT_OF_RANGE)
      fail(std::string(what) + " " + poly_quote(t) + " is out of range");
    if(status != POLY_INTEGER_OK) {
      double d = 0;
      if(poly_parse_real(t, d))
        fail(std::string(what) + " " + poly_quote(t) + " is not an integer");
      fail(poly_quote(t) + " is not a number");
    }
    return v;
  }

  double real(std::size_t i, const char* what) const
  {
    const std::string t = token(i);
    double v = 0;
    if(!poly_parse_real(t, v))
      fail(poly_quote(t) + " is not a number");
    if(!std::isfinite(v))
      fail(std::string(what) + " " + poly_quote(t) + " is not finite");
    return v;
  }

  std::size_t count(std::size_t i, const char* what) const
  {
    const long long v = integer(i, what);
    if(v < 0)
      fail(std::string(what) + " " + std::to_string(v) + " is negative");
    if(v > poly_max_count)
      fail(std::string(what) + " " + std::to_string(v) +
           " is too large (at most " + std::to_string(poly_max_count) + ")");
    return static_cast<std::size_t>(v);
  }

  int marker(std::size_t i) const
  {
    const long long v = integer(i, "boundary marker");
    // Triangle keeps markers in an int.
    if(v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      fail("boundary marker " + std::to_string(v) + " does not fit in an int");
    return static_cast<int>(v);
  }

  void expect_size(std::size_t n, const std::string& what) const
  {
    if(tokens_.size() != n)
      fail(what + " has " + std::to_string(tokens_.size()) + " value" +
           (tokens_.size() == 1 ? "" : "s") + ", expected " + std::to_string(n));
  }

private:
  // Reads one physical line without its comment; false at the end of input.
  bool read_line()
  {
    typedef std::char_traits<char> Traits;
    line_.clear();
    if(at_end_)
      return false;
    if(Traits::eq_int_type(buf_->sgetc(), Traits::eof())) {
      at_end_ = true;
      return false;
    }
    ++line_no_;
    bool in_comment = false;
    for(;;) {
      const Traits::int_type c = buf_->sbumpc();
      if(Traits::eq_int_type(c, Traits::eof())) {
        at_end_ = true;
        break;
      }
      const char ch = Traits::to_char_type(c);
      if(ch == '\n')
        break;
      if(in_comment)
        continue;
      if(ch == '#') {
        in_comment = true;
        continue;
      }
      if(line_.size() >= poly_max_line_length)
        fail("line is longer than " + std::to_string(poly_max_line_length) +
             " characters");
      line_ += ch;
    }
    return true;
  }

  static bool is_blank(char c)
  {
    // '\r' is blank so that files written on Windows read the same.
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }

  void split()
  {
    tokens_.clear();
    std::size_t i = 0;
    const std::size_t n = line_.size();
    while(i < n) {
      while(i < n && is_blank(line_[i]))
        ++i;
      if(i == n)
        break;
      const std::size_t b = i;
      while(i < n && !is_blank(line_[i]))
        ++i;
      tokens_.push_back(std::make_pair(b, i));
    }
  }

  std::streambuf* buf_;
  std::string file_;
  std::string line_;
  std::vector<std::pair<std::size_t, std::size_t> > tokens_;
  std::size_t line_no_ = 0;
  bool at_end_ = false;
};

struct Poly_node_header
{
  std::size_t vertices;
  std::size_t attributes;
  std::size_t markers;
};

inline std::string poly_count_phrase(std::size_t n, const char* singular,
                                     const char* plural)
{
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

// Shared by .poly and .node files, which start with the same header line.
inline Poly_node_header poly_read_node_header(Poly_line_reader& r)
{
  if(!r.next())
    r.fail("file holds no data, expected the header "
           "'<#vertices> <dimension> <#attributes> <#boundary markers>'");
  r.expect_size(4, "the header '<#vertices> <dimension> <#attributes> "
                   "<#boundary markers>'");
  Poly_node_header h;
  h.vertices = r.count(0, "vertex count");
  const long long dim = r.integer(1, "dimension");
  if(dim != 2)
    r.fail("dimension must be 2, got " + std::to_string(dim));
  const long long attributes = r.integer(2, "attribute count");
  if(attributes < 0)
    r.fail("attribute count " + std::to_string(attributes) + " is negative");
  if(attributes > poly_max_attributes)
    r.fail("attribute count " + std::to_string(attributes) +
           " is too large (at most " + std::to_string(poly_max_attributes) + ")");
  h.attributes = static_cast<std::size_t>(attributes);
  const long long markers = r.integer(3, "boundary marker count");
  if(markers != 0 && markers != 1)
    r.fail("number of boundary markers must be 0 or 1, got " +
           std::to_string(markers));
  h.markers = static_cast<std::size_t>(markers);
  return h;
}

// Checks the id in the first column. Triangle lets the first id choose
// between 0- and 1-based numbering; requiring the others to follow in order
// catches lines that were lost, duplicated or shuffled.
inline void poly_check_id(Poly_line_reader& r, const char* what,
                          std::size_t index, long long& base)
{
  const long long id = r.integer(0, (std::string(what) + " id").c_str());
  if(index == 0) {
    if(id != 0 && id != 1)
      r.fail(std::string("first ") + what + " id must be 0 or 1, got " +
             std::to_string(id));
    base = id;
  } else if(id != base + static_cast<long long>(index)) {
    r.fail(std::string(what) + " id " + std::to_string(id) +
           " is out of order, expected " +
           std::to_string(base + static_cast<long long>(index)));
  }
}

// Reads the vertex lines announced by `h`; returns the first vertex id, which
// segment endpoints are numbered from.
inline long long poly_read_vertices(Poly_line_reader& r,
                                    const Poly_node_header& h,
                                    Poly_data& data)
{
  const std::size_t n_tokens = 3 + h.attributes + h.markers;
  const std::string line_desc =
    "vertex line (id, x, y" +
    (h.attributes == 0 ? std::string() : ", " + poly_count_phrase(h.attributes, "attribute", "attributes")) +
    (h.markers == 0 ? std::string() : ", 1 boundary marker") + ")";
  long long base = 0;
  data.points.reserve(data.points.size() + (std::min)(h.vertices, std::size_t(1) << 20));
  for(std::size_t i = 0; i < h.vertices; ++i) {
    if(!r.next())
      r.fail("expected " + poly_count_phrase(h.vertices, "vertex", "vertices") +
             ", file ends after " + std::to_string(i));
    r.expect_size(n_tokens, line_desc);
    poly_check_id(r, "vertex", i, base);
    const double x = r.real(1, "coordinate");
    const double y = r.real(2, "coordinate");
    for(std::size_t a = 0; a < h.attributes; ++a)
      r.real(3 + a, "attribute");
    if(h.markers != 0)
      r.marker(3 + h.attributes);
    data.points.push_back(std::array<double, 2>{{x, y}});
    data.origin.point_lines.push_back(r.line());
  }
  data.origin.point_file = r.file();
  data.origin.first_point_id = base;
  return base;
}

inline std::string poly_node_file_name(const std::string& poly_file)
{
  const std::string ext = ".poly";
  if(poly_file.size() >= ext.size() &&
     poly_file.compare(poly_file.size() - ext.size(), ext.size(), ext) == 0)
    return poly_file.substr(0, poly_file.size() - ext.size()) + ".node";
  return poly_file + ".node";
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads a planar straight-line graph in Triangle's `.poly` format
(https://www.cs.cmu.edu/~quake/triangle.poly.html) from `in`.

The reader is strict on purpose: a mesher fed a silently misread boundary
produces a plausible but wrong mesh, which is much harder to trace back than
an error naming the faulty line. Accepted input:
- `#` starts a comment anywhere on a line; blank lines are skipped;
- a header `<#vertices> <dimension> <#attributes> <#boundary markers>` with
  dimension 2 and 0 or 1 markers, followed by exactly that many vertex lines
  `id x y [attributes...] [marker]`. Ids start at 0 or 1 (the first one
  decides, as in Triangle) and are consecutive;
- a segment header `<#segments> <#boundary markers>` and the segment lines
  `id v1 v2 [marker]`, whose endpoints are vertex ids;
- a hole header `<#holes>` and the hole lines `id x y`;
- optionally a region header `<#regions>` and the region lines
  `id x y attribute [maximum area]`, which are checked and then ignored;
- nothing but comments and blank lines after the last section.

Every line must hold exactly the number of values its section calls for:
unlike Triangle, the reader does not default omitted header fields, since a
short line is more often damage than shorthand. Every value must be a
complete number (integers where ids, counts and markers are expected), every
coordinate, attribute and area finite. Segment endpoints must be existing
vertices and distinct. Segment, hole and region ids follow the same rule as
vertex ids (Triangle ignores them, but ids out of order betray a damaged
file). Counts are at most 2147483647 (Triangle's `int`), attributes per
vertex at most 100000, and a line without its comment at most 1 MiB, so that
no input makes the reader allocate without bound. The input is read to its
end, to check that nothing follows the last section.

A header announcing 0 vertices means, as in Triangle, that the vertices are
in a `.node` file with the same base name: `file_name` with its `.poly`
extension replaced by `.node` (or with `.node` appended if it has none). That
file is read with the same rules and its errors name it and its own lines.

\param in the stream to read; it is read through its stream buffer, so its
formatting flags and locale do not matter
\param file_name the name used in error messages and to locate the `.node`
file

\returns the points, the segments as 0-based indices into the points, and
the hole seeds

\throws Poly_read_error on any problem with the input
*/
inline Poly_data read_poly(std::istream& in, const std::string& file_name)
{
  internal::Poly_line_reader r(in, file_name);
  Poly_data data;
  data.origin.file = file_name;

  const internal::Poly_node_header header = internal::poly_read_node_header(r);
  long long vertex_base = 0;
  if(header.vertices != 0) {
    vertex_base = internal::poly_read_vertices(r, header, data);
  } else {
    const std::string node_name = internal::poly_node_file_name(file_name);
    std::ifstream node_in(node_name.c_str(), std::ios::in | std::ios::binary);
    if(!node_in)
      throw Poly_read_error(node_name, 0,
                            "cannot open file (needed because " + file_name +
                            ":" + std::to_string(r.line()) +
                            " announces 0 vertices, meaning they are in a .node file)");
    internal::Poly_line_reader nr(node_in, node_name);
    const internal::Poly_node_header node_header = internal::poly_read_node_header(nr);
    vertex_base = internal::poly_read_vertices(nr, node_header, data);
    if(nr.next())
      nr.fail("unexpected content after the last vertex");
  }
  const std::size_t n_vertices = data.points.size();

  // Segments.
  if(!r.next())
    r.fail("expected the segment header '<#segments> <#boundary markers>', "
           "file ends");
  r.expect_size(2, "the segment header '<#segments> <#boundary markers>'");
  const std::size_t n_segments = r.count(0, "segment count");
  const long long segment_markers = r.integer(1, "boundary marker count");
  if(segment_markers != 0 && segment_markers != 1)
    r.fail("number of boundary markers must be 0 or 1, got " +
           std::to_string(segment_markers));
  const std::size_t seg_tokens = 3 + static_cast<std::size_t>(segment_markers);
  const std::string seg_desc = segment_markers == 0
                               ? "segment line (id, v1, v2)"
                               : "segment line (id, v1, v2, boundary marker)";
  data.segments.reserve((std::min)(n_segments, std::size_t(1) << 20));
  long long segment_base = 0;
  for(std::size_t i = 0; i < n_segments; ++i) {
    if(!r.next())
      r.fail("expected " + internal::poly_count_phrase(n_segments, "segment", "segments") +
             ", file ends after " + std::to_string(i));
    r.expect_size(seg_tokens, seg_desc);
    internal::poly_check_id(r, "segment", i, segment_base);
    std::array<std::size_t, 2> seg;
    for(int k = 0; k < 2; ++k) {
      const long long v = r.integer(1 + k, "segment endpoint");
      if(n_vertices == 0)
        r.fail("segment endpoint " + std::to_string(v) +
               " is out of range (there are no vertices)");
      // Written so that no subtraction can overflow for extreme values.
      if(v < vertex_base ||
         v > vertex_base + static_cast<long long>(n_vertices) - 1)
        r.fail("segment endpoint " + std::to_string(v) +
               " is out of range (vertex ids are " + std::to_string(vertex_base) +
               ".." + std::to_string(vertex_base + static_cast<long long>(n_vertices) - 1) +
               ")");
      seg[k] = static_cast<std::size_t>(v - vertex_base);
    }
    if(seg[0] == seg[1])
      r.fail("segment joins vertex " +
             std::to_string(static_cast<long long>(seg[0]) + vertex_base) +
             " to itself");
    if(segment_markers != 0)
      r.marker(3);
    data.segments.push_back(seg);
    data.origin.segment_lines.push_back(r.line());
  }
  data.origin.first_segment_id = segment_base;

  // Holes.
  if(!r.next())
    r.fail("expected the hole header '<#holes>', file ends");
  r.expect_size(1, "the hole header '<#holes>'");
  const std::size_t n_holes = r.count(0, "hole count");
  data.holes.reserve((std::min)(n_holes, std::size_t(1) << 20));
  long long hole_base = 0;
  for(std::size_t i = 0; i < n_holes; ++i) {
    if(!r.next())
      r.fail("expected " + internal::poly_count_phrase(n_holes, "hole", "holes") +
             ", file ends after " + std::to_string(i));
    r.expect_size(3, "hole line (id, x, y)");
    internal::poly_check_id(r, "hole", i, hole_base);
    const double x = r.real(1, "coordinate");
    const double y = r.real(2, "coordinate");
    data.holes.push_back(std::array<double, 2>{{x, y}});
    data.origin.hole_lines.push_back(r.line());
  }
  data.origin.first_hole_id = hole_base;

  // Regional attributes and area constraints belong to Triangle's own
  // refinement; they are validated so that a damaged file is still caught,
  // then dropped.
  if(r.next()) {
    if(r.size() != 1)
      r.fail("expected the optional region header '<#regions>' or the end of "
             "the file, found " + internal::poly_count_phrase(r.size(), "value", "values"));
    const std::size_t n_regions = r.count(0, "region count");
    long long region_base = 0;
    for(std::size_t i = 0; i < n_regions; ++i) {
      if(!r.next())
        r.fail("expected " + internal::poly_count_phrase(n_regions, "region", "regions") +
               ", file ends after " + std::to_string(i));
      if(r.size() != 4 && r.size() != 5)
        r.fail("region line (id, x, y, attribute[, maximum area]) has " +
               internal::poly_count_phrase(r.size(), "value", "values") +
               ", expected 4 or 5");
      internal::poly_check_id(r, "region", i, region_base);
      r.real(1, "coordinate");
      r.real(2, "coordinate");
      r.real(3, "region attribute");
      if(r.size() == 5)
        r.real(4, "maximum area");
    }
    if(r.next())
      r.fail("unexpected content after the last section");
  }
  return data;
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Reads the Triangle `.poly` file `file_name`; see
`read_poly(std::istream&, const std::string&)` for the accepted format.

\param file_name path of the `.poly` file

\throws Poly_read_error with the message "cannot open file" when the file
cannot be opened, and on any problem with its content
*/
inline Poly_data read_poly(const std::string& file_name)
{
  // Binary mode: line ends are handled by the reader itself, and the line
  // numbers must match what an editor shows.
  std::ifstream in(file_name.c_str(), std::ios::in | std::ios::binary);
  if(!in)
    throw Poly_read_error(file_name, 0, "cannot open file");
  return read_poly(in, file_name);
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes `data` in Triangle's `.poly` format with 1-based ids, no attributes,
no boundary markers and no regions.

Coordinates are written with `max_digits10` significant digits and in the
classic locale, so that `read_poly()` gives back exactly the same doubles
whatever the stream's formatting state; that state is restored afterwards.

\param os the output stream
\param data the graph to write

\throws std::invalid_argument if a coordinate is not finite, or a segment
has an endpoint out of range or joins a point to itself, since `read_poly()`
would reject the file
*/
inline void write_poly(std::ostream& os, const Poly_data& data)
{
  const std::size_t n = data.points.size();
  for(const std::array<double, 2>& p : data.points)
    if(!std::isfinite(p[0]) || !std::isfinite(p[1]))
      throw std::invalid_argument("write_poly: point coordinate is not finite");
  for(const std::array<std::size_t, 2>& s : data.segments) {
    if(s[0] >= n || s[1] >= n)
      throw std::invalid_argument("write_poly: segment endpoint out of range");
    if(s[0] == s[1])
      throw std::invalid_argument("write_poly: segment joins a point to itself");
  }
  for(const std::array<double, 2>& h : data.holes)
    if(!std::isfinite(h[0]) || !std::isfinite(h[1]))
      throw std::invalid_argument("write_poly: hole coordinate is not finite");

  // formatting and locale only: restoring the error state would hide a failed write
  boost::io::ios_base_all_saver format_saver(os);
  boost::io::ios_locale_saver locale_saver(os);
  os.imbue(std::locale::classic());
  os.flags(std::ios_base::dec);
  os.precision(std::numeric_limits<double>::max_digits10);
  os.width(0);

  os << n << " 2 0 0\n";
  for(std::size_t i = 0; i < n; ++i)
    os << (i + 1) << ' ' << data.points[i][0] << ' ' << data.points[i][1] << '\n';
  os << data.segments.size() << " 0\n";
  for(std::size_t i = 0; i < data.segments.size(); ++i)
    os << (i + 1) << ' ' << (data.segments[i][0] + 1) << ' '
       << (data.segments[i][1] + 1) << '\n';
  os << data.holes.size() << '\n';
  for(std::size_t i = 0; i < data.holes.size(); ++i)
    os << (i + 1) << ' ' << data.holes[i][0] << ' ' << data.holes[i][1] << '\n';
}

/*!
\ingroup PkgAdvancingFrontMesh2IO

Writes `data` to the file `file_name`; see
`write_poly(std::ostream&, const Poly_data&)`.

\param file_name path of the `.poly` file to create or overwrite
\param data the graph to write

\throws std::invalid_argument if `data` is not a valid graph
\throws std::runtime_error "cannot write FILE" when the file cannot be opened
or written
*/
inline void write_poly(const std::string& file_name, const Poly_data& data)
{
  std::ofstream os(file_name.c_str(), std::ios::out | std::ios::binary);
  if(!os)
    throw std::runtime_error("cannot write " + file_name);
  write_poly(os, data);
  os.flush();
  if(!os)
    throw std::runtime_error("cannot write " + file_name);
}

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_READ_POLY_H
