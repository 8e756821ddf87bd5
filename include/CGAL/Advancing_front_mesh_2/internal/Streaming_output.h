// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STREAMING_OUTPUT_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STREAMING_OUTPUT_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Finished_faces_check.h>
#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Size_bound.h>
#include <CGAL/Advancing_front_mesh_2/internal/Streaming_state.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Section 4 of Mavriplis (1992): the finished triangles go to the sink and
// leave memory, so that it holds only the triangles near the front.
//
// A triangle can only be broken by a point inside its circle. Points are
// placed ahead of the front, but a point's cavity may remove the front
// triangles behind a thin unmeshed gap, and the point then lands where the
// mesh was: up to about the placement distance (at most twice the target
// circumradius) behind the front. A triangle is taken for finished (see
// sweep()) when the disk about its circumcentre of radius `finished_margin`
// times its circumradius plus `placement_margin` times the target
// circumradius at its centroid meets no front edge and holds no free point,
// and its neighbours' disks are as clear. (With the first term alone, a
// 100M-triangle run had 2 points inside finished triangles' circles, both
// placed past a thin gap.) A point whose cavity reaches a finished triangle
// all the same is refused (Cavity.h).
template <class Front, class Sizing_bound, class Visitor>
class Streaming_output
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Vertex_handle Vertex_handle;
  typedef typename Front::Face_handle Face_handle;
  typedef typename Front::Point Point;
  typedef typename Context::Tds_face Tds_face;
  typedef typename Context::Phase_scope Phase_scope;
  typedef Streaming_state<Context> Stream;
  static constexpr double finished_margin = 2.0;
  static constexpr double placement_margin = 2.0;

  Streaming_output(Context& ctx, const Front& front, Stream& stream, Sizing_bound& size, Visitor& visitor)
    : ctx_(ctx), front_(front), stream_(stream), size_(size), visitor_(visitor) {}

  bool is_due() const { return stream_.created_since_sweep >= stream_.sweep_after; }
  void sweep(bool everything);
  void finish();

private:
  bool front_meets_disk(double cx, double cy, double radius) const;
  bool is_clear_of_front(Face_handle f);
  std::size_t output_vertex(Vertex_handle v);
  void hand_to_sink(const std::vector<Face_handle>& faces);
  void unlink(const std::vector<Face_handle>& faces);
  void drop(std::vector<Face_handle>& faces);
  void check_delaunay(std::vector<Face_handle>& faces);

  Context& ctx_;
  const Front& front_;
  Stream& stream_;
  Sizing_bound& size_;
  Visitor& visitor_;
  Flat_hash_map<const Tds_face*, bool> near_front_{nullptr}, batch_{nullptr};
};

// Is any front edge or active vertex within `radius` of (cx, cy)?
template <class Front, class S, class V>
bool Streaming_output<Front, S, V>::front_meets_disk(double cx, double cy, double radius) const
{
  bool meets = false;
  const double pad = 1e-9 * radius + 1e-12 * (std::abs(cx) + std::abs(cy));
  front_.active_points.query_with_reach(cx, cy, radius, [&](std::size_t id, double px, double py, bool in_disk) {
    if(meets) return;
    if(in_disk) {
      meets = true;
      return;
    }
    // a hub's reach covers its incoming edges too, which their sources'
    // reach does not (Front_2::update_reach())
    const bool hub = front_.is_hub(Vid(id));
    for(const auto* ends : {&front_.out[Vid(id)], hub ? &front_.in[Vid(id)] : nullptr}) {
      if(ends == nullptr) continue;
      for(Vid h : *ends)
        if(!(segment_distance(cx, cy, px, py, front_.x(h), front_.y(h)) > radius + pad)) {
          meets = true;
          return;
        }
    }
  });
  return meets;
}

template <class Front, class S, class V>
bool Streaming_output<Front, S, V>::is_clear_of_front(Face_handle f)
{
  if(front_.is_front_triangle(f)) return false;
  const Circle c = ctx_.circle_of(f);
  if(!(std::isfinite(c.cx) && std::isfinite(c.cy) && std::isfinite(c.r))) return false;
  // at the centroid, which lies in the domain (the circumcentre may not)
  double gx = 0, gy = 0;
  for(int i = 0; i < 3; ++i) {
    gx += ctx_.ix(f->vertex(i)->point()) / 3;
    gy += ctx_.iy(f->vertex(i)->point()) / 3;
  }
  return !front_meets_disk(c.cx, c.cy,
                           finished_margin * c.r + placement_margin * size_.target_circumradius(gx, gy, OUTPUT));
}

template <class Front, class S, class V>
std::size_t Streaming_output<Front, S, V>::output_vertex(Vertex_handle v)
{
  if(const std::uint64_t* id = stream_.output_id.find(&*v)) return std::size_t(*id);
  const std::size_t id = stream_.vertices_output++;
  stream_.output_id.insert(&*v, id);
  stream_.sink->add_vertex(id, v->point());
  return id;
}

// Hands the finished faces to the sink, in an order that depends only on
// their coordinates (not on addresses).
template <class Front, class S, class V>
void Streaming_output<Front, S, V>::hand_to_sink(const std::vector<Face_handle>& faces)
{
  struct Keyed
  {
    std::array<double, 6> key;
    Face_handle face;
    int first;
  };
  std::vector<Keyed> keyed;
  keyed.reserve(faces.size());
  for(Face_handle f : faces) {
    // rotated to start at the lexicographically smallest vertex
    int first = 0;
    for(int i = 1; i < 3; ++i) {
      const Point& p = f->vertex(i)->point();
      const Point& q = f->vertex(first)->point();
      if(ctx_.ix(p) < ctx_.ix(q) || (ctx_.ix(p) == ctx_.ix(q) && ctx_.iy(p) < ctx_.iy(q))) first = i;
    }
    Keyed k;
    k.face = f;
    k.first = first;
    for(int i = 0; i < 3; ++i) {
      k.key[2 * i] = ctx_.ix(f->vertex((first + i) % 3)->point());
      k.key[2 * i + 1] = ctx_.iy(f->vertex((first + i) % 3)->point());
    }
    keyed.push_back(k);
  }
  std::sort(keyed.begin(), keyed.end(), [](const Keyed& a, const Keyed& b) { return a.key < b.key; });
  for(const Keyed& k : keyed) {
    visitor_.on_face_finished(k.face);
    std::array<std::size_t, 3> ids;
    for(int i = 0; i < 3; ++i) ids[i] = output_vertex(k.face->vertex((k.first + i) % 3));
    stream_.sink->add_finished_triangle(ids[0], ids[1], ids[2], k.face->vertex(k.first)->point(),
                                        k.face->vertex((k.first + 1) % 3)->point(),
                                        k.face->vertex((k.first + 2) % 3)->point());
    ++stream_.triangles_output;
  }
}

// All links to the finished faces are cut before any face is deleted (a
// deleted face's slot is reused, and a stale link could then name a new
// face).
template <class Front, class S, class V>
void Streaming_output<Front, S, V>::unlink(const std::vector<Face_handle>& faces)
{
  batch_.clear();
  for(Face_handle f : faces) batch_.insert(&*f, true);
  for(Face_handle f : faces) {
    for(int k = 0; k < 3; ++k) {
      Face_handle g = f->neighbor(k);
      if(g == stream_.ghost) {
        stream_.ghost_apex.erase(std::make_pair(&*f->vertex(Context::ccw(k)), &*f->vertex(Context::cw(k))));
      } else if(g == Face_handle() || batch_.find(&*g) != nullptr) {
        continue;
      } else if(g->is_in_domain()) {
        // a face that stays: its edge now faces a finished triangle, whose
        // apex is kept to tell whether a cavity reaches it
        const int j = g->index(f);
        g->set_neighbor(j, stream_.ghost);
        stream_.ghost_apex[std::make_pair(&*g->vertex(Context::ccw(j)), &*g->vertex(Context::cw(j)))] =
          f->vertex(k)->point();
      } else {
        // a face outside the domain: it never links to the mesh again
        g->set_neighbor(g->index(f), Face_handle());
      }
    }
  }
  batch_.clear();
  batch_.shrink_if_sparse();
}

// Hands the finished faces to the sink and removes them and the vertices
// left without triangles.
template <class Front, class S, class V>
void Streaming_output<Front, S, V>::drop(std::vector<Face_handle>& faces)
{
  hand_to_sink(faces);
  unlink(faces);
  for(Face_handle f : faces) {
    std::array<Vertex_handle, 3> vs = {{f->vertex(0), f->vertex(1), f->vertex(2)}};
    ctx_.tds().delete_face(f);
    --stream_.triangles_in_memory;
    for(Vertex_handle v : vs) {
      std::uint32_t* n = stream_.live_faces.find(&*v);
      if(n == nullptr || --*n != 0 || front_.id_of(v) != nullptr) continue;
      stream_.live_faces.erase(&*v);
      stream_.output_id.erase(&*v);
      ctx_.tds().delete_vertex(v);
    }
  }
  stream_.live_faces.shrink_if_sparse();
  stream_.output_id.shrink_if_sparse();
}

// There is no final Lawson pass in streaming mode: the finished faces are
// checked as they leave (Finished_faces_check.h), flipped among themselves,
// kept back when an edge to a face in memory is not Delaunay.
template <class Front, class S, class V>
void Streaming_output<Front, S, V>::check_delaunay(std::vector<Face_handle>& faces)
{
  const auto apex_beyond = [this](Vertex_handle s, Vertex_handle t) -> const Point* {
    const auto it = stream_.ghost_apex.find(std::make_pair(&*s, &*t));
    return it == stream_.ghost_apex.end() ? nullptr : &it->second;
  };
  const auto on_flip = [this](Vertex_handle a, Vertex_handle b, Vertex_handle c, Vertex_handle d) {
    for(Vertex_handle v : {a, b})
      if(std::uint32_t* n = stream_.live_faces.find(&*v)) --*n;
    for(Vertex_handle v : {c, d})
      if(std::uint32_t* n = stream_.live_faces.find(&*v)) ++*n;
  };
  const Finished_faces_check found =
    check_finished_faces(ctx_.tr, ctx_.pred, faces, stream_.ghost, apex_beyond, on_flip);
  ctx_.stats.delaunay_repair_flips += found.flips;
  ctx_.stats.finished_triangles_held += found.held;
  ctx_.stats.finished_edges_not_delaunay += found.unrepaired;
}

// Searches the triangles in memory for finished ones (all of them, with
// `everything`) and drops them.
template <class Front, class S, class V>
void Streaming_output<Front, S, V>::sweep(bool everything)
{
  Phase_scope phase(ctx_.timer, OUTPUT);
  ++ctx_.stats.stream_sweeps;
  std::vector<Face_handle> kept, finished;
  near_front_.clear();
  // the container itself: faces_begin() is empty below dimension 2, which a
  // resumed run's triangulation keeps
  for(auto f = ctx_.tds().faces().begin(); f != ctx_.tds().faces().end(); ++f) {
    Face_handle fh = f;
    if(fh == stream_.ghost || !fh->is_in_domain()) continue;
    kept.push_back(fh);
    if(!everything && !is_clear_of_front(fh)) near_front_.insert(&*fh, true);
  }
  // A triangle goes only when its neighbours are clear of the front too: a
  // cavity can only open a triangle next to one whose circle a new point
  // breaks, and a neighbour with a large circle (a closure that the size
  // bound could not prevent) reaches far ahead.
  for(Face_handle f : kept) {
    bool done = near_front_.find(&*f) == nullptr;
    for(int k = 0; done && k < 3; ++k) {
      Face_handle g = f->neighbor(k);
      if(g != Face_handle() && g != stream_.ghost && g->is_in_domain() && near_front_.find(&*g) != nullptr)
        done = false;
    }
    if(done) finished.push_back(f);
  }
  near_front_.clear();
  near_front_.shrink_if_sparse();
  check_delaunay(finished);
  drop(finished);
  stream_.created_since_sweep = 0;
  // after as many new triangles as stayed in memory, so that each is tested
  // a bounded number of times on average
  stream_.sweep_after = (std::max)(stream_.triangles_in_memory, stream_.minimum_sweep);
}

// The end of a streamed run: every remaining triangle goes to the sink, and
// the triangulation is left empty.
template <class Front, class S, class V>
void Streaming_output<Front, S, V>::finish()
{
  sweep(true);
  stream_.ghost_apex.clear();
  stream_.live_faces.clear();
  stream_.output_id.clear();
  stream_.ghost = Face_handle();
  ctx_.tr.clear();
  ctx_.stats.number_of_faces = stream_.triangles_output;
  ctx_.stats.number_of_vertices = stream_.vertices_output;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STREAMING_OUTPUT_H
