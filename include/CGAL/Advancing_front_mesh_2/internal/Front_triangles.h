// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_TRIANGLES_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_TRIANGLES_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Streaming_state.h>

#include <CGAL/assertions.h>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The surgery on the triangulation data structure: a triangle made in the
// unmeshed region, or a mesh triangle removed, with the front updated to
// match. Only the faces behind the front exist while meshing.
template <class Front, class Visitor>
class Front_triangles
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Edge_key Edge_key;
  typedef typename Front::Front_edge Front_edge;
  typedef typename Front::Face_handle Face_handle;
  typedef typename Context::Phase_scope Phase_scope;
  typedef Streaming_state<Context> Stream;

  Front_triangles(Context& ctx, Front& front, Stream& stream, Visitor& visitor)
    : ctx_(ctx), front_(front), stream_(stream), visitor_(visitor) {}

  Face_handle make_triangle(Vid a, Vid b, Vid c, std::vector<Edge_key>* created = nullptr);
  void remove_triangle(Face_handle f, std::vector<Edge_key>* created);

  // the area meshed so far and the domain's, for the visitor's progress
  double meshed_area = 0, domain_area = 0;

private:
  void close_or_open_edges(Face_handle f, const std::array<Vid, 3>& vs, std::array<bool, 3>& consumed,
                           std::vector<Edge_key>* created);
  void reopen_edge(Face_handle f, int k, Vid s, Vid t, std::vector<Edge_key>* created);

  Context& ctx_;
  Front& front_;
  Stream& stream_;
  Visitor& visitor_;
};

// Creates the triangle (a, b, c), counter-clockwise, in the unmeshed
// region. Each of its edges either closes the front edge that faces it or
// becomes a new front edge facing the other way. Appends new front edges to
// `created` when given.
template <class Front, class Visitor>
typename Front::Face_handle
Front_triangles<Front, Visitor>::make_triangle(Vid a, Vid b, Vid c, std::vector<Edge_key>* created)
{
  CGAL_precondition(ctx_.pred.orientation(front_.point(a), front_.point(b), front_.point(c)) == LEFT_TURN);
  Phase_scope phase(ctx_.timer, FRONT_UPDATE);
  Face_handle f = ctx_.tds().create_face(front_.vertex[a], front_.vertex[b], front_.vertex[c]);
  f->set_in_domain(true);
  ++stream_.triangles_in_memory;
  ctx_.stats.largest_triangles_in_memory =
    (std::max)(ctx_.stats.largest_triangles_in_memory, stream_.triangles_in_memory);
  if(stream_.is_streaming())
    stream_.on_face_created(&*front_.vertex[a], &*front_.vertex[b], &*front_.vertex[c]);
  const std::array<Vid, 3> vs = {{a, b, c}};
  // The triangle splits or joins loops of the front when it meets the
  // front in more than one piece: the pieces are its front edges, joined
  // through their end points, and the front vertices off those edges.
  std::array<bool, 3> on_front, consumed;
  for(int k = 0; k < 3; ++k) on_front[k] = front_.is_on_front(vs[k]);
  close_or_open_edges(f, vs, consumed, created);
  const int edges_met = int(consumed[0]) + int(consumed[1]) + int(consumed[2]);
  int pieces = (edges_met > 0) ? 1 : 0;
  for(int k = 0; k < 3; ++k)
    // vertex k is off the met edges when the edges at it (k+1 and k+2) were not met
    if(on_front[k] && !consumed[Context::ccw(k)] && !consumed[Context::cw(k)]) ++pieces;
  if(pieces > 1) front_.loops_changed = true;
  for(Vid v : vs) {
    front_.vertex[v]->set_face(f);
    // a vertex left without front edges now lies behind the front
    if(!front_.is_on_front(v)) front_.release_record(v);
  }
  meshed_area += std::abs(ctx_.triangle_area(f));
  visitor_.on_face_created(f);
  return f;
}

// Edge k of the new face f (opposite vs[k], directed vs[k+1] -> vs[k+2]
// with f on its left) closes the front edge it lies on, linking f to the
// face behind it, or becomes a front edge the other way.
template <class Front, class Visitor>
void Front_triangles<Front, Visitor>::close_or_open_edges(Face_handle f, const std::array<Vid, 3>& vs,
                                                          std::array<bool, 3>& consumed,
                                                          std::vector<Edge_key>* created)
{
  for(int k = 0; k < 3; ++k) {
    const Vid s = vs[Context::ccw(k)], t = vs[Context::cw(k)];
    const Front_edge* it = front_.find(Front::key(s, t));
    consumed[k] = it != nullptr;
    if(it != nullptr) {
      const Front_edge fe = *it;
      f->set_constraint(k, fe.constrained);
      if(fe.behind != Face_handle()) {
        f->set_neighbor(k, fe.behind);
        if(fe.behind != stream_.ghost) fe.behind->set_neighbor(fe.behind_index, f);
      } else {
        f->set_neighbor(k, Face_handle());
        // a virgin side of a constraint: the other side now faces f
        Front_edge* rev = front_.find(Front::key(t, s));
        if(rev != nullptr) {
          rev->behind = f;
          rev->behind_index = k;
          front_.count_edge_behind(f);
        }
      }
      front_.remove_edge(s, t);
    } else {
      f->set_constraint(k, false);
      f->set_neighbor(k, Face_handle());
      front_.add_edge(t, s, f, k, false, vs[k]);
      if(created) created->push_back(Front::key(t, s));
    }
  }
}

// Removes a mesh face whose circle was broken. Its edges facing the
// remaining mesh (or the outside) become front edges; the front edges it
// had disappear into the unmeshed region, except constraints, which stay
// front edges on both sides.
template <class Front, class Visitor>
void Front_triangles<Front, Visitor>::remove_triangle(Face_handle f, std::vector<Edge_key>* created)
{
  Phase_scope phase(ctx_.timer, FRONT_UPDATE);
  visitor_.on_face_removed(f);
  std::array<Vid, 3> vs;
  for(int k = 0; k < 3; ++k) vs[k] = front_.activate(f->vertex(k));
  --stream_.triangles_in_memory;
  if(stream_.is_streaming()) stream_.on_face_removed(&*f->vertex(0), &*f->vertex(1), &*f->vertex(2));
  for(int k = 0; k < 3; ++k) reopen_edge(f, k, vs[Context::ccw(k)], vs[Context::cw(k)], created);
  meshed_area -= std::abs(ctx_.triangle_area(f));
  ctx_.tds().delete_face(f);
  // a vertex left without front edges has no triangle left either: it
  // stays active, as a free point
  ++ctx_.stats.triangles_removed;
}

// Edge k of the face f being removed, from s to t with f on its left.
template <class Front, class Visitor>
void Front_triangles<Front, Visitor>::reopen_edge(Face_handle f, int k, Vid s, Vid t,
                                                  std::vector<Edge_key>* created)
{
  Face_handle g = f->neighbor(k);
  const bool constrained = f->is_constrained(k);
  if(g == Face_handle()) {
    // the unmeshed region is beyond: front edge t -> s has f behind it
    CGAL_assertion(front_.contains(Front::key(t, s)));
    if(constrained) {
      Front_edge* rev = front_.find(Front::key(t, s));
      rev->behind = Face_handle();
      rev->behind_index = -1;
      front_.uncount_edge_behind(f);
      front_.add_edge(s, t, Face_handle(), -1, true);
      if(created) created->push_back(Front::key(s, t));
    } else {
      front_.remove_edge(t, s);
    }
  } else if(stream_.is_streaming() && g == stream_.ghost) {
    // beyond lies the outside after a restart, or a finished triangle
    // (then the cavity is put back, see Cavity.h)
    front_.add_edge(s, t, stream_.ghost, -1, constrained);
    if(created) created->push_back(Front::key(s, t));
  } else {
    const int j = g->index(f);
    g->set_neighbor(j, Face_handle());
    front_.add_edge(s, t, g, j, constrained);
    if(created) created->push_back(Front::key(s, t));
  }
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_TRIANGLES_H
