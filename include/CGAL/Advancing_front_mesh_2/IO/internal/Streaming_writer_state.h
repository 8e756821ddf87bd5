// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_STREAMING_WRITER_STATE_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_STREAMING_WRITER_STATE_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

// Reads the text of checkpoint_state(); everything it does not like is
// std::invalid_argument, and no number read is used for a size before it
// is checked against the length of the text.
class Streaming_state_reader
{
public:
  explicit Streaming_state_reader(const std::string& s) : s_(s) {}

  [[noreturn]] void corrupt(const std::string& what) const
  {
    throw std::invalid_argument("corrupt streaming writer state: " + what +
                                " (at byte " + std::to_string(pos_) + ")");
  }

  void expect(const char* literal, const char* what)
  {
    const std::size_t n = std::strlen(literal);
    if(s_.compare(pos_, n, literal) != 0)
      corrupt(std::string("expected ") + what);
    pos_ += n;
  }

  // consumes `literal` if the text continues with it
  bool try_expect(const char* literal)
  {
    const std::size_t n = std::strlen(literal);
    if(s_.compare(pos_, n, literal) != 0)
      return false;
    pos_ += n;
    return true;
  }

  std::size_t position() const { return pos_; }

  std::uint64_t read_uint(const char* what)
  {
    const char* b = s_.data() + pos_;
    const char* e = s_.data() + s_.size();
    std::uint64_t v = 0;
    const std::from_chars_result r = std::from_chars(b, e, v);
    if(r.ec != std::errc() || r.ptr == b)
      corrupt(std::string("bad ") + what);
    pos_ += static_cast<std::size_t>(r.ptr - b);
    return v;
  }

  std::size_t read_size(const char* what)
  {
    const std::uint64_t v = read_uint(what);
    if(v > (std::numeric_limits<std::size_t>::max)())
      corrupt(std::string(what) + " too large");
    return static_cast<std::size_t>(v);
  }

  // length:characters, so that any character may appear in a file name
  std::string read_name(const char* what)
  {
    const std::uint64_t n = read_uint(what);
    expect(":", "':' after the length of a name");
    if(n > s_.size() - pos_)
      corrupt(std::string(what) + " longer than the state");
    std::string r = s_.substr(pos_, static_cast<std::size_t>(n));
    pos_ += static_cast<std::size_t>(n);
    return r;
  }

  double read_double(const char* what)
  {
    const char* b = s_.data() + pos_;
    const char* e = s_.data() + s_.size();
    double v = 0;
    const std::from_chars_result r = std::from_chars(b, e, v, std::chars_format::hex);
    if(r.ec != std::errc() || r.ptr == b || !std::isfinite(v))
      corrupt(std::string("bad ") + what);
    pos_ += static_cast<std::size_t>(r.ptr - b);
    return v;
  }

  bool at_end() const { return pos_ == s_.size(); }

private:
  const std::string& s_;
  std::size_t pos_ = 0;
};

constexpr const char* streaming_state_magic = "CGAL Advancing_front_mesh_2 Streaming_mesh_writer state 2\n";

// The text of checkpoint_state() as read back, its syntax checked; whether
// it matches the files is for resume() to check.
struct Streaming_recorded_state
{
  bool binary = true, tagged = false;
  std::vector<double> attributes;
  std::vector<std::string> names; // the outputs, as given
  // per output, its part files with their sizes
  std::vector<std::vector<std::pair<std::string, std::uint64_t> > > files;
  std::vector<std::size_t> group_counts; // triangles per region attribute
  std::size_t nv = 0, nt = 0;
  double bbox[4] = {0, 0, 0, 0}; // xmin, ymin, xmax, ymax
};

inline Streaming_recorded_state streaming_read_state(Streaming_state_reader& r)
{
  Streaming_recorded_state s;
  r.expect(streaming_state_magic, "the first line of a streaming writer state");
  r.expect("content ", "'content'");
  const std::uint64_t binary = r.read_uint("VTU encoding");
  r.expect(" ", "space");
  const std::uint64_t tagged = r.read_uint("tags");
  if(binary > 1 || tagged > 1) r.corrupt("bad content flags");
  s.binary = binary == 1;
  s.tagged = tagged == 1;
  r.expect(" ", "space");
  // No reserve() from a count read: each item read consumes the text, so a
  // corrupt count fails at the end of the text, not in the allocator.
  const std::uint64_t n_attributes = r.read_uint("number of region attributes");
  for(std::uint64_t i = 0; i < n_attributes; ++i) {
    r.expect(" ", "space");
    s.attributes.push_back(r.read_double("region attribute"));
    if(i > 0 && !(s.attributes[i - 1] < s.attributes[i])) r.corrupt("region attributes not sorted");
  }
  if(n_attributes > 0 && !s.tagged) r.corrupt("regions without tags");
  r.expect("\noutputs ", "'outputs'");
  const std::uint64_t n_outputs = r.read_uint("number of outputs");
  r.expect("\n", "end of line");
  if(n_outputs == 0)
    r.corrupt("no output");
  for(std::uint64_t i = 0; i < n_outputs; ++i) {
    r.expect("output ", "'output'");
    s.names.push_back(r.read_name("length of an output name"));
    r.expect("\nfiles ", "'files'");
    const std::uint64_t n_files = r.read_uint("number of files");
    r.expect("\n", "end of line");
    std::vector<std::pair<std::string, std::uint64_t> > of;
    for(std::uint64_t k = 0; k < n_files; ++k) {
      r.expect("file ", "'file'");
      const std::uint64_t size = r.read_uint("file size");
      r.expect(" ", "space");
      of.emplace_back(r.read_name("length of a file name"), size);
      r.expect("\n", "end of line");
    }
    s.files.push_back(of);
  }
  r.expect("groups ", "'groups'");
  const std::uint64_t n_groups = r.read_uint("number of groups");
  if(n_groups != n_attributes) r.corrupt("a group count per region attribute expected");
  for(std::uint64_t g = 0; g < n_groups; ++g) {
    r.expect(" ", "space");
    s.group_counts.push_back(r.read_size("triangles of a group"));
  }
  r.expect("\nvertices ", "'vertices'");
  s.nv = r.read_size("number of vertices");
  r.expect("\ntriangles ", "'triangles'");
  s.nt = r.read_size("number of triangles");
  r.expect("\nbbox ", "'bbox'");
  for(int k = 0; k < 4; ++k) {
    if(k != 0)
      r.expect(" ", "space");
    s.bbox[k] = r.read_double("bounding box coordinate");
  }
  r.expect("\nend\n", "'end'");
  if(!r.at_end())
    r.corrupt("text after the end");
  return s;
}

} // namespace internal

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_STREAMING_WRITER_STATE_H
