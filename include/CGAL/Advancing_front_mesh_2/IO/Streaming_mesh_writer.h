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
#include <CGAL/Advancing_front_mesh_2/IO/internal/Streaming_files.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Streaming_writer_state.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <memory>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

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
        char* c = f.reserve(internal::streaming_max_uint_chars + n + 4);
        if(o->format == internal::Streaming_format::NODE_ELE) {
          c = internal::streaming_format_uint(c, std::uint64_t(index) + 1);
          *c++ = ' ';
          std::memcpy(c, xy, n);
          c += n;
          *c++ = '\n';
        } else {
          std::memcpy(c, xy, n);
          c += n;
          std::memcpy(c, " 0\n", 3);
          c += 3;
        }
        f.commit(c);
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
    const internal::Streaming_recorded_state s = internal::streaming_read_state(r);
    std::unique_ptr<Streaming_mesh_writer> w(new Streaming_mesh_writer(s.names, Resume_tag()));
    w->check_recorded_counts(r, s);
    // Everything is checked before anything is truncated, so that a failed
    // resume leaves the files as it found them.
    for(std::size_t i = 0; i < w->outputs_.size(); ++i)
      for(int k = 0; k < 2; ++k)
        check_partial_file(s.files[i][k].first, s.files[i][k].second);
    w->truncate_and_reopen(s.files);
    w->nv_ = s.nv;
    w->nt_ = s.nt;
    w->xmin_ = s.bbox[0]; w->ymin_ = s.bbox[1];
    w->xmax_ = s.bbox[2]; w->ymax_ = s.bbox[3];
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

  // The counts of a state against each other and against the sizes of the
  // files, which cannot hold more than a line of the shortest kind per
  // vertex or triangle; the names of the files against those of the outputs.
  void check_recorded_counts(const internal::Streaming_state_reader& r,
                             const internal::Streaming_recorded_state& s) const
  {
    const std::size_t nv = s.nv, nt = s.nt;
    if(nt != 0 && nv == 0)
      r.corrupt("triangles without vertices");
    if(nv != 0 && !(s.bbox[0] <= s.bbox[2] && s.bbox[1] <= s.bbox[3]))
      r.corrupt("empty bounding box");
    for(std::size_t i = 0; i < outputs_.size(); ++i) {
      const internal::Streaming_output& o = *outputs_[i];
      const internal::Streaming_file* mine[2] = {&o.vertices, &o.triangles};
      for(int k = 0; k < 2; ++k) {
        if(s.files[i][k].first != mine[k]->path())
          r.corrupt("file " + s.files[i][k].first + " is not one of output " + o.name);
        const std::uint64_t size = s.files[i][k].second;
        const std::uint64_t header = internal::streaming_header_size(o.format, k == 1);
        const std::uint64_t count = (k == 0) ? nv : nt;
        if(size < header ||
           count > (size - header) / internal::streaming_min_line(o.format, k == 1))
          r.corrupt("size " + std::to_string(size) + " of " + mine[k]->path() +
                    " cannot hold " + std::to_string(count) +
                    (k == 0 ? " vertices" : " triangles"));
      }
    }
  }

  // Cuts every file back to its size at the checkpoint and continues it.
  void truncate_and_reopen(
    const std::vector<std::array<std::pair<std::string, std::uint64_t>, 2> >& files)
  {
    for(std::size_t i = 0; i < outputs_.size(); ++i) {
      internal::Streaming_output& o = *outputs_[i];
      internal::Streaming_file* mine[2] = {&o.vertices, &o.triangles};
      for(int k = 0; k < 2; ++k) {
        std::error_code ec;
        std::filesystem::resize_file(mine[k]->path(), files[i][k].second, ec);
        if(ec)
          throw std::runtime_error("cannot write " + mine[k]->path());
        mine[k]->append(files[i][k].second);
      }
    }
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

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_STREAMING_MESH_WRITER_H
