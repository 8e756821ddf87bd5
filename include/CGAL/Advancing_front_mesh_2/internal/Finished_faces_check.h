// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FINISHED_FACES_CHECK_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FINISHED_FACES_CHECK_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// What check_finished_faces() found.
struct Finished_faces_check
{
  std::size_t flips = 0;     // edges between two finished faces flipped (repaired)
  std::size_t held = 0;      // faces kept back: an edge to a face in memory is not Delaunay
  std::size_t unrepaired = 0; // edges to a face already written that are not Delaunay
};

// Flips the edge i of f, whose faces f and n = f->neighbor(i) form a convex
// quadrilateral (a pair that is not Delaunay does), as the triangulation
// data structure's flip() does, and carries the constraint marks of the
// quadrilateral's sides along. Unlike it, leaves alone an outer neighbour
// that is no face or the `ghost` (which stands for faces gone to the sink
// and has no links of its own).
template <class Face_handle>
void flip_in_memory(Face_handle f, int i, Face_handle ghost)
{
  auto ccw = [](int k) { return (k + 1) % 3; };
  auto cw = [](int k) { return (k + 2) % 3; };
  Face_handle n = f->neighbor(i);
  const int ni = n->index(f);
  Face_handle tr = f->neighbor(ccw(i)), bl = n->neighbor(ccw(ni));
  const bool tr_constrained = f->is_constrained(ccw(i)), bl_constrained = n->is_constrained(ccw(ni));
  const int tri = (tr != Face_handle() && tr != ghost) ? tr->index(f) : -1;
  const int bli = (bl != Face_handle() && bl != ghost) ? bl->index(n) : -1;
  auto v_cw = f->vertex(cw(i));
  auto v_ccw = f->vertex(ccw(i));
  f->set_vertex(cw(i), n->vertex(ni));
  n->set_vertex(cw(ni), f->vertex(i));
  f->set_neighbor(i, bl);
  f->set_constraint(i, bl_constrained);
  if(bli >= 0) bl->set_neighbor(bli, f);
  f->set_neighbor(ccw(i), n);
  f->set_constraint(ccw(i), false);
  n->set_neighbor(ccw(ni), f);
  n->set_constraint(ccw(ni), false);
  n->set_neighbor(ni, tr);
  n->set_constraint(ni, tr_constrained);
  if(tri >= 0) tr->set_neighbor(tri, n);
  if(v_cw->face() == f) v_cw->set_face(n);
  if(v_ccw->face() == n) v_ccw->set_face(f);
}

// Streaming mode has no final Lawson pass over the whole mesh (it is never
// in memory), so the faces about to go to the sink are checked here, each
// edge with the exact in-circle predicate, before they leave. The advancing
// front builds a constrained Delaunay triangulation by itself, so nothing is
// expected to be found; if something is, it is repaired where it can be and
// counted:
// - an edge between two of the faces is flipped, Lawson's way, among them;
// - a face whose edge to a face that stays in memory is not Delaunay stays
//   too (it is removed from `faces`): once both are finished, the flip
//   repairs them;
// - an edge to a face already written (`ghost` stands for it, and
//   `apex_beyond(s, t)` gives the apex of that face beyond the edge from s
//   to t, as the edge runs in the face in memory) cannot be repaired: it is
//   counted.
// Constrained edges are never tested (a constrained Delaunay triangulation
// may have non-Delaunay pairs across them). `on_flip(a, b, c, d)` is
// called at each flip with the vertices of the flipped edge, which lose a
// face each, and the two others, which gain one, so that the caller can
// keep its counts of faces per vertex.
template <class Tr, class Predicates, class Apex_beyond, class On_flip>
Finished_faces_check check_finished_faces(Tr& tr, const Predicates& pred, std::vector<typename Tr::Face_handle>& faces,
                                          typename Tr::Face_handle ghost, const Apex_beyond& apex_beyond,
                                          const On_flip& on_flip)
{
  typedef typename Tr::Face_handle Face_handle;
  typedef typename Tr::Tds::Face Tds_face;
  Finished_faces_check result;
  Flat_hash_map<const Tds_face*, bool> batch{nullptr};
  for(Face_handle f : faces) batch.insert(&*f, true);
  auto in_batch = [&batch](Face_handle g) { return g != Face_handle() && batch.find(&*g) != nullptr; };
  // is the apex of g beyond edge i of f strictly inside f's circle?
  auto breaks = [&pred](Face_handle f, const typename Tr::Point& q) {
    return pred.strictly_inside_circle(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point(), q);
  };
  // Lawson's flips among the faces: a flip keeps both faces in the batch
  std::vector<std::pair<Face_handle, int> > stack;
  for(Face_handle f : faces)
    for(int i = 0; i < 3; ++i)
      if(in_batch(f->neighbor(i)) && &*f->neighbor(i) < &*f) stack.emplace_back(f, i);
  while(!stack.empty()) {
    Face_handle f = stack.back().first;
    const int i = stack.back().second;
    stack.pop_back();
    Face_handle g = f->neighbor(i);
    if(f->is_constrained(i) || !in_batch(g)) continue;
    if(!breaks(f, g->vertex(g->index(f))->point())) continue;
    on_flip(f->vertex(Tr::ccw(i)), f->vertex(Tr::cw(i)), f->vertex(i), g->vertex(g->index(f)));
    flip_in_memory(f, i, ghost);
    ++result.flips;
    for(Face_handle h : {f, g})
      for(int k = 0; k < 3; ++k)
        if(h->neighbor(k) != f && h->neighbor(k) != g && in_batch(h->neighbor(k))) stack.emplace_back(h, k);
  }
  // the edges to faces beyond the batch
  std::vector<Face_handle> kept;
  kept.reserve(faces.size());
  for(Face_handle f : faces) {
    bool hold = false;
    for(int i = 0; i < 3; ++i) {
      const Face_handle g = f->neighbor(i);
      if(f->is_constrained(i) || g == Face_handle() || in_batch(g)) continue;
      if(g == ghost) {
        const auto* apex = apex_beyond(f->vertex(Tr::ccw(i)), f->vertex(Tr::cw(i)));
        if(apex != nullptr && breaks(f, *apex)) ++result.unrepaired;
      } else if(g->is_in_domain() && !tr.is_infinite(g) && breaks(f, g->vertex(g->index(f))->point())) {
        hold = true;
      }
    }
    if(hold) ++result.held;
    else kept.push_back(f);
  }
  faces.swap(kept);
  return result;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FINISHED_FACES_CHECK_H
