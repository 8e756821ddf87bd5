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
#include <CGAL/Advancing_front_mesh_2/IO/internal/Streaming_assembly.h>
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
#include <map>
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

What the outputs of a `Streaming_mesh_writer` hold beyond the mesh, and how
VTU arrays are encoded.
*/
struct Streaming_mesh_writer_options
{
  /// VTU arrays in binary (raw appended, as `write_mesh_VTU()`), or in ASCII when `false`
  bool use_binary_mode = true;
  /*!
  Whether the outputs carry boundary markers: a marker per vertex and the
  segments with their markers (`add_vertex()` and `add_segment()` with a
  marker), written as `write_mesh()` writes them with a
  `Markers_and_regions_2` object.
  */
  bool markers = false;
  /*!
  With `markers`: the region attributes the triangles may have (in any
  order; duplicates are ignored); empty for no regions. Triangles outside
  every region have attribute 0, which must then be listed.
  */
  std::vector<double> region_attributes;
};

/*!
\ingroup PkgAdvancingFrontMesh2IO

A `Mesh_sink_2` that writes the mesh to files while it is being generated,
in memory independent of the size of the mesh, so that meshes much larger
than the memory can be written; one writer feeds any number of outputs.

The format of each output is given by the extension of its name
(case-insensitive), with the same content as `write_mesh()`:
- `.off`: as `write_OFF()`;
- `.vtu`: as `write_mesh_VTU()`: binary unless
  `Streaming_mesh_writer_options::use_binary_mode` is `false`;
- `.node` or `.ele`: both `BASENAME.node` and `BASENAME.ele` (and
  `BASENAME.edge` with markers), as `write_triangle_node_ele()` except that
  the count of the first line is padded with spaces to 20 characters;
- `.msh`: as `write_gmsh_msh()`, the bounding box of the written vertices
  included. With markers, every entity has the bounding box of the whole
  mesh, and the triangles have element tags 1 to `nt` in the order they
  were received, the segments `nt + 1` on (a Gmsh reader takes element
  tags in any order).

Vertices and triangles are written in the order and with the numbers they
are received (0-based for OFF and VTU, 1-based for Triangle and Gmsh).
Coordinates are converted with `CGAL::to_double()` and written as the
shortest decimal that reads back to the same double (or as raw doubles in
binary VTU). With markers and regions (see `Streaming_mesh_writer_options`),
the files carry them as `write_mesh()` does with a `Markers_and_regions_2`
object; `Streaming_tagging_sink_2` finds them while the mesh is streamed.

Everything is first written to part files beside each output (`NAME.*.part`,
`BASENAME.node.part`, ...). `close()` makes each final file from them under
the name `FINAL.part` and renames it to its final name only when every
output is complete: an interrupted run leaves no half-written file under a
final name, and the constructor removes the final files of an earlier run,
so that a stale mesh cannot be taken for this one's.

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
  Creates the part files of every output (the `.node` and `.ele` ones with
  a provisional first line) and removes the final files of the outputs, so
  that a stale mesh from an earlier run cannot be taken for this one's;
  an unwritable destination is reported before the meshing.

  \param file_names the outputs; their format is given by their extension
  (see the class description)
  \param options what the outputs hold beyond the mesh, and the VTU encoding

  \throws std::invalid_argument if `file_names` is empty, if an extension is
  not one of `.off`, `.vtu`, `.node`, `.ele`, `.msh` (`.svg`, for one, needs
  the whole mesh), if two outputs would write the same file (such as
  `a.node` and `a.ele`), if a region attribute is not finite, or if
  regions are given without markers; no file is created then
  \throws std::runtime_error "cannot write FILE" if a file cannot be created
  or a final file cannot be removed
  */
  explicit Streaming_mesh_writer(const std::vector<std::string>& file_names,
                                 const Streaming_mesh_writer_options& options = Streaming_mesh_writer_options())
    : file_names_(file_names)
  {
    if(file_names.empty())
      throw std::invalid_argument("Streaming_mesh_writer: no output file given");
    content_.binary = options.use_binary_mode;
    content_.tagged = options.markers;
    content_.attributes = options.region_attributes;
    for(double a : content_.attributes)
      if(!std::isfinite(a))
        throw std::invalid_argument("Streaming_mesh_writer: a region attribute is not finite");
    std::sort(content_.attributes.begin(), content_.attributes.end());
    content_.attributes.erase(std::unique(content_.attributes.begin(), content_.attributes.end()),
                              content_.attributes.end());
    if(content_.has_regions() && !content_.tagged)
      throw std::invalid_argument("Streaming_mesh_writer: regions need markers (Streaming_mesh_writer_options::markers)");
    group_counts_.assign(content_.attributes.size(), 0);
    make_outputs();
    std::vector<std::string> created;
    for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
      for(const std::string& f : o->final_files(content_)) {
        std::error_code ec;
        if(std::filesystem::is_directory(f, ec))
          throw std::runtime_error("cannot write " + f + " (a directory)");
        std::filesystem::remove(f, ec);
        if(ec)
          throw std::runtime_error("cannot write " + f + " (cannot remove the file of an earlier run)");
      }
      for(const std::unique_ptr<internal::Streaming_part>& p : o->parts) {
        p->file.create();
        created.push_back(p->file.path());
      }
      if(o->format == internal::Streaming_format::NODE_ELE) {
        internal::streaming_put_count_line(o->vertices(), 0, node_tail());
        internal::streaming_put_count_line(o->triangles(), 0, ele_tail());
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

  /// writes vertex `index` with marker 0; see `add_vertex(std::size_t, const Point&, int)`
  void add_vertex(std::size_t index, const Point& p) override { add_vertex(index, p, 0); }

  /*!
  Writes vertex `index` to every output, with its boundary `marker` where
  the outputs carry markers (it is ignored otherwise).

  \pre `index` is the number of vertices written so far, and the coordinates
  converted to `double` are finite

  \throws std::logic_error if `index` is not the number of vertices written
  so far, or after `close()`
  \throws std::invalid_argument if a coordinate is not finite
  \throws std::runtime_error "cannot write FILE" on a write error; the writer
  then refuses everything (resume from the last checkpoint)
  */
  void add_vertex(std::size_t index, const Point& p, int marker)
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

    // "x y", formatted once for all text outputs
    char xy[2 * internal::text_max_double_chars + 1];
    char* e = internal::text_format_double(xy, x);
    *e++ = ' ';
    e = internal::text_format_double(e, y);
    const std::size_t n = static_cast<std::size_t>(e - xy);
    char mark[internal::text_max_uint_chars + 2];
    const std::size_t nm = static_cast<std::size_t>(std::to_chars(mark, mark + sizeof(mark), marker).ptr - mark);

    guarded([&] {
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
        internal::Streaming_file& f = o->vertices();
        if(o->format == internal::Streaming_format::VTU && content_.binary) {
          internal::streaming_put_raw(f, x); internal::streaming_put_raw(f, y); internal::streaming_put_raw(f, 0.);
          if(o->vertex_markers != nullptr) internal::streaming_put_raw(o->vertex_markers->file, std::int32_t(marker));
          continue;
        }
        char* c = f.reserve(2 * internal::text_max_uint_chars + n + 8);
        if(o->format == internal::Streaming_format::NODE_ELE) {
          c = internal::text_format_uint(c, std::uint64_t(index) + 1);
          *c++ = ' ';
          std::memcpy(c, xy, n);
          c += n;
          if(content_.tagged) {
            *c++ = ' ';
            std::memcpy(c, mark, nm);
            c += nm;
          }
          *c++ = '\n';
        } else {
          std::memcpy(c, xy, n);
          c += n;
          std::memcpy(c, " 0\n", 3);
          c += 3;
        }
        f.commit(c);
        if(o->vertex_markers != nullptr) internal::streaming_put_line(o->vertex_markers->file, mark, nm);
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

  /// writes triangle `(i, j, k)` with attribute 0; see `add_triangle(std::size_t, std::size_t, std::size_t, double)`
  void add_triangle(std::size_t i, std::size_t j, std::size_t k) override { add_triangle(i, j, k, 0.); }

  /*!
  Writes triangle `(i, j, k)` (counter-clockwise) to every output, with the
  attribute of its region where the outputs carry regions (it is ignored
  otherwise).

  \pre `i`, `j` and `k` are smaller than `number_of_vertices()`

  \throws std::logic_error if an index is not that of a vertex written
  before, or after `close()`
  \throws std::invalid_argument if the outputs carry regions and
  `attribute` is not one of `Streaming_mesh_writer_options::region_attributes`
  \throws std::runtime_error "cannot write FILE" on a write error; the writer
  then refuses everything (resume from the last checkpoint)
  */
  void add_triangle(std::size_t i, std::size_t j, std::size_t k, double attribute)
  {
    check_writable("add_triangle()");
    if(i >= nv_ || j >= nv_ || k >= nv_)
      throw std::logic_error("Streaming_mesh_writer: triangle (" + std::to_string(i) + ", " +
                             std::to_string(j) + ", " + std::to_string(k) +
                             ") uses a vertex not received yet (" + std::to_string(nv_) +
                             " vertices so far)");
    std::size_t group = 0;
    if(content_.has_regions()) {
      const auto it = std::lower_bound(content_.attributes.begin(), content_.attributes.end(), attribute);
      if(it == content_.attributes.end() || *it != attribute)
        throw std::invalid_argument("Streaming_mesh_writer: triangle " + std::to_string(nt_) +
                                    " has a region attribute that was not announced");
      group = static_cast<std::size_t>(it - content_.attributes.begin());
    }

    // "i j k" (0-based) and "t i j k" (1-based), each formatted once
    char zero[3 * (internal::text_max_uint_chars + 1)];
    char one[4 * (internal::text_max_uint_chars + 1) + internal::text_max_double_chars + 1];
    char* z = zero;
    char* w = internal::text_format_uint(one, std::uint64_t(nt_) + 1);
    for(std::size_t v : {i, j, k}) {
      if(z != zero)
        *z++ = ' ';
      z = internal::text_format_uint(z, v);
      *w++ = ' ';
      w = internal::text_format_uint(w, std::uint64_t(v) + 1);
    }
    *z++ = '\n';
    const std::size_t nz = static_cast<std::size_t>(z - zero);
    const std::size_t nw = static_cast<std::size_t>(w - one); // without the line end
    char attr[internal::text_max_double_chars + 1];
    const std::size_t na = static_cast<std::size_t>(internal::text_format_double(attr, attribute) - attr);

    guarded([&] {
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
        switch(o->format) {
        case internal::Streaming_format::OFF:
          o->triangles().put("3 ", 2);
          o->triangles().put(zero, nz);
          break;
        case internal::Streaming_format::VTU:
          if(content_.binary) {
            for(std::size_t v : {i, j, k}) internal::streaming_put_raw(o->triangles(), std::int64_t(v));
            if(o->triangle_attributes != nullptr) internal::streaming_put_raw(o->triangle_attributes->file, attribute);
          } else {
            o->triangles().put(zero, nz);
            if(o->triangle_attributes != nullptr) internal::streaming_put_line(o->triangle_attributes->file, attr, na);
          }
          break;
        case internal::Streaming_format::NODE_ELE:
          o->triangles().put(one, nw);
          if(content_.has_regions()) {
            o->triangles().put(" ", 1);
            o->triangles().put(attr, na);
          }
          o->triangles().put("\n", 1);
          break;
        case internal::Streaming_format::MSH:
          internal::streaming_put_line(o->triangles(o->triangle_parts > 1 ? group : 0), one, nw);
          break;
        }
      }
    });
    if(content_.has_regions()) ++group_counts_[group];
    ++nt_;
  }

  /*!
  Adds the segment from vertex `i` to vertex `j` with boundary `marker`,
  for the outputs that carry markers. Segments are kept in memory (a
  boundary is small beside its mesh) and written by `close()`, after the
  triangles; they are not part of a checkpoint, so give them after the
  last one, just before `close()` (as `Streaming_tagging_sink_2` does).

  \throws std::logic_error if the outputs carry no markers, if `i` or `j` is
  not a vertex written before, or after `close()`
  */
  void add_segment(std::size_t i, std::size_t j, int marker)
  {
    check_writable("add_segment()");
    if(!content_.tagged)
      throw std::logic_error("Streaming_mesh_writer: add_segment() on outputs without markers");
    if(i >= nv_ || j >= nv_)
      throw std::logic_error("Streaming_mesh_writer: segment (" + std::to_string(i) + ", " + std::to_string(j) +
                             ") uses a vertex not received yet (" + std::to_string(nv_) + " vertices so far)");
    segments_.push_back({{std::uint64_t(i), std::uint64_t(j)}});
    segment_markers_.push_back(marker);
  }

  /*!
  Flushes all files, makes them durable (`fsync()` where POSIX is
  available, `_commit()` on Windows) and returns the text `resume()`
  needs: a version line, the content options, the outputs as given, their
  part files with their sizes, the counts and the bounding box (as
  hexadecimal floating-point numbers). Names are written length-prefixed,
  so any character may appear in them.

  \throws std::logic_error after `close()`, or once segments were added
  \throws std::runtime_error "cannot write FILE" on a write error
  */
  std::string checkpoint_state() override
  {
    check_writable("checkpoint_state()");
    if(!segments_.empty())
      throw std::logic_error("Streaming_mesh_writer: checkpoint_state() after add_segment() (segments are "
                             "not part of a checkpoint: add them after the last one)");
    guarded([&] {
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_)
        for(const std::unique_ptr<internal::Streaming_part>& p : o->parts) p->file.sync();
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
      char b[internal::text_max_double_chars];
      s.append(b, std::to_chars(b, b + sizeof(b), v, std::chars_format::hex).ptr);
    };
    s += std::string("content ") + (content_.binary ? "1 " : "0 ") + (content_.tagged ? "1 " : "0 ") +
         std::to_string(content_.attributes.size());
    for(double a : content_.attributes) {
      s += ' ';
      put_double(a);
    }
    s += "\noutputs " + std::to_string(outputs_.size()) + "\n";
    for(const std::unique_ptr<internal::Streaming_output>& o : outputs_) {
      s += "output ";
      put_name(o->name);
      s += "\nfiles " + std::to_string(o->parts.size()) + "\n";
      for(const std::unique_ptr<internal::Streaming_part>& p : o->parts) {
        s += "file " + std::to_string(p->file.size()) + " ";
        put_name(p->file.path());
        s += "\n";
      }
    }
    s += "groups " + std::to_string(group_counts_.size());
    for(std::size_t c : group_counts_) s += " " + std::to_string(c);
    s += "\nvertices " + std::to_string(nv_) + "\n";
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
  returned by its `checkpoint_state()`: every part file is truncated to its
  size at the checkpoint and reopened for appending. Vertices and triangles
  are then to be passed again from number `number_of_vertices()` and
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
    std::unique_ptr<Streaming_mesh_writer> w(new Streaming_mesh_writer(s, Resume_tag()));
    w->check_recorded_counts(r, s);
    // Everything is checked before anything is truncated, so that a failed
    // resume leaves the files as it found them.
    for(std::size_t i = 0; i < w->outputs_.size(); ++i)
      for(std::size_t k = 0; k < s.files[i].size(); ++k)
        check_partial_file(*w->outputs_[i]->parts[k], s.files[i][k].second);
    w->truncate_and_reopen(s.files);
    w->nv_ = s.nv;
    w->nt_ = s.nt;
    w->group_counts_ = s.group_counts;
    w->xmin_ = s.bbox[0]; w->ymin_ = s.bbox[1];
    w->xmax_ = s.bbox[2]; w->ymax_ = s.bbox[3];
    return w;
  }

  /*!
  Finishes the output: closes the part files, makes each final file from
  them under a temporary name (`FINAL.part`), makes it durable, renames
  every one into place once all are complete and removes the part files.
  Does nothing when called again.

  If it fails before the renaming, the part files are kept (and no final
  file is written), so that the output can still be continued from the last
  checkpoint with `resume()`.

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
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_)
        for(const std::unique_ptr<internal::Streaming_part>& p : o->parts) p->file.close(false);
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_)
        finish(*o);
      // only now: until every output is complete, a resume needs them all
      std::vector<std::string> finals;
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_)
        for(const std::string& f : o->final_files(content_)) {
          std::error_code ec;
          std::filesystem::rename(internal::Streaming_output::temporary(f), f, ec);
          if(ec)
            throw std::runtime_error("cannot write " + f + " (" + ec.message() + ")");
          finals.push_back(f);
        }
      internal::streaming_sync_directories(finals);
      for(const std::unique_ptr<internal::Streaming_output>& o : outputs_)
        for(const std::unique_ptr<internal::Streaming_part>& p : o->parts) {
          std::error_code ec;
          std::filesystem::remove(p->file.path(), ec);
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
  Streaming_mesh_writer(const internal::Streaming_recorded_state& s, Resume_tag)
    : file_names_(s.names)
  {
    content_.binary = s.binary;
    content_.tagged = s.tagged;
    content_.attributes = s.attributes;
    try {
      make_outputs();
    } catch(const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("corrupt streaming writer state: ") + e.what());
    }
  }

  const char* node_tail() const
  {
    return content_.tagged ? internal::streaming_node_tagged_tail : internal::streaming_node_tail;
  }
  const char* ele_tail() const
  {
    return content_.has_regions() ? internal::streaming_ele_regions_tail : internal::streaming_ele_tail;
  }

  void make_outputs()
  {
    for(const std::string& name : file_names_)
      outputs_.push_back(internal::streaming_make_output(name, content_));
    internal::streaming_check_distinct(outputs_, content_);
  }

  // The counts of a state against each other and against the sizes of the
  // files, which cannot hold more than a line of the shortest kind per
  // vertex or triangle (binary parts: exactly a record each); the files
  // against those of the outputs.
  void check_recorded_counts(const internal::Streaming_state_reader& r,
                             const internal::Streaming_recorded_state& s) const
  {
    const std::size_t nv = s.nv, nt = s.nt;
    if(nt != 0 && nv == 0)
      r.corrupt("triangles without vertices");
    if(nv != 0 && !(s.bbox[0] <= s.bbox[2] && s.bbox[1] <= s.bbox[3]))
      r.corrupt("empty bounding box");
    std::uint64_t grouped = 0;
    for(std::size_t c : s.group_counts) grouped += c;
    if(!s.group_counts.empty() && grouped != nt)
      r.corrupt("the triangles of the groups do not add up to " + std::to_string(nt));
    for(std::size_t i = 0; i < outputs_.size(); ++i) {
      const internal::Streaming_output& o = *outputs_[i];
      if(s.files[i].size() != o.parts.size())
        r.corrupt("output " + o.name + " has " + std::to_string(o.parts.size()) + " part files, not " +
                  std::to_string(s.files[i].size()));
      std::size_t group = 0;
      for(std::size_t k = 0; k < o.parts.size(); ++k) {
        const internal::Streaming_part& p = *o.parts[k];
        if(s.files[i][k].first != p.file.path())
          r.corrupt("file " + s.files[i][k].first + " is not one of output " + o.name);
        const std::uint64_t size = s.files[i][k].second;
        std::uint64_t count = nv;
        if(p.count == internal::Streaming_count::TRIANGLES) count = nt;
        if(p.count == internal::Streaming_count::GROUP_TRIANGLES) count = s.group_counts[group++];
        const bool fits = size >= p.header &&
          (p.binary ? (size - p.header) / p.unit == count && (size - p.header) % p.unit == 0
                    : count <= (size - p.header) / p.unit);
        if(!fits)
          r.corrupt("size " + std::to_string(size) + " of " + p.file.path() + " does not fit " +
                    std::to_string(count) +
                    (p.count == internal::Streaming_count::VERTICES ? " vertices" : " triangles"));
      }
    }
  }

  // Cuts every file back to its size at the checkpoint and continues it.
  void truncate_and_reopen(const std::vector<std::vector<std::pair<std::string, std::uint64_t> > >& files)
  {
    for(std::size_t i = 0; i < outputs_.size(); ++i) {
      internal::Streaming_output& o = *outputs_[i];
      for(std::size_t k = 0; k < o.parts.size(); ++k) {
        internal::Streaming_file& f = o.parts[k]->file;
        std::error_code ec;
        std::filesystem::resize_file(f.path(), files[i][k].second, ec);
        if(ec)
          throw std::runtime_error("cannot write " + f.path());
        f.append(files[i][k].second);
      }
    }
  }

  static void check_partial_file(const internal::Streaming_part& p, std::uint64_t size)
  {
    const std::string& path = p.file.path();
    std::error_code ec;
    const std::uintmax_t actual = std::filesystem::file_size(path, ec);
    if(ec || actual < size)
      throw std::runtime_error("cannot resume the streaming output: " + path +
                               " is missing or shorter than at the checkpoint");
    if(size == 0 || p.binary)
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

  // The final files of `o`, under their temporary names (Streaming_assembly.h).
  void finish(internal::Streaming_output& o)
  {
    typedef internal::Streaming_format Format;
    const internal::Streaming_totals t{nv_, nt_, xmin_, ymin_, xmax_, ymax_,
                                       content_, segments_, segment_markers_, group_counts_};
    if(o.format == Format::NODE_ELE) {
      internal::streaming_finish_node_ele(o, t);
      return;
    }
    internal::Streaming_file out(internal::Streaming_output::temporary(o.name));
    out.create();
    if(o.format == Format::OFF) {
      out.put("OFF\n", 4);
      out.put_uint(nv_); out.put(" ", 1); out.put_uint(nt_); out.put(" 0\n", 3);
      internal::streaming_copy(out, o.vertices());
      internal::streaming_copy(out, o.triangles());
    } else if(o.format == Format::MSH) {
      if(content_.tagged) internal::streaming_write_tagged_msh(out, o, t);
      else internal::streaming_write_msh(out, o, t);
    } else {
      internal::streaming_write_vtu(out, o, t);
    }
    out.close(true);
  }


  std::vector<std::string> file_names_;
  internal::Streaming_content content_;
  std::vector<std::unique_ptr<internal::Streaming_output> > outputs_;
  std::vector<std::string> created_files_; // whose directory entries are not synced yet
  std::size_t nv_ = 0;
  std::size_t nt_ = 0;
  std::vector<std::size_t> group_counts_; // triangles per region attribute
  std::vector<std::array<std::uint64_t, 2> > segments_;
  std::vector<int> segment_markers_;
  double xmin_ = 0, ymin_ = 0, xmax_ = 0, ymax_ = 0;
  bool closing_ = false; // close() was called: nothing more may be added
  bool closed_ = false;  // close() succeeded
  bool failed_ = false;  // a write failed: the outputs disagree
};

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_STREAMING_MESH_WRITER_H
