// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STREAMING_STATE_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STREAMING_STATE_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Mesh_sink_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>
#include <CGAL/Advancing_front_mesh_2/internal/Refinement_context.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <utility>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// What the mesh in memory knows of streaming (section 4 of Mavriplis 1992;
// the sweeps are in Streaming_output.h): the sink, the ghost face that
// stands for the finished faces beyond an edge, and the counts that tell
// when a vertex may leave memory. Without a sink only the count of the
// triangles in memory is kept.
template <class Context>
class Streaming_state
{
public:
  typedef typename Context::Point Point;
  typedef typename Context::Vertex_handle Vertex_handle;
  typedef typename Context::Face_handle Face_handle;
  typedef typename Context::Tds_vertex Tds_vertex;
  typedef typename Context::Tds_face Tds_face;
  typedef Mesh_sink_2<Point> Mesh_sink;
  typedef std::pair<const Tds_vertex*, const Tds_vertex*> Vertex_pair;

  bool is_streaming() const { return sink != nullptr; }

  void clear()
  {
    ghost = Face_handle();
    ghost_apex.clear();
    live_faces.clear();
    output_id.clear();
    vertices_output = 0;
    triangles_output = 0;
    triangles_in_memory = 0;
    created_since_sweep = 0;
    sweep_after = minimum_sweep;
  }

  // a face with these vertices was created or removed
  void on_face_created(const Tds_vertex* a, const Tds_vertex* b, const Tds_vertex* c)
  {
    ++created_since_sweep;
    for(const Tds_vertex* v : {a, b, c})
      if(std::uint32_t* n = live_faces.find(v)) ++*n;
  }
  void on_face_removed(const Tds_vertex* a, const Tds_vertex* b, const Tds_vertex* c)
  {
    for(const Tds_vertex* v : {a, b, c})
      if(std::uint32_t* n = live_faces.find(v)) --*n;
  }

  // Is a finished face beyond edge k of f, a face of p's cavity? (Not the
  // outside, which stands behind the ghost after a restart.) Counts in
  // `broken` the finished faces the mesher without streaming would have
  // broken: their circle holds p and the walk would cross the edge.
  bool is_finished_face_beyond(Face_handle f, int k, const Point& p, std::size_t& broken, Context& ctx) const
  {
    const Vertex_handle s = f->vertex(Context::ccw(k)), t = f->vertex(Context::cw(k));
    const auto it = ghost_apex.find(std::make_pair(&*s, &*t));
    if(it == ghost_apex.end()) return false;
    if(!f->is_constrained(k)) {
      ++ctx.stats.incircle_tests;
      if(ctx.pred.strictly_inside_circle(t->point(), s->point(), it->second, p)) ++broken;
    }
    return true;
  }

  struct Vertex_pair_hash
  {
    std::size_t operator()(const Vertex_pair& e) const
    {
      return std::hash<const void*>()(e.first) * 31 + std::hash<const void*>()(e.second);
    }
  };

  Mesh_sink* sink = nullptr;
  Face_handle ghost; // stands for the finished faces beyond an edge
  // the apex of the finished face beyond each edge of a face in memory, by
  // the edge's end points as they run in that face
  std::unordered_map<Vertex_pair, Point, Vertex_pair_hash> ghost_apex;
  // the vertices the mesher created, with their number of faces in memory
  Flat_hash_map<const Tds_vertex*, std::uint32_t> live_faces{nullptr};
  // the sink's numbers of the vertices already written that are still in memory
  Flat_hash_map<const Tds_vertex*, std::uint64_t> output_id{nullptr};
  std::size_t vertices_output = 0, triangles_output = 0;
  std::size_t triangles_in_memory = 0; // also without streaming
  std::size_t minimum_sweep = 4096;
  std::size_t created_since_sweep = 0, sweep_after = 4096;
};

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STREAMING_STATE_H
