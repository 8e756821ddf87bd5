// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Compact_id_list.h>
#include <CGAL/Advancing_front_mesh_2/internal/Double_geometry.h>
#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_hubs.h>
#include <CGAL/Advancing_front_mesh_2/internal/Refinement_context.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <queue>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The state of the advancing front (steps 1-2 of Mavriplis 1992): the
// records of the active vertices, the front edges, the queue that orders
// them, and the front triangles with their circles in the circle index
// (step 7 searches it). Everything else of the mesher reads and edits the
// front through this class.
//
// `PointIndex` models AdvancingFrontPointIndex_2 (the close points of step
// 4), `FaceCircleIndex` models AdvancingFrontCircleIndex_2 with face
// handles as payloads.
template <class Context_, class PointIndex, class FaceCircleIndex>
class Front_2
{
public:
  typedef Context_ Context;
  typedef typename Context::Point Point;
  typedef typename Context::Vertex_handle Vertex_handle;
  typedef typename Context::Face_handle Face_handle;
  typedef typename Context::Tds_vertex Tds_vertex;
  typedef typename Context::Tds_face Tds_face;
  typedef typename Context::Phase_scope Phase_scope;
  typedef PointIndex Point_index;
  typedef FaceCircleIndex Face_circle_index;

  // Vertex ids name the active vertices; an edge key is (source, target).
  typedef std::uint32_t Vid;
  typedef Front_hubs<Point, typename Context::Predicates> Hubs;
  typedef std::uint64_t Edge_key;
  static constexpr Vid no_vertex = (std::numeric_limits<Vid>::max)();

  static Edge_key key(Vid u, Vid v) { return (Edge_key(u) << 32) | Edge_key(v); }
  static Vid source(Edge_key k) { return Vid(k >> 32); }
  static Vid target(Edge_key k) { return Vid(k & 0xffffffffu); }

  // A front edge is directed with the unmeshed region on its left.
  struct Front_edge
  {
    Face_handle behind;  // face on the meshed side (mesh or outside face), null on a virgin side of a constraint
    int behind_index = -1;
    bool constrained = false;
    bool awaiting_queue = false; // created in this step, queued at its end (queue_created_edges())
    std::uint16_t level = 0; // pockets within pockets: see Pockets.h
    std::uint32_t version = 0;
  };

  // A front triangle: its item in the circle index and the number of front
  // edges it is behind.
  struct Face_record
  {
    std::size_t circle_item;
    int front_edges;
  };

  struct Queue_entry
  {
    Queue_entry(double len, Edge_key k, std::uint32_t v, std::uint16_t l)
      : length(len), key(k), version(v), level(l) {}
    double length;
    Edge_key key;
    std::uint32_t version;
    std::uint16_t level;
    bool operator<(const Queue_entry& o) const
    {
      // std::priority_queue is a max-heap: invert to pop the shortest edge,
      // the edges of the innermost pockets first; ties broken by age
      // (versions grow with creation, and when an edge is found on a
      // pocket), which does not depend on the reuse of vertex ids, so that
      // runs are deterministic
      if(level != o.level) return level < o.level;
      if(length != o.length) return length > o.length;
      return version > o.version;
    }
  };

  explicit Front_2(Context& ctx) : ctx_(ctx) {}

  void clear();

  // ---------------------------------------------------------- vertices
  const Point& point(Vid v) const { return vertex[v]->point(); }
  double x(Vid v) const { return xy[v][0]; }
  double y(Vid v) const { return xy[v][1]; }
  bool is_on_front(Vid v) const { return !out[v].empty() || !in[v].empty(); }
  const Vid* id_of(Vertex_handle vh) const { return ids.find(&*vh); }
  std::size_t number_of_active_vertices() const { return ids.size(); }

  Vid activate(Vertex_handle vh);
  void release_record(Vid v);
  void reuse_released_ids();

  // ------------------------------------------------------------- edges
  std::size_t size() const { return edges.size(); }
  bool empty() const { return edges.empty(); }
  bool contains(Edge_key k) const { return edges.contains(k); }
  const Front_edge* find(Edge_key k) const { return edges.find(k); }
  Front_edge* find(Edge_key k) { return edges.find(k); }
  double edge_length(Vid u, Vid v) const { return length(x(v) - x(u), y(v) - y(u)); }
  // the circle through three active vertices, and in `error` a bound on how
  // far its centre and radius may lie from the true circle's (rounding,
  // and the coordinates' own error when they are not exact)
  Circle circle_of(Vid a, Vid b, Vid c, double& error) const
  {
    error = 0;
    return ctx_.circle_through(x(a), y(a), x(b), y(b), x(c), y(c), &error);
  }
  bool is_front_segment(Vid u, Vid v) const;
  bool is_hub(Vid v) const { return hubs.contains(v); }

  void add_edge(Vid u, Vid v, Face_handle behind, int behind_index, bool constrained, Vid apex = no_vertex);
  void remove_edge(Vid u, Vid v);
  void push(Edge_key k, const Front_edge& fe) { queue.push(Queue_entry{edge_length(source(k), target(k)), k, fe.version, fe.level}); }
  void compact_queue();
  // the queue rebuilt once most of its entries are stale (compact_queue())
  void compact_queue_if_mostly_stale() { if(queue.size() > 2 * edges.size() + 1024) compact_queue(); }
  void queue_created_edges();

  // ---------------------------------------------------- front triangles
  void count_edge_behind(Face_handle f, Vid a = no_vertex, Vid b = no_vertex, Vid c = no_vertex);
  void uncount_edge_behind(Face_handle f);
  bool is_front_triangle(Face_handle f) const { return face_records.find(&*f) != nullptr; }

  // ------------------------------------------------------------- memory
  void release_unused_memory();
  bool is_valid(Face_handle ghost) const;
  bool reach_covers_edges() const;

  // The changes since the neighbourhood was gathered (Neighbourhood.h)
  // and in this step (Pockets.h).
  void start_change_log()
  {
    created_since_gather.clear();
    removed_since_gather.clear();
  }

  void rebuild_hubs();

private:
  void update_reach(Vid u);
  void update_hub(Vid v);
  void compact_vertex_ids();

  Context& ctx_;

public:
  // Only the active vertices have a record: an id, their coordinates, their
  // front edges and a place in the point index. A vertex is active while it
  // has front edges, or while no triangle touches it (a free point, or a
  // vertex whose triangles were all removed by a cavity). Behind the front a
  // vertex needs nothing, so its record is released and its id reused: the
  // records and the lookup of ids by vertex hold O(front) memory instead of
  // O(mesh), which was 60 bytes per triangle at 1M triangles.
  //
  // No triangle count is needed to tell the two kinds of vertices without
  // front edges apart: a vertex that loses its last front edge to a new
  // triangle belongs to that triangle (behind the front), and one that loses
  // it to a removed triangle keeps no triangle at all (a removed triangle's
  // edges at a vertex either become front edges, when a triangle lies beyond
  // them, or vanish, when the vertex's fan was that triangle alone).
  std::vector<Vertex_handle> vertex;
  std::vector<std::array<double, 2> > xy; // internal coordinates
  std::vector<Compact_id_list> out, in;   // targets of outgoing, sources of incoming front edges
  Flat_hash_map<const Tds_vertex*, Vid> ids{nullptr};
  std::vector<Vid> free_ids, released_ids;
  Point_index active_points; // the close-point search of step 4
  // The vertices with many front edges; their edges are reached through the
  // hub's reach and found by direction (Front_hubs.h), not through the
  // other end points' reach.
  Hubs hubs;

  // keyed by (source, target); the empty key is no real edge
  Flat_hash_map<Edge_key, Front_edge> edges{~Edge_key(0)};
  std::priority_queue<Queue_entry> queue;
  // Set during a step of the mesher: the edges it creates are queued at its
  // end, by queue_created_edges(), instead of when they are made. About a
  // third of them are closed again within the step (the fan about a new
  // point closes the edges its first triangle opened), and each entry of a
  // closed edge cost the heap a pop later. The order of the pops is that of
  // the entries' keys, which are distinct (the versions are), so it does not
  // depend on when they were pushed: the mesh is the same.
  bool defer_queueing = false;
  std::uint32_t version_counter = 0;
  std::size_t queue_compactions = 0;

  // A face enters the circle index with its first front edge and leaves it
  // with its last: the index holds exactly the front triangles.
  Flat_hash_map<const Tds_face*, Face_record> face_records{nullptr};
  Face_circle_index front_triangle_circles;

  // the level of the edge being processed, which the edges it creates
  // inherit (Pockets.h)
  std::uint16_t level = 0;
  bool loops_changed = false;             // this step split or joined loops of the front
  std::vector<Edge_key> created_this_step;
  std::vector<Edge_key> created_since_gather, removed_since_gather;
};

template <class C, class P, class F>
void Front_2<C, P, F>::clear()
{
  edges.clear();
  out.clear();
  in.clear();
  vertex.clear();
  xy.clear();
  ids.clear();
  free_ids.clear();
  released_ids.clear();
  face_records.clear();
  queue = std::priority_queue<Queue_entry>();
  defer_queueing = false;
  level = 0;
  loops_changed = false;
  created_this_step.clear();
  active_points.clear();
  hubs.clear();
}

// The id of a vertex, which becomes active if it was not.
template <class C, class P, class F>
typename Front_2<C, P, F>::Vid Front_2<C, P, F>::activate(Vertex_handle vh)
{
  if(const Vid* known = ids.find(&*vh)) return *known;
  const std::array<double, 2> p = {{ctx_.ix(vh->point()), ctx_.iy(vh->point())}};
  Vid id;
  if(!free_ids.empty()) {
    id = free_ids.back();
    free_ids.pop_back();
    vertex[id] = vh;
    xy[id] = p;
    CGAL_assertion(out[id].empty() && in[id].empty());
  } else {
    if(vertex.size() >= std::size_t(no_vertex) - 1)
      throw std::length_error("Advancing_front_mesher_2: too many active vertices");
    id = static_cast<Vid>(vertex.size());
    vertex.push_back(vh);
    xy.push_back(p);
    out.emplace_back();
    in.emplace_back();
  }
  ids.insert(&*vh, id);
  active_points.insert(id, p[0], p[1]);
  ctx_.stats.largest_active_vertices = (std::max)(ctx_.stats.largest_active_vertices, ids.size());
  return id;
}

// Releases the record of a vertex that now lies behind the front. Its id
// is reused from the next step on, not before: ids gathered in this step
// (the neighbourhood, the cavity) must keep naming the same vertex.
template <class C, class P, class F>
void Front_2<C, P, F>::release_record(Vid v)
{
  CGAL_precondition(out[v].empty() && in[v].empty());
  active_points.remove(v);
  ids.erase(&*vertex[v]);
  released_ids.push_back(v);
}

template <class C, class P, class F>
void Front_2<C, P, F>::reuse_released_ids()
{
  free_ids.insert(free_ids.end(), released_ids.begin(), released_ids.end());
  released_ids.clear();
}

// Is the segment u-v (vertex ids, or no_vertex for a new point) a front
// edge, in either direction?
template <class C, class P, class F>
bool Front_2<C, P, F>::is_front_segment(Vid u, Vid v) const
{
  if(u == no_vertex || v == no_vertex) return false;
  for(Vid w : out[u]) if(w == v) return true;
  for(Vid w : in[u]) if(w == v) return true;
  return false;
}

// `apex`, when known, is the vertex of `behind` opposite the edge: it
// spares the lookups of the face's vertex ids.
template <class C, class P, class F>
void Front_2<C, P, F>::add_edge(Vid u, Vid v, Face_handle behind, int behind_index, bool constrained, Vid apex)
{
  CGAL_assertion(!edges.contains(key(u, v)));
  Front_edge fe;
  fe.behind = behind;
  fe.behind_index = behind_index;
  fe.constrained = constrained;
  fe.level = level;
  fe.version = ++version_counter;
  fe.awaiting_queue = defer_queueing;
  const double len = edge_length(u, v);
  edges.insert(key(u, v), fe);
  created_since_gather.push_back(key(u, v));
  created_this_step.push_back(key(u, v));
  out[u].push_back(v);
  in[v].push_back(u);
  if(!hubs.empty()) {
    const auto point_of = [this](Vid w) -> const Point& { return point(w); };
    if(hubs.contains(u)) hubs.insert(u, v, true, point_of, ctx_.pred);
    if(hubs.contains(v)) hubs.insert(v, u, false, point_of, ctx_.pred);
  }
  // The edge is found through its source unless it enters a hub, and
  // through that hub in any case: a hub's reach covers all its edges, also
  // those from another hub (when the source stops being a hub, its reach
  // stops counting the edge).
  const bool into_hub = hubs.contains(v);
  if(into_hub && !(len <= active_points.reach(v))) active_points.set_reach(v, len);
  if((!into_hub || hubs.contains(u)) && !(len <= active_points.reach(u))) active_points.set_reach(u, len);
  if(out[u].size() == hubs.min_out_degree) update_hub(u);
  if(behind != Face_handle() && behind->is_in_domain()) count_edge_behind(behind, v, apex, u);
  if(!defer_queueing) {
    queue.push(Queue_entry{len, key(u, v), fe.version, fe.level});
    compact_queue_if_mostly_stale();
  }
  ctx_.stats.largest_front = (std::max)(ctx_.stats.largest_front, edges.size());
}

// The end of a step: the edges it created that are still on the front enter
// the queue (an edge created twice in the step is listed twice and queued
// once), and queueing is immediate again.
template <class C, class P, class F>
void Front_2<C, P, F>::queue_created_edges()
{
  defer_queueing = false;
  for(Edge_key k : created_this_step) {
    Front_edge* fe = edges.find(k);
    if(fe == nullptr || !fe->awaiting_queue) continue;
    fe->awaiting_queue = false;
    push(k, *fe);
  }
  compact_queue_if_mostly_stale();
}

// The queue keeps an entry of every front edge until it is popped, also of
// those closed before their turn (it cannot erase): rebuilt from the front
// when those are the majority, it holds O(front) entries instead of 15
// bytes per triangle of the mesh.
template <class C, class P, class F>
void Front_2<C, P, F>::compact_queue()
{
  // (within a step it would queue the edges awaiting the step's end twice)
  CGAL_precondition(!defer_queueing);
  std::vector<Queue_entry> live;
  live.reserve(edges.size());
  edges.for_each([this, &live](Edge_key k, const Front_edge& fe) {
    live.push_back(Queue_entry{edge_length(source(k), target(k)), k, fe.version, fe.level});
  });
  queue = std::priority_queue<Queue_entry>(std::less<Queue_entry>(), std::move(live));
  ++queue_compactions;
}

template <class C, class P, class F>
void Front_2<C, P, F>::remove_edge(Vid u, Vid v)
{
  const Front_edge* it = edges.find(key(u, v));
  CGAL_assertion(it != nullptr);
  const Front_edge fe = *it;
  edges.erase(key(u, v));
  // beyond 8 removals the neighbourhood probes the table: no need to list more
  if(removed_since_gather.size() <= 8) removed_since_gather.push_back(key(u, v));
  out[u].erase_value(v);
  in[v].erase_value(u);
  if(!hubs.empty()) {
    if(hubs.contains(u)) hubs.erase(u, v, true);
    if(hubs.contains(v)) hubs.erase(v, u, false);
  }
  if(out[u].size() + 1 == hubs.min_out_degree) update_hub(u);
  // a hub's reach is only lowered when it stops being one: recomputed at
  // every removal it cost the hub's degree each time
  if(!hubs.contains(u)) update_reach(u);
  if(fe.behind != Face_handle() && fe.behind->is_in_domain()) uncount_edge_behind(fe.behind);
}

// A front vertex's reach in the point index is the length of its longest
// outgoing front edge: a front edge meeting a disk of radius s about q has
// its source within s + its length of q, so the vertices found within s
// plus their reach lead, through their outgoing edges, to every front edge
// near the disk (see Neighbourhood.h). A hub reaches all its edges, also
// the incoming ones, and the other vertices do not count their edges into
// a hub: a star's spoke ends then leave the neighbourhoods near its centre
// alone.
template <class C, class P, class F>
void Front_2<C, P, F>::update_reach(Vid u)
{
  double reach = 0;
  const bool hub = hubs.contains(u);
  auto extend = [&](Vid w) {
    const double l = edge_length(u, w);
    reach = std::isnan(l) ? l : (std::max)(reach, l);
  };
  for(Vid w : out[u]) {
    if(hub || !hubs.contains(w)) extend(w);
    if(std::isnan(reach)) break;
  }
  if(hub)
    for(Vid w : in[u]) {
      if(std::isnan(reach)) break;
      extend(w);
    }
  active_points.set_reach(u, reach);
}

// Makes v a hub, or an ordinary vertex, as its out-degree now asks; the
// reach of v and of the sources of its incoming edges changes with it.
template <class C, class P, class F>
void Front_2<C, P, F>::update_hub(Vid v)
{
  const bool hub = out[v].size() >= hubs.min_out_degree;
  if(hub == hubs.contains(v)) return;
  if(hub)
    hubs.make(v, out[v], in[v], [this](Vid w) -> const Point& { return point(w); }, ctx_.pred);
  else
    hubs.unmake(v);
  update_reach(v);
  for(Vid s : in[v]) update_reach(s);
}

// The hubs from the front's edges (after the vertex ids changed, or a
// checkpoint was read). The reach of the other vertices was set for these
// hubs and is kept; a hub's reach is made to cover all its edges (a
// checkpoint of an older version may not have counted its incoming ones).
template <class C, class P, class F>
void Front_2<C, P, F>::rebuild_hubs()
{
  hubs.clear();
  for(Vid v = 0; v < out.size(); ++v) {
    if(out[v].size() < hubs.min_out_degree) continue;
    hubs.make(v, out[v], in[v], [this](Vid w) -> const Point& { return point(w); }, ctx_.pred);
    double reach = active_points.reach(v);
    for(const auto* ends : {&out[v], &in[v]})
      for(Vid w : *ends) {
        const double l = edge_length(v, w);
        if(!(l <= reach)) reach = l;
      }
    active_points.set_reach(v, reach);
  }
}

// Counts one more front edge with f behind it; its first enters f's circle
// in the circle index (computed from a, b, c when all three are given).
template <class C, class P, class F>
void Front_2<C, P, F>::count_edge_behind(Face_handle f, Vid a, Vid b, Vid c)
{
  Face_record* it = face_records.find(&*f);
  if(it != nullptr) {
    ++it->front_edges;
    return;
  }
  Phase_scope phase(ctx_.timer, CIRCLE_OCTREE);
  // the circle is stored grown by its rounding error bound, so that the
  // index's answers hold every circle a point truly breaks (the in-circle
  // predicate then decides)
  double error = 0;
  Circle circle;
  if(a != no_vertex && b != no_vertex && c != no_vertex) {
    circle = circle_of(a, b, c, error);
  } else {
    circle = ctx_.circle_of(f, &error);
  }
  face_records.insert(&*f, Face_record{front_triangle_circles.insert(circle.cx, circle.cy, circle.r + error, f), 1});
  ctx_.stats.largest_live_triangles = (std::max)(ctx_.stats.largest_live_triangles, face_records.size());
}

template <class C, class P, class F>
void Front_2<C, P, F>::uncount_edge_behind(Face_handle f)
{
  Face_record* it = face_records.find(&*f);
  CGAL_assertion(it != nullptr);
  if(--it->front_edges == 0) {
    Phase_scope phase(ctx_.timer, CIRCLE_OCTREE);
    front_triangle_circles.remove(it->circle_item);
    face_records.erase(&*f);
  }
}

// The front rises and falls: with uniform sizes it grows to about 1% of the
// mesh's edges and shrinks to nothing at the end, when the triangulation is
// largest. Containers keep their capacity, so without this the run's peak
// would be the triangulation plus the structures of the largest front (4
// bytes per triangle at 1M triangles). Each structure is rebuilt at its
// current size once it uses less than a quarter (hash tables: an eighth) of
// what it holds; the rebuilds cost O(front) and come at geometrically
// spaced sizes.
template <class C, class P, class F>
void Front_2<C, P, F>::release_unused_memory()
{
  if(vertex.size() >= 64 && 4 * ids.size() < vertex.size()) compact_vertex_ids();
  edges.shrink_if_sparse();
  face_records.shrink_if_sparse();
  if(front_triangle_circles.is_sparse())
    front_triangle_circles.rebuild([this](Face_handle f, std::size_t item) {
      Face_record* r = face_records.find(&*f);
      CGAL_assertion(r != nullptr);
      r->circle_item = item;
    });
}

// Renumbers the active vertices 0..n-1 (keeping their order, so that
// nothing that depends on ids changes order) and rebuilds everything
// indexed or keyed by vertex ids. Only between steps: ids gathered during a
// step must keep naming the same vertex.
template <class C, class P, class F>
void Front_2<C, P, F>::compact_vertex_ids()
{
  CGAL_precondition(released_ids.empty());
  std::vector<Vid> new_id(vertex.size(), no_vertex);
  for(Vid v : free_ids) new_id[v] = 0; // marks the free ids
  Vid n = 0;
  for(Vid v = 0; v < new_id.size(); ++v) new_id[v] = (new_id[v] == no_vertex) ? n++ : no_vertex;
  CGAL_assertion(n == ids.size());

  std::vector<Vertex_handle> new_vertex(n);
  std::vector<std::array<double, 2> > new_xy(n);
  std::vector<Compact_id_list> new_out(n), new_in(n);
  for(Vid v = 0; v < new_id.size(); ++v) {
    const Vid w = new_id[v];
    if(w == no_vertex) continue;
    new_vertex[w] = vertex[v];
    new_xy[w] = xy[v];
    for(Vid t : out[v]) new_out[w].push_back(new_id[t]);
    for(Vid s : in[v]) new_in[w].push_back(new_id[s]);
  }
  vertex.swap(new_vertex);
  xy.swap(new_xy);
  out.swap(new_out);
  in.swap(new_in);
  std::vector<Vid>().swap(free_ids);

  Flat_hash_map<const Tds_vertex*, Vid> new_ids(nullptr);
  new_ids.reserve(n);
  for(Vid w = 0; w < n; ++w) new_ids.insert(&*vertex[w], w);
  ids = std::move(new_ids);

  Flat_hash_map<Edge_key, Front_edge> new_edges(~Edge_key(0));
  new_edges.reserve(edges.size());
  edges.for_each([&](Edge_key k, const Front_edge& fe) {
    new_edges.insert(key(new_id[source(k)], new_id[target(k)]), fe);
  });
  edges = std::move(new_edges);

  active_points.renumber(new_id);
  rebuild_hubs();
  compact_queue(); // the queue's keys name vertices too
  ++ctx_.stats.memory_compactions;
}

// The front invariants (O(front size)): every front vertex has as many
// incoming as outgoing front edges, every front edge is recorded at both
// end points, and every front edge's face on the meshed side (unless null
// or `ghost`) really has that edge; and the records of the active vertices
// agree: every id not free names a vertex that maps back to it, with its
// coordinates and a place in the point index.
template <class C, class P, class F>
bool Front_2<C, P, F>::is_valid(Face_handle ghost) const
{
  std::vector<bool> is_free(vertex.size(), false);
  for(Vid v : free_ids) is_free[v] = true;
  for(Vid v : released_ids) is_free[v] = true;
  std::size_t active = 0;
  for(Vid v = 0; v < vertex.size(); ++v) {
    if(is_free[v]) continue;
    ++active;
    const Vid* id = ids.find(&*vertex[v]);
    if(id == nullptr || *id != v || !active_points.contains(v)) return false;
    if(xy[v][0] != ctx_.ix(vertex[v]->point()) || xy[v][1] != ctx_.iy(vertex[v]->point())) return false;
  }
  if(active != ids.size()) return false;
  std::size_t counted = 0;
  for(Vid v = 0; v < out.size(); ++v) {
    if(out[v].size() != in[v].size()) return false;
    if(is_free[v] && !out[v].empty()) return false;
    for(Vid w : out[v]) {
      const Front_edge* it = edges.find(key(v, w));
      if(it == nullptr) return false;
      if(std::find(in[w].begin(), in[w].end(), v) == in[w].end()) return false;
      const Front_edge& fe = *it;
      if(fe.behind != Face_handle() && fe.behind != ghost) {
        const int i = fe.behind_index;
        if(fe.behind->vertex(C::cw(i)) != vertex[v] || fe.behind->vertex(C::ccw(i)) != vertex[w]) return false;
        if(fe.behind->neighbor(i) != Face_handle()) return false;
      }
      ++counted;
    }
  }
  return counted == edges.size();
}

// Does the close-point search find every front edge (O(front size))? An
// edge is found through its source, unless it enters a hub, and through a
// hub at either end: their reach must cover it. (Separate from is_valid():
// a checkpoint's hubs are rebuilt only after that has passed.)
template <class C, class P, class F>
bool Front_2<C, P, F>::reach_covers_edges() const
{
  bool ok = true;
  edges.for_each([&](Edge_key k, const Front_edge&) {
    const Vid v = source(k), w = target(k);
    const double len = edge_length(v, w);
    if(hubs.contains(w) && !(len <= active_points.reach(w))) ok = false;
    if((!hubs.contains(w) || hubs.contains(v)) && !(len <= active_points.reach(v))) ok = false;
  });
  return ok;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_FRONT_2_H
