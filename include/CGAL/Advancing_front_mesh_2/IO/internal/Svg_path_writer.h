// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_PATH_WRITER_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_PATH_WRITER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <ios>
#include <ostream>
#include <string>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// Writes the `d` attribute of one <path> on an integer grid in picture
// space. Relative steps between grid points are exact, so the short deltas
// of small edges save space without accumulating rounding drift.
class Svg_path_writer
{
public:
  // `splittable` tells whether the subpaths may be spread over several
  // elements: not for a fill, where a hole only stays empty if its loop is in
  // the same element as the loop around it.
  Svg_path_writer(std::ostream& os, const std::string& attributes,
                  double x0, double y1, double scale, int decimals,
                  bool splittable)
    : os_(os), attributes_(attributes), x0_(x0), y1_(y1), decimals_(decimals),
      splittable_(splittable)
  {
    pow10_ = 1;
    for(int i = 0; i < decimals; ++i)
      pow10_ *= 10;
    grid_scale_ = scale * static_cast<double>(pow10_);
  }

  void move_to(const std::array<double, 2>& p)
  {
    // A new element every so often, since a stroke looks the same drawn in
    // one element or several: librsvg 2.54 (through libxml2) gives up on
    // files with many path data much longer than 256 KB, and each subpath
    // starts with an absolute move, so the split is free.
    if(splittable_ && opened_ && element_length_ > max_element_length)
      finish();
    long long gx, gy;
    to_grid(p, gx, gy);
    put_move(gx, gy);
    start_x_ = gx;
    start_y_ = gy;
  }

  void line_to(const std::array<double, 2>& p)
  {
    long long gx, gy;
    to_grid(p, gx, gy);
    // One polyline can be long enough to need splitting by itself.
    if(splittable_ && element_length_ > 2 * max_element_length) {
      finish();
      put_move(x_, y_);
    }
    maybe_break();
    if(last_command_ != 'l')
      put_command('l');
    put_number(gx - x_);
    put_number(gy - y_);
    x_ = gx;
    y_ = gy;
    maybe_flush();
  }

  void close()
  {
    put_command('z');
    x_ = start_x_;
    y_ = start_y_;
  }

  // Ends the element, if anything was drawn; an empty path is not written.
  void finish()
  {
    if(!opened_)
      return;
    buf_ += "\"/>\n";
    os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
    opened_ = false;
    element_length_ = 0;
  }

private:
  static constexpr std::size_t max_element_length = std::size_t(1) << 16;

  void put_move(long long gx, long long gy)
  {
    open();
    maybe_break();
    put_command('M');
    put_number(gx);
    put_number(gy);
    x_ = gx;
    y_ = gy;
  }

  void open()
  {
    if(opened_)
      return;
    opened_ = true;
    buf_ += "<path ";
    buf_ += attributes_;
    buf_ += " d=\"";
    last_command_ = 0;
    line_length_ = 0;
  }

  // Keeps lines short for text tools; whitespace is a valid separator.
  void maybe_break()
  {
    if(line_length_ > 120) {
      buf_ += '\n';
      line_length_ = 0;
      need_separator_ = false;
    }
  }

  void to_grid(const std::array<double, 2>& p, long long& gx, long long& gy) const
  {
    gx = std::llround((p[0] - x0_) * grid_scale_);
    gy = std::llround((y1_ - p[1]) * grid_scale_);
  }

  void put_command(char c)
  {
    buf_ += c;
    ++line_length_;
    ++element_length_;
    last_command_ = c;
    need_separator_ = false;
  }

  void put_number(long long g)
  {
    char tmp[48];
    int n = 0;
    const bool negative = g < 0;
    unsigned long long a = negative ? 0ULL - static_cast<unsigned long long>(g)
                                    : static_cast<unsigned long long>(g);
    const unsigned long long p = static_cast<unsigned long long>(pow10_);
    unsigned long long ip = a / p, fp = a % p;
    // Fraction digits, most significant first, without trailing zeros.
    char frac[24];
    int nf = 0;
    if(fp != 0) {
      for(int i = decimals_ - 1; i >= 0; --i) {
        frac[i] = static_cast<char>('0' + fp % 10);
        fp /= 10;
      }
      nf = decimals_;
      while(nf > 0 && frac[nf - 1] == '0')
        --nf;
    }
    char digits[24];
    int nd = 0;
    do {
      digits[nd++] = static_cast<char>('0' + ip % 10);
      ip /= 10;
    } while(ip != 0);
    if(negative)
      tmp[n++] = '-'; // the sign also separates it from the previous number
    else if(need_separator_)
      tmp[n++] = ' ';
    while(nd > 0)
      tmp[n++] = digits[--nd];
    if(nf > 0) {
      tmp[n++] = '.';
      for(int i = 0; i < nf; ++i)
        tmp[n++] = frac[i];
    }
    buf_.append(tmp, static_cast<std::size_t>(n));
    line_length_ += static_cast<std::size_t>(n);
    element_length_ += static_cast<std::size_t>(n);
    need_separator_ = true;
  }

  void maybe_flush()
  {
    if(buf_.size() >= (std::size_t(1) << 16)) {
      os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
      buf_.clear();
    }
  }

  std::ostream& os_;
  std::string attributes_;
  double x0_, y1_;
  int decimals_;
  bool splittable_;
  long long pow10_;
  double grid_scale_;
  std::string buf_;
  bool opened_ = false;
  bool need_separator_ = false;
  char last_command_ = 0;
  std::size_t line_length_ = 0;
  std::size_t element_length_ = 0;
  long long x_ = 0, y_ = 0, start_x_ = 0, start_y_ = 0;
};

} // namespace internal

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_SVG_PATH_WRITER_H
