// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_STREAMING_FILES_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_STREAMING_FILES_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Durable_files.h>

#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_writer_common.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#if defined(_WIN32)
#  include <io.h>
#elif defined(__unix__) || defined(__APPLE__)
#  include <fcntl.h>
#  include <unistd.h>
#  define CGAL_ADVANCING_FRONT_MESH_2_HAS_POSIX_FSYNC
#endif

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

namespace internal {

enum class Streaming_format { OFF, VTU, NODE_ELE, MSH };

// The count in the first line of a .node or .ele file written while
// streaming is not known until the end: it is reserved as a field this wide,
// padded with spaces, and overwritten in place by close(). Triangle's
// readers, like every other reader of these files, split on whitespace.
constexpr std::size_t streaming_count_width = text_max_uint_chars;

// A file written from start to end through a large buffer of our own (the
// meshes reach gigabytes, and stdio's per-call formatting and iostream's
// sentries would dominate the run time). Keeps its own size, flushed bytes
// plus buffered ones, which is what a checkpoint records.
class Streaming_file
{
public:
  explicit Streaming_file(const std::string& path) : path_(path) {}
  Streaming_file(const Streaming_file&) = delete;
  Streaming_file& operator=(const Streaming_file&) = delete;
  ~Streaming_file() { abandon(); }

  const std::string& path() const { return path_; }
  std::uint64_t size() const { return size_; }
  bool is_open() const { return f_ != nullptr; }

  // Creates the file, or empties it.
  void create()
  {
    open("wb");
    size_ = 0;
  }

  // Continues a file that has just been truncated to `size` bytes.
  void append(std::uint64_t size)
  {
    open("ab");
    size_ = size;
  }

  // Room for `n` characters (at most the buffer capacity) at the end of the
  // buffer; `commit()` then says how many were written.
  char* reserve(std::size_t n)
  {
    if(capacity - used_ < n)
      drain();
    return buf_.get() + used_;
  }

  void commit(const char* end)
  {
    const std::size_t n = static_cast<std::size_t>(end - (buf_.get() + used_));
    used_ += n;
    size_ += n;
  }

  void put(const char* s, std::size_t n)
  {
    while(n > 0) {
      const std::size_t k = (std::min)(n, capacity);
      char* p = reserve(k);
      std::memcpy(p, s, k);
      commit(p + k);
      s += k;
      n -= k;
    }
  }

  void put(const char* s) { put(s, std::strlen(s)); }
  void put(const std::string& s) { put(s.data(), s.size()); }

  void put_uint(std::uint64_t v)
  {
    char* p = reserve(text_max_uint_chars);
    commit(text_format_uint(p, v));
  }

  void put_double(double v)
  {
    char* p = reserve(text_max_double_chars);
    commit(text_format_double(p, v));
  }

  // Hands everything to the operating system; throws on a write error.
  void flush()
  {
    drain();
    if(std::fflush(f_) != 0 || std::ferror(f_))
      fail();
  }

  // Makes everything durable, where the platform can tell.
  void sync()
  {
    flush();
#if defined(_WIN32)
    if(::_commit(::_fileno(f_)) != 0)
      fail();
#elif defined(CGAL_ADVANCING_FRONT_MESH_2_HAS_POSIX_FSYNC)
    // EINVAL: a special file that cannot be synchronized (/dev/null, a
    // pipe), which is not an error of the output
    if(::fsync(::fileno(f_)) != 0 && errno != EINVAL)
      fail();
#endif
  }

  // Flushes (and syncs if asked) and closes; throws on a write error.
  void close(bool durable)
  {
    if(f_ == nullptr)
      return;
    if(durable)
      sync();
    else
      flush();
    std::FILE* f = f_;
    f_ = nullptr;
    if(std::fclose(f) != 0)
      fail();
  }

  // Writes what it can and closes, without a word: for destructors and
  // error paths, where the output is given up anyway (a resume truncates
  // whatever came after the last checkpoint).
  void abandon() noexcept
  {
    if(f_ == nullptr)
      return;
    if(used_ != 0 && std::fwrite(buf_.get(), 1, used_, f_) != used_) {
      // nothing to do about it here
    }
    used_ = 0;
    std::fclose(f_);
    f_ = nullptr;
  }

  [[noreturn]] void fail()
  {
    used_ = 0; // not to be retried by abandon()
    throw std::runtime_error("cannot write " + path_);
  }

  // 1 MiB: large enough for the kernel to see big sequential writes, small
  // enough to allow a few files per output.
  static constexpr std::size_t capacity = std::size_t(1) << 20;

private:
  void open(const char* mode)
  {
    abandon();
    if(!buf_)
      buf_.reset(new char[capacity]);
    used_ = 0;
    f_ = std::fopen(path_.c_str(), mode);
    if(f_ == nullptr)
      fail();
    // our buffer is the only one: no copy through stdio's
    std::setvbuf(f_, nullptr, _IONBF, 0);
  }

  void drain()
  {
    if(used_ != 0 && std::fwrite(buf_.get(), 1, used_, f_) != used_)
      fail();
    used_ = 0;
  }

  std::string path_;
  std::FILE* f_ = nullptr;
  std::unique_ptr<char[]> buf_;
  std::size_t used_ = 0;
  std::uint64_t size_ = 0;
};

// What a streamed output records, beyond the mesh: markers (vertex and
// segment markers, segments) and regions (the attribute of each triangle,
// one of `attributes`, sorted and distinct). VTU arrays are binary unless
// `binary` is false.
struct Streaming_content
{
  bool binary = true;
  bool tagged = false;
  std::vector<double> attributes; // empty: no regions

  bool has_regions() const { return !attributes.empty(); }
};

// What a part file holds, for the checks of a resume: per vertex or per
// triangle (of one group of Gmsh surfaces, whose own count is recorded),
// lines of at least `unit` bytes or records of exactly `unit` bytes, after
// `header` bytes written at creation.
enum class Streaming_count { VERTICES, TRIANGLES, GROUP_TRIANGLES };

struct Streaming_part
{
  Streaming_part(const std::string& path, Streaming_count c, bool is_binary, std::uint64_t u, std::uint64_t h = 0)
    : file(path), count(c), binary(is_binary), unit(u), header(h)
  {}
  Streaming_file file;
  Streaming_count count;
  bool binary;
  std::uint64_t unit;
  std::uint64_t header;
};

// One output given by the user and the part files written while streaming,
// beside it; close() makes the final files from them under temporary names
// (FINAL.part; the .node and .ele parts are those of their finals, patched
// in place) and renames them into place only when all are complete, so that
// an interrupted run leaves no half-written file under a final name.
//
// Parts: the vertices first; then the triangles (one part per region
// attribute for a tagged Gmsh file, whose surfaces are grouped by
// attribute); then, for VTU, the vertex markers and the triangle attributes
// when the output has them. Triangle's .node and .ele are their own parts,
// their counts patched in place at the end.
struct Streaming_output
{
  std::string name;
  Streaming_format format;
  std::string base; // .node/.ele: the path without its extension
  std::vector<std::unique_ptr<Streaming_part> > parts;
  std::size_t triangle_parts = 1;
  Streaming_part* vertex_markers = nullptr;      // VTU, tagged
  Streaming_part* triangle_attributes = nullptr; // VTU, with regions

  Streaming_file& vertices() { return parts[0]->file; }
  Streaming_file& triangles(std::size_t group = 0) { return parts[1 + group]->file; }

  // the finished files, and the temporary names they are made under
  std::vector<std::string> final_files(const Streaming_content& c) const
  {
    if(format != Streaming_format::NODE_ELE) return {name};
    std::vector<std::string> r{base + ".node", base + ".ele"};
    if(c.tagged) r.push_back(base + ".edge");
    return r;
  }
  static std::string temporary(const std::string& final_file) { return final_file + ".part"; }
};

constexpr const char* streaming_node_tail = " 2 0 0\n";
constexpr const char* streaming_node_tagged_tail = " 2 0 1\n";
constexpr const char* streaming_ele_tail = " 3 0\n";
constexpr const char* streaming_ele_regions_tail = " 3 1\n";

inline std::unique_ptr<Streaming_output> streaming_make_output(const std::string& name, const Streaming_content& c)
{
  const std::string ext = mesh_lower_extension(name);
  std::unique_ptr<Streaming_output> o(new Streaming_output);
  o->name = name;
  if(ext == "off")
    o->format = Streaming_format::OFF;
  else if(ext == "vtu")
    o->format = Streaming_format::VTU;
  else if(ext == "node" || ext == "ele")
    o->format = Streaming_format::NODE_ELE;
  else if(ext == "msh")
    o->format = Streaming_format::MSH;
  else
    throw std::invalid_argument("Streaming_mesh_writer: the format of '" + name +
                                "' cannot be streamed (streamed formats: .off, .vtu, "
                                ".node/.ele, .msh)");
  auto add = [&o](const std::string& path, Streaming_count count, bool binary, std::uint64_t unit,
                  std::uint64_t header = 0) {
    o->parts.emplace_back(new Streaming_part(path, count, binary, unit, header));
    return o->parts.back().get();
  };
  // the fewest bytes of a line: "0 0 0\n", "3 0 0 0\n", "0 0 0\n", "1 0 0 0\n", "0\n"
  switch(o->format) {
  case Streaming_format::OFF:
    add(name + ".vertices.part", Streaming_count::VERTICES, false, 6);
    add(name + ".triangles.part", Streaming_count::TRIANGLES, false, 8);
    break;
  case Streaming_format::NODE_ELE: {
    o->base = name.substr(0, name.size() - ext.size() - 1);
    const std::uint64_t node_header =
      streaming_count_width + std::strlen(c.tagged ? streaming_node_tagged_tail : streaming_node_tail);
    const std::uint64_t ele_header =
      streaming_count_width + std::strlen(c.has_regions() ? streaming_ele_regions_tail : streaming_ele_tail);
    add(o->base + ".node.part", Streaming_count::VERTICES, false, 6, node_header);
    add(o->base + ".ele.part", Streaming_count::TRIANGLES, false, 8, ele_header);
    break;
  }
  case Streaming_format::MSH:
    add(name + ".vertices.part", Streaming_count::VERTICES, false, 6);
    if(c.tagged && c.has_regions()) {
      o->triangle_parts = c.attributes.size();
      for(std::size_t g = 0; g < c.attributes.size(); ++g)
        add(name + ".triangles." + std::to_string(g) + ".part", Streaming_count::GROUP_TRIANGLES, false, 8);
    } else {
      add(name + ".triangles.part", Streaming_count::TRIANGLES, false, 8);
    }
    break;
  case Streaming_format::VTU:
    add(name + ".vertices.part", Streaming_count::VERTICES, c.binary, c.binary ? 24 : 6);
    add(name + ".triangles.part", Streaming_count::TRIANGLES, c.binary, c.binary ? 24 : 6);
    if(c.tagged)
      o->vertex_markers = add(name + ".markers.part", Streaming_count::VERTICES, c.binary, c.binary ? 4 : 2);
    if(c.tagged && c.has_regions())
      o->triangle_attributes = add(name + ".regions.part", Streaming_count::TRIANGLES, c.binary, c.binary ? 8 : 2);
    break;
  }
  return o;
}

// Every file an output writes: its parts, the finished files and their
// temporary names.
inline std::vector<std::string> streaming_files_of(const Streaming_output& o, const Streaming_content& c)
{
  std::vector<std::string> r;
  for(const std::unique_ptr<Streaming_part>& p : o.parts) r.push_back(p->file.path());
  for(const std::string& f : o.final_files(c)) {
    r.push_back(f);
    // the .node and .ele parts are the temporary files of their finals
    if(std::find(r.begin(), r.end(), Streaming_output::temporary(f)) == r.end())
      r.push_back(Streaming_output::temporary(f));
  }
  return r;
}

// Two outputs writing the same file would garble it: "a.node" and "a.ele"
// are the same pair of files, "a.off" given twice is the same file.
inline void streaming_check_distinct(const std::vector<std::unique_ptr<Streaming_output> >& outputs,
                                     const Streaming_content& c)
{
  std::vector<std::pair<std::string, std::string> > files; // normalized, given
  for(const std::unique_ptr<Streaming_output>& o : outputs)
    for(const std::string& f : streaming_files_of(*o, c))
      files.emplace_back(std::filesystem::path(f).lexically_normal().string(), o->name);
  std::sort(files.begin(), files.end());
  for(std::size_t i = 1; i < files.size(); ++i)
    if(files[i].first == files[i - 1].first)
      throw std::invalid_argument("Streaming_mesh_writer: the outputs '" + files[i - 1].second +
                                  "' and '" + files[i].second + "' would both write " +
                                  files[i].first);
}

// The first line of a .node or .ele file, with the count padded to its
// reserved width; `tail` is the rest of the line.
inline void streaming_put_count_line(Streaming_file& f, std::uint64_t count, const char* tail)
{
  char line[streaming_count_width + 16];
  char* p = text_format_uint(line, count);
  while(p < line + streaming_count_width)
    *p++ = ' ';
  f.put(line, streaming_count_width);
  f.put(tail, std::strlen(tail));
}

// Rewrites the reserved count of a closed .node or .ele file.
inline void streaming_patch_count(const std::string& path, std::uint64_t count)
{
  char field[streaming_count_width];
  char* p = text_format_uint(field, count);
  while(p < field + streaming_count_width)
    *p++ = ' ';
  std::FILE* f = std::fopen(path.c_str(), "r+b");
  if(f == nullptr)
    throw std::runtime_error("cannot write " + path);
  bool ok = std::fwrite(field, 1, streaming_count_width, f) == streaming_count_width &&
            std::fflush(f) == 0;
#if defined(_WIN32)
  ok = ok && ::_commit(::_fileno(f)) == 0;
#elif defined(CGAL_ADVANCING_FRONT_MESH_2_HAS_POSIX_FSYNC)
  ok = ok && (::fsync(::fileno(f)) == 0 || errno == EINVAL);
#endif
  ok = (std::fclose(f) == 0) && ok;
  if(!ok)
    throw std::runtime_error("cannot write " + path);
}

// Appends the whole content of `part`, which must be `size` bytes long.
inline void streaming_copy_part(Streaming_file& out, const std::string& part, std::uint64_t size)
{
  // closed also when a write to `out` throws
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> in(std::fopen(part.c_str(), "rb"), &std::fclose);
  if(!in)
    throw std::runtime_error("cannot read " + part);
  std::uint64_t copied = 0;
  for(;;) {
    char* p = out.reserve(Streaming_file::capacity);
    const std::size_t n = std::fread(p, 1, Streaming_file::capacity, in.get());
    out.commit(p + n);
    copied += n;
    if(n < Streaming_file::capacity)
      break;
  }
  const bool ok = !std::ferror(in.get());
  if(!ok || copied != size)
    throw std::runtime_error("cannot read " + part + " (" +
                             (ok ? "its size changed while the mesh was written" : "read error") + ")");
}

// Makes the directory entries of newly created files durable (POSIX only;
// elsewhere, and on file systems that refuse it, this is skipped).
inline void streaming_sync_directories(const std::vector<std::string>& files)
{
  std::vector<std::string> dirs;
  for(const std::string& f : files) {
    const std::string d = std::filesystem::path(f).parent_path().string();
    if(std::find(dirs.begin(), dirs.end(), d) != dirs.end())
      continue;
    dirs.push_back(d);
    Advancing_front_mesh_2::internal::sync_directory_of(f);
  }
}

} // namespace internal

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#undef CGAL_ADVANCING_FRONT_MESH_2_HAS_POSIX_FSYNC

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_STREAMING_FILES_H
