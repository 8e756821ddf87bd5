// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_POLY_LINE_READER_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_POLY_LINE_READER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Poly_read_error.h>

#include <cerrno>
#include <clocale>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <cstring>
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

// '\r' is blank so that files written on Windows read the same.
inline bool poly_is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Reads one physical line of `buf` into `line`, without its end and, when
// `comment` is not '\0', without what follows that character; counts it in
// `line_no`; false (and `at_end` set) at the end of input. Stops with
// `too_long` set once the line holds more than `max_length` characters, so
// that binary garbage without a newline is not buffered whole.
inline bool poly_read_physical_line(std::streambuf* buf, std::size_t max_length, char comment, std::string& line,
                                    std::size_t& line_no, bool& at_end, bool& too_long)
{
  typedef std::char_traits<char> Traits;
  line.clear();
  too_long = false;
  if(at_end)
    return false;
  if(Traits::eq_int_type(buf->sgetc(), Traits::eof())) {
    at_end = true;
    return false;
  }
  ++line_no;
  bool in_comment = false;
  for(;;) {
    const Traits::int_type c = buf->sbumpc();
    if(Traits::eq_int_type(c, Traits::eof())) {
      at_end = true;
      break;
    }
    const char ch = Traits::to_char_type(c);
    if(ch == '\n')
      break;
    if(in_comment)
      continue;
    if(comment != '\0' && ch == comment) {
      in_comment = true;
      continue;
    }
    if(line.size() >= max_length) {
      too_long = true;
      break;
    }
    line += ch;
  }
  return true;
}

// The tokens of `line` (separated by blanks), as [begin, end) positions.
inline void poly_split_tokens(const std::string& line, std::vector<std::pair<std::size_t, std::size_t> >& tokens)
{
  tokens.clear();
  std::size_t i = 0;
  const std::size_t n = line.size();
  while(i < n) {
    while(i < n && poly_is_blank(line[i])) ++i;
    if(i == n) break;
    const std::size_t b = i;
    while(i < n && !poly_is_blank(line[i])) ++i;
    tokens.push_back(std::make_pair(b, i));
  }
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
    bool too_long = false;
    const bool got = poly_read_physical_line(buf_, poly_max_line_length, '#', line_, line_no_, at_end_, too_long);
    if(too_long)
      fail("line is longer than " + std::to_string(poly_max_line_length) + " characters");
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

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_POLY_LINE_READER_H
