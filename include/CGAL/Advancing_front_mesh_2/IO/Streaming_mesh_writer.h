// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_STREAMING_MESH_WRITER_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_STREAMING_MESH_WRITER_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Mesh_sink_2.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
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

// Longest outputs of std::to_chars: "-2.2250738585072014e-308" has 24
// characters, a 64-bit unsigned integer 20.
constexpr std::size_t streaming_max_double_chars = 32;
constexpr std::size_t streaming_max_uint_chars = 20;

// The count in the first line of a .node or .ele file written while
// streaming is not known until the end: it is reserved as a field this wide,
// padded with spaces, and overwritten in place by close(). Triangle's
// readers, like every other reader of these files, split on whitespace.
constexpr std::size_t streaming_count_width = streaming_max_uint_chars;

// The shortest decimal that reads back to the same double, in the "C"
// locale whatever the global one is: files read back exactly, and are
// about half the size of max_digits10 output for round numbers.
inline char* streaming_format_double(char* p, double v)
{
  return std::to_chars(p, p + streaming_max_double_chars, v).ptr;
}

inline char* streaming_format_uint(char* p, std::uint64_t v)
{
  return std::to_chars(p, p + streaming_max_uint_chars, v).ptr;
}

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
    char* p = reserve(streaming_max_uint_chars);
    commit(streaming_format_uint(p, v));
  }

  void put_double(double v)
  {
    char* p = reserve(streaming_max_double_chars);
    commit(streaming_format_double(p, v));
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

// One output given by the user, and the two files written while streaming:
// the vertex and triangle part files assembled by close() for OFF, VTU and
// MSH, whose headers hold counts and whose vertices come before the
// elements; the .node and .ele files themselves for Triangle's format,
// whose only count is patched in place.
struct Streaming_output
{
  Streaming_output(const std::string& given, Streaming_format f,
                   const std::string& vertex_file, const std::string& triangle_file)
    : name(given), format(f), vertices(vertex_file), triangles(triangle_file)
  {}

  std::string name;
  Streaming_format format;
  Streaming_file vertices;
  Streaming_file triangles;
};

inline std::unique_ptr<Streaming_output> streaming_make_output(const std::string& name)
{
  const std::string ext = mesh_lower_extension(name);
  Streaming_format format;
  if(ext == "off")
    format = Streaming_format::OFF;
  else if(ext == "vtu")
    format = Streaming_format::VTU;
  else if(ext == "node" || ext == "ele")
    format = Streaming_format::NODE_ELE;
  else if(ext == "msh")
    format = Streaming_format::MSH;
  else
    throw std::invalid_argument("Streaming_mesh_writer: the format of '" + name +
                                "' cannot be streamed (streamed formats: .off, .vtu, "
                                ".node/.ele, .msh)");
  if(format == Streaming_format::NODE_ELE) {
    const std::string base = name.substr(0, name.size() - ext.size() - 1);
    return std::unique_ptr<Streaming_output>(
      new Streaming_output(name, format, base + ".node", base + ".ele"));
  }
  return std::unique_ptr<Streaming_output>(
    new Streaming_output(name, format, name + ".vertices.part", name + ".triangles.part"));
}

// Every file an output writes, the assembled one included.
inline std::vector<std::string> streaming_files_of(const Streaming_output& o)
{
  std::vector<std::string> r{o.vertices.path(), o.triangles.path()};
  if(o.format != Streaming_format::NODE_ELE)
    r.push_back(o.name);
  return r;
}

// Two outputs writing the same file would garble it: "a.node" and "a.ele"
// are the same pair of files, "a.off" given twice is the same file.
inline void streaming_check_distinct(const std::vector<std::unique_ptr<Streaming_output> >& outputs)
{
  std::vector<std::pair<std::string, std::string> > files; // normalized, given
  for(const std::unique_ptr<Streaming_output>& o : outputs)
    for(const std::string& f : streaming_files_of(*o))
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
  char* p = streaming_format_uint(line, count);
  while(p < line + streaming_count_width)
    *p++ = ' ';
  f.put(line, streaming_count_width);
  f.put(tail, std::strlen(tail));
}

constexpr const char* streaming_node_tail = " 2 0 0\n";
constexpr const char* streaming_ele_tail = " 3 0\n";

// Rewrites the reserved count of a closed .node or .ele file.
inline void streaming_patch_count(const std::string& path, std::uint64_t count)
{
  char field[streaming_count_width];
  char* p = streaming_format_uint(field, count);
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
#if defined(CGAL_ADVANCING_FRONT_MESH_2_HAS_POSIX_FSYNC)
  std::vector<std::string> dirs;
  for(const std::string& f : files) {
    std::string d = std::filesystem::path(f).parent_path().string();
    if(d.empty())
      d = ".";
    if(std::find(dirs.begin(), dirs.end(), d) != dirs.end())
      continue;
    dirs.push_back(d);
    const int fd = ::open(d.c_str(), O_RDONLY);
    if(fd >= 0) {
      if(::fsync(fd) != 0) {
        // not all file systems can sync a directory; the files are synced
      }
      ::close(fd);
    }
  }
#else
  static_cast<void>(files);
#endif
}

// The smallest number of bytes a vertex or triangle line takes in each
// file ("0 0 0\n", "3 0 0 0\n", ...), and the header written at creation:
// with them a corrupt count far beyond what the recorded file sizes can
// hold is refused instead of being trusted.
inline std::uint64_t streaming_min_line(Streaming_format f, bool triangles)
{
  if(!triangles)
    return 6;
  return f == Streaming_format::VTU ? 6 : 8;
}

inline std::uint64_t streaming_header_size(Streaming_format f, bool triangles)
{
  if(f != Streaming_format::NODE_ELE)
    return 0;
  return streaming_count_width + std::strlen(triangles ? streaming_ele_tail : streaming_node_tail);
}

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

constexpr const char* streaming_state_magic = "CGAL Advancing_front_mesh_2 Streaming_mesh_writer state 1\n";

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2IO

A `Mesh_sink_2` that writes the mesh to files while it is being generated,
in memory independent of the size of the mesh, so that meshes much larger
than the memory can be written; one writer feeds any number of outputs.

The format of each output is given by the extension of its name
(case-insensitive), with the same content as `write_mesh()`:
- `.off`: as `write_OFF()`;
- `.vtu`: a VTK unstructured grid in ASCII with the points (z = 0) and one
  triangle cell (type 5) per triangle, counter-clockwise, 0-based;
- `.node` or `.ele`: both `BASENAME.node` and `BASENAME.ele`, as
  `write_triangle_node_ele()` except that the count of the first line is
  padded with spaces to 20 characters;
- `.msh`: as `write_gmsh_msh()`, the bounding box of the written vertices
  included.

Vertices and triangles are written in the order and with the numbers they
are received (0-based for OFF and VTU, 1-based for Triangle and Gmsh).
Coordinates are converted with `CGAL::to_double()` and written as the
shortest decimal that reads back to the same double.

OFF, VTU and MSH files give their counts before the vertices and the
vertices before the elements, so the vertex and triangle lines are written to
the part files `NAME.vertices.part` and `NAME.triangles.part` beside each
output `NAME`, and `close()` assembles the final file from them and removes
them. The `.node` and `.ele` files are written directly, and `close()` fills
in their counts.

At a checkpoint, `checkpoint_state()` makes the files durable and returns a
text from which `resume()` continues the output exactly from that point,
even after more was written and the process died: the files are then
byte-for-byte those of an uninterrupted run.

\tparam Point the point type of the mesher (a CGAL `Point_2`)
*/
template <class Point>
class Streaming_mesh_writer : public Mesh_sink_2<Point>
{
public:
  /*!
  Creates the files of every output: the part files, `.node` and `.ele`
  with a provisional first line, and each final OFF, VTU or MSH file,
  emptied now so that a stale mesh from an earlier run cannot be taken for
  this one's and an unwritable destination is reported before the meshing.

  \param file_names the outputs; their format is given by their extension
  (see the class description)

  \throws std::invalid_argument if `file_names` is empty, if an extension is
  not one of `.off`, `.vtu`, `.node`, `.ele`, `.msh` (`.svg`, for one, needs
  the whole mesh), or if two outputs would write the same file (such as
  `a.node` and `a.ele`); no file is created then
  \throws std::runtime_error "cannot write FILE" if a file cannot be created
  */
  explicit Streaming_mesh_writer(const std::vector<std::string>& file_names)
    : file_names_(file_names)
  {
    if(file_names.empty())
      throw std::invalid_argument("Streaming_mesh_writer: no output file given");
    make_outputs();
    std::vector<std::string> created;
    for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
      if(o->format != internal::Streaming_format::NODE_ELE) {
        std::FILE* f = std::fopen(o->name.c_str(), "wb");
        if(f == nullptr || std::fclose(f) != 0)
          throw std::runtime_error("cannot write " + o->name);
        created.push_back(o->name);
      }
      o->vertices.create();
      o->triangles.create();
      created.push_back(o->vertices.path());
      created.push_back(o->triangles.path());
      if(o->format == internal::Streaming_format::NODE_ELE) {
        internal::streaming_put_count_line(o->vertices, 0, internal::streaming_node_tail);
        internal::streaming_put_count_line(o->triangles, 0, internal::streaming_ele_tail);
      }
    }
    created_files_ = created;
  }

  /*!
  Closes the files without assembling anything and without throwing: an
  abandoned writer leaves its part files, from which `resume()` continues
  at the last checkpoint. Call `close()` to finish the output.
  */
  ~Streaming_mesh_writer() = default;

  Streaming_mesh_writer(const Streaming_mesh_writer&) = delete;
  Streaming_mesh_writer& operator=(const Streaming_mesh_writer&) = delete;

  /*!
  Writes vertex `index` to every output.

  \pre `index` is the number of vertices written so far, and the coordinates
  converted to `double` are finite

  \throws std::logic_error if `index` is not the number of vertices written
  so far, or after `close()`
  \throws std::invalid_argument if a coordinate is not finite
  \throws std::runtime_error "cannot write FILE" on a write error; the writer
  then refuses everything (resume from the last checkpoint)
  */
  void add_vertex(std::size_t index, const Point& p) override
  {
    check_writable("add_vertex()");
    if(index != nv_)
      throw std::logic_error("Streaming_mesh_writer: vertex " + std::to_string(index) +
                             " received when vertex " + std::to_string(nv_) +
                             " was expected (vertices come numbered 0, 1, 2, ... in order)");
    const double x = CGAL::to_double(p.x());
    const double y = CGAL::to_double(p.y());
    if(!(std::isfinite(x) && std::isfinite(y)))
      throw std::invalid_argument("Streaming_mesh_writer: vertex " + std::to_string(index) +
                                  " has a coordinate that is not a finite double");

    // "x y", formatted once for all outputs
    char xy[2 * internal::streaming_max_double_chars + 1];
    char* e = internal::streaming_format_double(xy, x);
    *e++ = ' ';
    e = internal::streaming_format_double(e, y);
    const std::size_t n = static_cast<std::size_t>(e - xy);

    guarded([&] {
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
        internal::Streaming_file& f = o->vertices;
        char* p = f.reserve(internal::streaming_max_uint_chars + n + 4);
        if(o->format == internal::Streaming_format::NODE_ELE) {
          p = internal::streaming_format_uint(p, std::uint64_t(index) + 1);
          *p++ = ' ';
          std::memcpy(p, xy, n);
          p += n;
          *p++ = '\n';
        } else {
          std::memcpy(p, xy, n);
          p += n;
          std::memcpy(p, " 0\n", 3);
          p += 3;
        }
        f.commit(p);
      }
    });

    // same updates, in the same order, as write_gmsh_msh()
    if(nv_ == 0) {
      xmin_ = xmax_ = x;
      ymin_ = ymax_ = y;
    } else {
      xmin_ = (std::min)(xmin_, x); xmax_ = (std::max)(xmax_, x);
      ymin_ = (std::min)(ymin_, y); ymax_ = (std::max)(ymax_, y);
    }
    ++nv_;
  }

  /*!
  Writes triangle `(i, j, k)` (counter-clockwise) to every output.

  \pre `i`, `j` and `k` are smaller than `number_of_vertices()`

  \throws std::logic_error if an index is not that of a vertex written
  before, or after `close()`
  \throws std::runtime_error "cannot write FILE" on a write error; the writer
  then refuses everything (resume from the last checkpoint)
  */
  void add_triangle(std::size_t i, std::size_t j, std::size_t k) override
  {
    check_writable("add_triangle()");
    if(i >= nv_ || j >= nv_ || k >= nv_)
      throw std::logic_error("Streaming_mesh_writer: triangle (" + std::to_string(i) + ", " +
                             std::to_string(j) + ", " + std::to_string(k) +
                             ") uses a vertex not received yet (" + std::to_string(nv_) +
                             " vertices so far)");

    // "i j k" (0-based) and "t i j k" (1-based), each formatted once
    char zero[3 * (internal::streaming_max_uint_chars + 1)];
    char one[4 * (internal::streaming_max_uint_chars + 1)];
    char* z = zero;
    char* w = internal::streaming_format_uint(one, std::uint64_t(nt_) + 1);
    for(std::size_t v : {i, j, k}) {
      if(z != zero)
        *z++ = ' ';
      z = internal::streaming_format_uint(z, v);
      *w++ = ' ';
      w = internal::streaming_format_uint(w, std::uint64_t(v) + 1);
    }
    *z++ = '\n';
    *w++ = '\n';
    const std::size_t nz = static_cast<std::size_t>(z - zero);
    const std::size_t nw = static_cast<std::size_t>(w - one);

    guarded([&] {
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
        internal::Streaming_file& f = o->triangles;
        switch(o->format) {
        case internal::Streaming_format::OFF:
          f.put("3 ", 2);
          f.put(zero, nz);
          break;
        case internal::Streaming_format::VTU:
          f.put(zero, nz);
          break;
        case internal::Streaming_format::NODE_ELE:
        case internal::Streaming_format::MSH:
          f.put(one, nw);
          break;
        }
      }
    });
    ++nt_;
  }

  /*!
  Flushes all files, makes them durable (`fsync()` where POSIX is
  available, `_commit()` on Windows) and returns the text `resume()`
  needs: a version line, the outputs as given, the counts, the bounding box
  as hexadecimal floating-point numbers and the size of every file written.
  Names are written length-prefixed, so any character may appear in them.

  \throws std::logic_error after `close()`
  \throws std::runtime_error "cannot write FILE" on a write error
  */
  std::string checkpoint_state() override
  {
    check_writable("checkpoint_state()");
    guarded([&] {
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
        o->vertices.sync();
        o->triangles.sync();
      }
    });
    if(!created_files_.empty()) {
      // the files were created by this process: their names must survive too
      internal::streaming_sync_directories(created_files_);
      created_files_.clear();
    }

    std::string s = internal::streaming_state_magic;
    auto put_name = [&s](const std::string& name) {
      s += std::to_string(name.size());
      s += ':';
      s += name;
    };
    auto put_double = [&s](double v) {
      char b[internal::streaming_max_double_chars];
      s.append(b, std::to_chars(b, b + sizeof(b), v, std::chars_format::hex).ptr);
    };
    s += "outputs " + std::to_string(outputs_.size()) + "\n";
    for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
      s += "output ";
      put_name(o->name);
      s += "\n";
      for(const internal::Streaming_file* f : {&o->vertices, &o->triangles}) {
        s += "file " + std::to_string(f->size()) + " ";
        put_name(f->path());
        s += "\n";
      }
    }
    s += "vertices " + std::to_string(nv_) + "\n";
    s += "triangles " + std::to_string(nt_) + "\n";
    s += "bbox ";
    put_double(xmin_); s += ' ';
    put_double(ymin_); s += ' ';
    put_double(xmax_); s += ' ';
    put_double(ymax_); s += "\nend\n";
    return s;
  }

  /*!
  Continues the output of a writer at the checkpoint where `state` was
  returned by its `checkpoint_state()`: every file is truncated to its size
  at the checkpoint and reopened for appending. Vertices and triangles are
  then to be passed again from number `number_of_vertices()` and
  `number_of_triangles()` on; `close()` then gives the files an
  uninterrupted writer would have written.

  \throws std::invalid_argument "corrupt streaming writer state: ..." if
  `state` is not a text written by `checkpoint_state()` (or is damaged);
  nothing is touched then
  \throws std::runtime_error naming the file if a file is missing, shorter
  than at the checkpoint, or does not end a line where the checkpoint left
  it; nothing is touched then. Also "cannot write FILE" if a file cannot be
  truncated or opened.
  */
  static std::unique_ptr<Streaming_mesh_writer> resume(const std::string& state)
  {
    internal::Streaming_state_reader r(state);
    r.expect(internal::streaming_state_magic, "the first line of a streaming writer state");
    r.expect("outputs ", "'outputs'");
    const std::uint64_t n_outputs = r.read_uint("number of outputs");
    r.expect("\n", "end of line");
    if(n_outputs == 0)
      r.corrupt("no output");
    // No reserve(n_outputs): each output read consumes the text, so a
    // corrupt count fails at the end of the text, not in the allocator.
    std::vector<std::string> names;
    std::vector<std::array<std::pair<std::string, std::uint64_t>, 2> > files;
    for(std::uint64_t i = 0; i < n_outputs; ++i) {
      r.expect("output ", "'output'");
      names.push_back(r.read_name("length of an output name"));
      r.expect("\n", "end of line");
      std::array<std::pair<std::string, std::uint64_t>, 2> of;
      for(int k = 0; k < 2; ++k) {
        r.expect("file ", "'file'");
        of[k].second = r.read_uint("file size");
        r.expect(" ", "space");
        of[k].first = r.read_name("length of a file name");
        r.expect("\n", "end of line");
      }
      files.push_back(of);
    }
    r.expect("vertices ", "'vertices'");
    const std::size_t nv = r.read_size("number of vertices");
    r.expect("\ntriangles ", "'triangles'");
    const std::size_t nt = r.read_size("number of triangles");
    r.expect("\nbbox ", "'bbox'");
    double bbox[4];
    for(int k = 0; k < 4; ++k) {
      if(k != 0)
        r.expect(" ", "space");
      bbox[k] = r.read_double("bounding box coordinate");
    }
    r.expect("\nend\n", "'end'");
    if(!r.at_end())
      r.corrupt("text after the end");

    std::unique_ptr<Streaming_mesh_writer> w(new Streaming_mesh_writer(names, Resume_tag()));
    // counts that the recorded sizes cannot hold, or that contradict each other
    if(nt != 0 && nv == 0)
      r.corrupt("triangles without vertices");
    if(nv != 0 && !(bbox[0] <= bbox[2] && bbox[1] <= bbox[3]))
      r.corrupt("empty bounding box");
    for(std::size_t i = 0; i < w->outputs_.size(); ++i) {
      const internal::Streaming_output& o = *w->outputs_[i];
      const internal::Streaming_file* mine[2] = {&o.vertices, &o.triangles};
      for(int k = 0; k < 2; ++k) {
        if(files[i][k].first != mine[k]->path())
          r.corrupt("file " + files[i][k].first + " is not one of output " + o.name);
        const std::uint64_t size = files[i][k].second;
        const std::uint64_t header = internal::streaming_header_size(o.format, k == 1);
        const std::uint64_t count = (k == 0) ? nv : nt;
        if(size < header ||
           count > (size - header) / internal::streaming_min_line(o.format, k == 1))
          r.corrupt("size " + std::to_string(size) + " of " + mine[k]->path() +
                    " cannot hold " + std::to_string(count) +
                    (k == 0 ? " vertices" : " triangles"));
      }
    }

    // Everything is checked before anything is truncated, so that a failed
    // resume leaves the files as it found them.
    for(std::size_t i = 0; i < w->outputs_.size(); ++i)
      for(int k = 0; k < 2; ++k)
        check_partial_file(files[i][k].first, files[i][k].second);
    for(std::size_t i = 0; i < w->outputs_.size(); ++i) {
      internal::Streaming_output& o = *w->outputs_[i];
      internal::Streaming_file* mine[2] = {&o.vertices, &o.triangles};
      for(int k = 0; k < 2; ++k) {
        std::error_code ec;
        std::filesystem::resize_file(mine[k]->path(), files[i][k].second, ec);
        if(ec)
          throw std::runtime_error("cannot write " + mine[k]->path());
        mine[k]->append(files[i][k].second);
      }
    }
    w->nv_ = nv;
    w->nt_ = nt;
    w->xmin_ = bbox[0]; w->ymin_ = bbox[1];
    w->xmax_ = bbox[2]; w->ymax_ = bbox[3];
    return w;
  }

  /*!
  Finishes the output: closes the files, assembles each OFF, VTU and MSH
  file from its header, its part files and its trailer, fills in the counts
  of the `.node` and `.ele` files, makes the results durable and removes
  the part files. Does nothing when called again.

  If it fails, the part files are kept, so that the output can still be
  continued from the last checkpoint with `resume()`.

  \throws std::runtime_error "cannot write FILE" (or "cannot read FILE") on
  an input/output error, or if an earlier write failed
  */
  void close()
  {
    if(closed_)
      return;
    if(failed_)
      throw std::runtime_error("Streaming_mesh_writer: cannot close after a failed write "
                               "(resume from the last checkpoint instead)");
    closing_ = true;
    guarded([&] {
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
        o->vertices.close(false);
        o->triangles.close(false);
      }
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_)
        finish(*o);
      // only now: until every output is complete, a resume needs them all
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
        if(o->format == internal::Streaming_format::NODE_ELE)
          continue;
        std::error_code ec;
        std::filesystem::remove(o->vertices.path(), ec);
        std::filesystem::remove(o->triangles.path(), ec);
      }
    });
    closed_ = true;
  }

  /// the number of vertices written so far
  std::size_t number_of_vertices() const { return nv_; }

  /// the number of triangles written so far
  std::size_t number_of_triangles() const { return nt_; }

  /// the outputs, as given to the constructor (or recorded in the state)
  const std::vector<std::string>& file_names() const { return file_names_; }

private:
  struct Resume_tag {};

  // Only the outputs; resume() opens the files.
  Streaming_mesh_writer(const std::vector<std::string>& file_names, Resume_tag)
    : file_names_(file_names)
  {
    try {
      make_outputs();
    } catch(const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("corrupt streaming writer state: ") + e.what());
    }
  }

  void make_outputs()
  {
    for(const std::string& name : file_names_)
      outputs_.push_back(internal::streaming_make_output(name));
    internal::streaming_check_distinct(outputs_);
  }

  static void check_partial_file(const std::string& path, std::uint64_t size)
  {
    std::error_code ec;
    const std::uintmax_t actual = std::filesystem::file_size(path, ec);
    if(ec || actual < size)
      throw std::runtime_error("cannot resume the streaming output: " + path +
                               " is missing or shorter than at the checkpoint");
    if(size == 0)
      return;
    // A checkpoint always falls after a complete line. (A stream, since
    // fseek() takes a long, which has 32 bits on Windows.)
    std::ifstream in(path.c_str(), std::ios::in | std::ios::binary);
    char c = 0;
    in.seekg(static_cast<std::streamoff>(size - 1));
    if(!in.get(c) || c != '\n')
      throw std::runtime_error("cannot resume the streaming output: " + path +
                               " does not match the checkpoint");
  }

  void check_writable(const char* what) const
  {
    if(closing_)
      throw std::logic_error(std::string("Streaming_mesh_writer: ") + what + " after close()");
    if(failed_)
      throw std::runtime_error(std::string("Streaming_mesh_writer: ") + what +
                               " after a failed write (resume from the last checkpoint instead)");
  }

  // A failed write leaves the outputs at different points of the mesh:
  // nothing more may be written or recorded.
  template <class F>
  void guarded(F f)
  {
    try {
      f();
    } catch(...) {
      failed_ = true;
      throw;
    }
  }

  void finish(internal::Streaming_output& o)
  {
    typedef internal::Streaming_format Format;
    if(o.format == Format::NODE_ELE) {
      internal::streaming_patch_count(o.vertices.path(), nv_);
      internal::streaming_patch_count(o.triangles.path(), nt_);
      return;
    }
    internal::Streaming_file out(o.name);
    out.create();
    if(o.format == Format::OFF) {
      out.put("OFF\n", 4);
      out.put_uint(nv_); out.put(" ", 1); out.put_uint(nt_); out.put(" 0\n", 3);
      internal::streaming_copy_part(out, o.vertices.path(), o.vertices.size());
      internal::streaming_copy_part(out, o.triangles.path(), o.triangles.size());
    } else if(o.format == Format::MSH) {
      write_msh(out, o);
    } else {
      write_vtu(out, o);
    }
    out.close(true);
  }

  // The layout of write_gmsh_msh().
  void write_msh(internal::Streaming_file& out, const internal::Streaming_output& o)
  {
    out.put("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
    out.put("$Entities\n0 0 1 0\n1 ");
    out.put_double(xmin_); out.put(" ", 1); out.put_double(ymin_); out.put(" 0 ", 3);
    out.put_double(xmax_); out.put(" ", 1); out.put_double(ymax_);
    out.put(" 0 0 0\n$EndEntities\n");
    out.put("$Nodes\n");
    if(nv_ == 0) {
      out.put("0 0 0 0\n");
    } else {
      out.put("1 "); out.put_uint(nv_); out.put(" 1 "); out.put_uint(nv_);
      out.put("\n2 1 0 "); out.put_uint(nv_); out.put("\n");
      for(std::uint64_t i = 1; i <= nv_; ++i) {
        char* p = out.reserve(internal::streaming_max_uint_chars + 1);
        p = internal::streaming_format_uint(p, i);
        *p++ = '\n';
        out.commit(p);
      }
      internal::streaming_copy_part(out, o.vertices.path(), o.vertices.size());
    }
    out.put("$EndNodes\n$Elements\n");
    if(nt_ == 0) {
      out.put("0 0 0 0\n");
    } else {
      out.put("1 "); out.put_uint(nt_); out.put(" 1 "); out.put_uint(nt_);
      out.put("\n2 1 2 "); out.put_uint(nt_); out.put("\n");
      internal::streaming_copy_part(out, o.triangles.path(), o.triangles.size());
    }
    out.put("$EndElements\n");
  }

  // ASCII, with 64-bit integers whatever std::size_t is, so that the file
  // does not depend on the platform that wrote it.
  void write_vtu(internal::Streaming_file& out, const internal::Streaming_output& o)
  {
    out.put("<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" "
            "header_type=\"UInt64\">\n"
            "  <UnstructuredGrid>\n"
            "    <Piece NumberOfPoints=\"");
    out.put_uint(nv_);
    out.put("\" NumberOfCells=\"");
    out.put_uint(nt_);
    out.put("\">\n"
            "      <Points>\n"
            "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    internal::streaming_copy_part(out, o.vertices.path(), o.vertices.size());
    out.put("        </DataArray>\n"
            "      </Points>\n"
            "      <Cells>\n"
            "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    internal::streaming_copy_part(out, o.triangles.path(), o.triangles.size());
    out.put("        </DataArray>\n"
            "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for(std::uint64_t i = 1; i <= nt_; ++i) {
      char* p = out.reserve(internal::streaming_max_uint_chars + 1);
      p = internal::streaming_format_uint(p, 3 * i);
      *p++ = '\n';
      out.commit(p);
    }
    out.put("        </DataArray>\n"
            "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for(std::uint64_t i = 0; i < nt_; ++i) {
      char* p = out.reserve(2);
      p[0] = '5';
      p[1] = '\n';
      out.commit(p + 2);
    }
    out.put("        </DataArray>\n"
            "      </Cells>\n"
            "    </Piece>\n"
            "  </UnstructuredGrid>\n"
            "</VTKFile>\n");
  }

  std::vector<std::string> file_names_;
  std::vector<std::unique_ptr<internal::Streaming_output> > outputs_;
  std::vector<std::string> created_files_; // whose directory entries are not synced yet
  std::size_t nv_ = 0;
  std::size_t nt_ = 0;
  double xmin_ = 0, ymin_ = 0, xmax_ = 0, ymax_ = 0;
  bool closing_ = false; // close() was called: nothing more may be added
  bool closed_ = false;  // close() succeeded
  bool failed_ = false;  // a write failed: the outputs disagree
};

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#undef CGAL_ADVANCING_FRONT_MESH_2_HAS_POSIX_FSYNC

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_STREAMING_MESH_WRITER_H
