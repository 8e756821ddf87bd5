// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_STREAMING_TAGGING_SINK_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_STREAMING_TAGGING_SINK_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/IO/Streaming_mesh_writer.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Input_tags_2.h>
#include <CGAL/Advancing_front_mesh_2/IO/internal/Streaming_writer_state.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_sink_2.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {

/*!
\ingroup PkgAdvancingFrontMesh2IO

A `Mesh_sink_2` that gives the markers and regions of `Markers_and_regions_2`
to a `Streaming_mesh_writer` while the mesh is streamed, so that streamed
files carry them as `write_mesh()` writes them from a mesh in memory.

In streaming mode the mesh is never whole in memory, so the tags cannot be
found on it afterwards. They are found on the input instead, which the mesh
refines without changing its boundary: the sink keeps a copy of the input
triangulation (its constraints and in-domain marks as `insert_poly()` left
them, before meshing), whose size is that of the boundary, and
- a vertex gets the marker of the input vertex at its point (found by point
  location in the copy), 0 elsewhere: the mesher puts no vertex on a
  constraint that is not an input vertex;
- a triangle gets the attribute of the region of the input face its
  interior starts in: at its first vertex `a`, the face of the copy whose
  angle at `a` holds the direction of the triangle's first edge (or the
  face holding `a`, or the side of the edge holding it), decided with the
  kernel's orientation predicate only, so exactly with exact predicates;
- the segments are the constrained edges of the copy beside the domain,
  with the domain on their left (from the first domain face seen), given to
  the writer by `close()`.

The memory is that of the boundary, plus the writer's numbers of the input
vertices; the time, a point location per vertex and per triangle, each
starting from the face of the previous one.

\tparam CDT the triangulation type the input was inserted into
*/
template <class CDT>
class Streaming_tagging_sink_2 : public Mesh_sink_2<typename CDT::Point>
{
public:
  typedef typename CDT::Point Point;
  typedef Streaming_mesh_writer<Point> Writer;

  /*!
  Finds the tags on a copy of `input`, before it is meshed.

  \param input the input triangulation, as `insert_poly()` left it
  \param tags its markers and regions (regions need not be marked)
  */
  Streaming_tagging_sink_2(const CDT& input, const Markers_and_regions_2<CDT>& tags)
      : tags_(input, tags), written_(tags_.number_of_input_vertices(), none)
  {
  }

  /*!
  The options of a writer that takes everything this sink gives: markers,
  and the region attributes when there are regions (0 included, for
  triangles outside every region), with VTU arrays binary unless
  `use_binary_mode` is `false`.
  */
  Streaming_mesh_writer_options writer_options(bool use_binary_mode = true) const
  {
    Streaming_mesh_writer_options o;
    o.use_binary_mode = use_binary_mode;
    o.markers = true;
    o.region_attributes = tags_.attributes();
    return o;
  }

  /// the writer that receives everything; it must have `writer_options()` and outlive the meshing
  void set_writer(Writer* writer) { writer_ = writer; }

  /// the writer that receives everything, owned by the sink from now on
  void set_writer(std::unique_ptr<Writer> writer)
  {
    owned_writer_ = std::move(writer);
    writer_ = owned_writer_.get();
  }

  /// the writer
  Writer* writer() const { return writer_; }

  /// gives vertex `index` to the writer with the marker of the input vertex at `p` (0 if none)
  void add_vertex(std::size_t index, const Point& p) override
  {
    int marker = 0;
    const std::size_t ordinal = tags_.input_vertex_at(p);
    if(ordinal != Tags::none) {
      marker = tags_.marker(ordinal);
      written_[ordinal] = index;
    }
    writer_->add_vertex(index, p, marker);
  }

  /*!
  refuses: the region of a triangle needs its points (the mesher calls
  `add_finished_triangle()`).

  \throws std::logic_error always
  */
  void add_triangle(std::size_t, std::size_t, std::size_t) override
  {
    throw std::logic_error("Streaming_tagging_sink_2: triangles must come with their points");
  }

  /// gives the triangle to the writer with the attribute of its region
  void add_finished_triangle(std::size_t i, std::size_t j, std::size_t k, const Point& a, const Point& b,
                             const Point& c) override
  {
    writer_->add_triangle(i, j, k, tags_.has_regions() ? tags_.region_attribute(a, b, c) : 0.);
  }

  /*!
  The writer's state after the sink's own (the writer's numbers of the
  input vertices written so far).
  */
  std::string checkpoint_state() override
  {
    std::string s = magic();
    s += "vertices " + std::to_string(written_.size()) + "\n";
    for(std::size_t o = 0; o < written_.size(); ++o)
      if(written_[o] != none) s += std::to_string(o) + " " + std::to_string(written_[o]) + "\n";
    s += "end\n";
    return s + writer_->checkpoint_state();
  }

  /*!
  Continues at the checkpoint where `state` was returned by
  `checkpoint_state()` of a sink made from the same input: the sink is
  made again from `input` and `tags`, and its writer resumed (see
  `Streaming_mesh_writer::resume()`); the sink owns that writer.

  \throws std::invalid_argument "corrupt streaming writer state: ..." if
  `state` is damaged or was not made from this input
  \throws std::runtime_error as `Streaming_mesh_writer::resume()`
  */
  static std::unique_ptr<Streaming_tagging_sink_2> resume(const std::string& state, const CDT& input,
                                                          const Markers_and_regions_2<CDT>& tags)
  {
    std::unique_ptr<Streaming_tagging_sink_2> sink(new Streaming_tagging_sink_2(input, tags));
    internal::Streaming_state_reader r(state);
    r.expect(magic(), "the first line of a streaming tagging state");
    r.expect("vertices ", "'vertices'");
    if(r.read_size("number of input vertices") != sink->written_.size())
      r.corrupt("the state was not made from this input (another number of input vertices)");
    r.expect("\n", "end of line");
    std::size_t consumed = 0;
    for(;;) {
      if(r.try_expect("end\n")) break;
      const std::size_t o = r.read_size("input vertex");
      r.expect(" ", "space");
      const std::size_t index = r.read_size("vertex number");
      r.expect("\n", "end of line");
      if(o >= sink->written_.size() || sink->written_[o] != none) r.corrupt("bad input vertex");
      sink->written_[o] = index;
    }
    consumed = r.position();
    sink->owned_writer_ = Writer::resume(state.substr(consumed));
    sink->writer_ = sink->owned_writer_.get();
    for(std::size_t index : sink->written_)
      if(index != none && index >= sink->writer_->number_of_vertices())
        r.corrupt("an input vertex numbered beyond the vertices written");
    return sink;
  }

  /*!
  Gives the segments to the writer (every end point was written) and
  closes it.

  \throws std::logic_error if an end point of a segment was not written (the
  mesh was not finished)
  \throws std::runtime_error as `Streaming_mesh_writer::close()`
  */
  void close()
  {
    if(!segments_given_) {
      for(const typename Tags::Segment& s : tags_.segments()) {
        if(written_[s.a] == none || written_[s.b] == none)
          throw std::logic_error("Streaming_tagging_sink_2: a segment's end point was not written");
        writer_->add_segment(written_[s.a], written_[s.b], s.marker);
      }
      segments_given_ = true;
    }
    writer_->close();
  }

private:
  typedef internal::Input_tags_2<CDT> Tags;
  static constexpr std::size_t none = Tags::none;

  static const char* magic() { return "CGAL Advancing_front_mesh_2 Streaming_tagging_sink_2 state 1\n"; }

  internal::Input_tags_2<CDT> tags_;
  std::vector<std::size_t> written_; // per input vertex: the writer's number, or none
  bool segments_given_ = false;
  Writer* writer_ = nullptr;
  std::unique_ptr<Writer> owned_writer_;
};

} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_STREAMING_TAGGING_SINK_2_H
