// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_PART_SPLICING_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_PART_SPLICING_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Flat_hash_map.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lawson_flips.h>

#include <CGAL/Has_timestamp.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <unordered_map>
#include <utility>
#include <vector>

// The merge of a decomposed domain's parts (mesh_in_parallel_2.h): the
// parts' triangulations spliced into the input triangulation, and the CGAL
// time stamps that make the splice safe.

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Time stamps across spliced containers. CGAL orders (and may hash) the
// handles of items that have time stamps by them, so the stamps in one
// container must be distinct; every stamp in a container is below its
// counter, the stamp its next new item gets (a reused slot keeps its
// stamp). The parts' items are spliced into cdt's containers with their
// stamps, so each part counts in a range of its own above cdt's counter
// (2^40 stamps: more items than any memory holds), and cdt's counter is
// raised above all the ranges after the merge.
constexpr std::size_t time_stamp_range = std::size_t(1) << 40;

// A stamp written just before its item is erased is a store the compiler
// may drop (GCC's lifetime dead-store elimination: the item's life ends
// at the erase; at -O2 the trick below then failed and every release run
// fell back to one piece). An opaque call that could read the item keeps
// the store.
inline void keep_stores_to(const void* item)
{
  static void (*volatile opaque)(const void*) = [](const void*) {};
  opaque(item);
}

template <class Container>
constexpr bool has_time_stamps()
{
  return CGAL::internal::Has_timestamp<typename Container::value_type>::value;
}

// The counter of `c`: a slot is taken and marked as never used, so that
// taking it again gives it the counter's stamp (the counter moves on by
// one); it is then freed, marked as never used again.
template <class Container>
std::size_t time_stamp_counter(Container& c)
{
  if constexpr(has_time_stamps<Container>()) {
    const std::size_t fresh = std::size_t(-1);
    auto it = c.emplace();
    it->set_time_stamp(fresh);
    keep_stores_to(&*it);
    c.erase(it);
    it = c.emplace();
    const std::size_t stamp = it->time_stamp();
    it->set_time_stamp(fresh);
    keep_stores_to(&*it);
    c.erase(it);
    return stamp;
  } else {
    return 0;
  }
}

// Raises the counter of `c` to at least `stamp` + 1: a slot is given the
// stamp and freed, and taken again (the free list's head), which makes the
// container count on from above it when the item's constructor leaves the
// stamp of a reused slot alone (CGAL's face and vertex bases do); throws
// std::runtime_error otherwise (the caller then meshes in one piece).
template <class Container>
void raise_time_stamp_counter(Container& c, std::size_t stamp)
{
  if constexpr(has_time_stamps<Container>()) {
    auto it = c.emplace();
    it->set_time_stamp(stamp);
    keep_stores_to(&*it);
    c.erase(it);
    it = c.emplace();
    const bool kept = it->time_stamp() == stamp;
    c.erase(it);
    if(!kept)
      throw std::runtime_error("the triangulation's items reset their time stamps when made: "
                               "the parts cannot be spliced");
  }
}

// The first stamp of part `k`'s range, given cdt's counters.
struct Time_stamp_bases
{
  std::size_t faces = 0, vertices = 0;
  std::size_t of_faces(std::size_t k) const { return faces + k * time_stamp_range; }
  std::size_t of_vertices(std::size_t k) const { return vertices + k * time_stamp_range; }
};

template <class CDT>
Time_stamp_bases time_stamp_bases(CDT& cdt)
{
  return Time_stamp_bases{time_stamp_counter(cdt.tds().faces()), time_stamp_counter(cdt.tds().vertices())};
}

// The items of `c` made so far (before it counts in its range) are given
// stamps from the middle of the range.
template <class Container>
void restamp_from_middle(Container& c, std::size_t base)
{
  if constexpr(has_time_stamps<Container>()) {
    std::size_t stamp = base + time_stamp_range / 2;
    for(auto it = c.begin(); it != c.end(); ++it) it->set_time_stamp(stamp++);
  }
}

// A fresh part counts in range `k`; the infinite vertex and the face that
// the triangulation's constructor made are given stamps in the range too
// (they end in cdt's containers, live or freed, with the part's items).
template <class CDT>
void start_time_stamps(CDT& part, const Time_stamp_bases& bases, std::size_t k)
{
  restamp_from_middle(part.tds().faces(), bases.of_faces(k));
  restamp_from_middle(part.tds().vertices(), bases.of_vertices(k));
  raise_time_stamp_counter(part.tds().faces(), bases.of_faces(k));
  raise_time_stamp_counter(part.tds().vertices(), bases.of_vertices(k));
}

// A point as a hash key: equal points (exactly, by the kernel) are one key.
template <class Point>
struct Point_hash
{
  std::size_t operator()(const Point& p) const
  {
    const std::size_t hx = std::hash<double>()(CGAL::to_double(p.x())), hy = std::hash<double>()(CGAL::to_double(p.y()));
    return hx ^ (hy + 0x9e3779b97f4a7c15ull + (hx << 6) + (hx >> 2));
  }
};

// A directed edge by its end points, as a hash key.
template <class Point>
struct Point_pair_hash
{
  std::size_t operator()(const std::pair<Point, Point>& e) const
  {
    return Point_hash<Point>()(e.first) * 31 + Point_hash<Point>()(e.second);
  }
};

// What the merge matches by: the domain's vertices by point, and its
// boundary edges, directed with the domain on their left, with the face
// outside (and that face's index of the edge).
template <class CDT>
struct Stitch_tables
{
  typedef typename CDT::Point Point;
  typedef std::pair<Point, Point> Point_pair;
  std::unordered_map<Point, typename CDT::Vertex_handle, Point_hash<Point> > vertex_at;
  std::unordered_map<Point_pair, std::pair<typename CDT::Face_handle, int>, Point_pair_hash<Point> > outside;
  std::vector<typename CDT::Face_handle> domain_faces;

  explicit Stitch_tables(const CDT& cdt)
  {
    for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) vertex_at.emplace(v->point(), v);
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      domain_faces.push_back(f);
      for(int k = 0; k < 3; ++k) {
        const typename CDT::Face_handle g = f->neighbor(k);
        if(!cdt.is_infinite(g) && g->is_in_domain()) continue;
        outside.emplace(Point_pair(f->vertex(CDT::ccw(k))->point(), f->vertex(CDT::cw(k))->point()),
                        std::make_pair(g, g->index(f)));
      }
    }
  }
};

// Whether the parts fit the domain: each part's open edges lie on the
// domain's boundary or on an interface that another part closes the other
// way, together they cover the domain's boundary, and every vertex of the
// domain on no constraint (a free point) is a vertex of some part's domain
// (the boundary edges alone do not show a free point left outside its
// part's domain: it could lie within rounding of a cut).
template <class CDT>
bool parts_fit(const CDT& cdt, const std::vector<CDT>& parts, const Stitch_tables<CDT>& tables)
{
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef std::pair<Point, Point> Point_pair;
  std::size_t boundary_edges = 0;
  std::unordered_map<Point_pair, int, Point_pair_hash<Point> > interface_sides;
  for(const CDT& part : parts)
    for(auto f = part.finite_faces_begin(); f != part.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      for(int k = 0; k < 3; ++k) {
        const Face_handle g = f->neighbor(k);
        if(!part.is_infinite(g) && g->is_in_domain()) continue;
        Point_pair e(f->vertex(CDT::ccw(k))->point(), f->vertex(CDT::cw(k))->point());
        if(tables.outside.count(e)) {
          ++boundary_edges;
          continue;
        }
        if(!f->is_constrained(k)) return false; // a part's domain ends at an unconstrained edge
        Point_pair twin(e.second, e.first);
        auto it = interface_sides.find(twin);
        if(it != interface_sides.end()) {
          if(--it->second == 0) interface_sides.erase(it);
        } else if(++interface_sides[e] > 1) {
          return false;
        }
      }
    }
  if(boundary_edges != tables.outside.size() || !interface_sides.empty()) return false;
  for(Face_handle f : tables.domain_faces)
    for(int k = 0; k < 3; ++k) {
      const Vertex_handle v = f->vertex(k);
      if(cdt.are_there_incident_constraints(v)) continue;
      bool found = false;
      for(const CDT& part : parts) {
        typename CDT::Locate_type lt;
        int li;
        const Face_handle g = part.locate(v->point(), lt, li);
        if(lt != CDT::VERTEX) continue;
        auto fc = part.incident_faces(g->vertex(li)), done = fc;
        do {
          found = found || (!part.is_infinite(fc) && fc->is_in_domain());
        } while(++fc != done);
        if(found) break;
      }
      if(!found) return false;
    }
  return true;
}

// Moves the in-domain faces of `part` into `cdt` (whose domain faces are
// gone) without copying them: the part's vertices that `cdt` (or a part
// spliced before) has at their point give way to those, the part's faces
// outside its domain are deleted, and its containers are spliced into
// cdt's (`Compact_container::merge()`, a matter of blocks, not items).
// The faces stay linked to each other as they were; across the domain's
// boundary edges they are linked to the faces outside, and across the
// interfaces to the faces of the parts spliced before (`open_interfaces`:
// the interface edges whose other side is not spliced yet), released. The
// joined interface edges are appended to `seams`, the part's vertices
// that stay to `made`. The part is left empty.
template <class CDT, class Open_interfaces>
void splice_part(CDT& cdt, CDT& part, Stitch_tables<CDT>& tables, Open_interfaces& open_interfaces,
                 std::vector<typename CDT::Edge>& seams, std::vector<typename CDT::Vertex_handle>& made)
{
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef std::pair<Point, Point> Point_pair;
  // a part without faces brings nothing (parts_fit() saw no domain face)
  if(part.dimension() < 2) {
    part.clear();
    return;
  }
  // the vertices that give way, and those that stay; an interface point
  // that stays is found by the part on the other side
  std::vector<std::pair<Vertex_handle, Vertex_handle> > replaced;
  std::vector<Vertex_handle> kept;
  for(auto v = part.finite_vertices_begin(); v != part.finite_vertices_end(); ++v) {
    auto it = tables.vertex_at.find(v->point());
    if(it != tables.vertex_at.end()) {
      replaced.emplace_back(v, it->second);
      continue;
    }
    if(part.are_there_incident_constraints(v)) tables.vertex_at.emplace(v->point(), v);
    kept.push_back(v);
  }
  std::vector<Face_handle> around;
  for(const auto& r : replaced) {
    around.clear();
    auto fc = part.incident_faces(r.first), done = fc;
    do {
      around.push_back(fc);
    } while(++fc != done);
    for(Face_handle f : around) f->set_vertex(f->index(r.first), r.second);
  }
  // every vertex of an in-domain face points to one (the vertices that
  // give way pointed to faces of their own part); the open edges
  std::vector<Face_handle> dropped;
  std::vector<typename CDT::Edge> open;
  for(auto f = part.all_faces_begin(); f != part.all_faces_end(); ++f) {
    if(part.is_infinite(f) || !f->is_in_domain()) {
      dropped.push_back(f);
      continue;
    }
    for(int k = 0; k < 3; ++k) {
      f->vertex(k)->set_face(f);
      const Face_handle n = f->neighbor(k);
      if(part.is_infinite(n) || !n->is_in_domain()) open.emplace_back(f, k);
    }
  }
  // the vertices no in-domain face uses (none when the parts fit) go too
  std::size_t used = 0;
  for(Vertex_handle v : kept) {
    if(!part.is_infinite(v->face()) && v->face()->is_in_domain()) {
      kept[used++] = v;
    } else {
      auto it = tables.vertex_at.find(v->point());
      if(it != tables.vertex_at.end() && it->second == v) tables.vertex_at.erase(it);
      part.tds().delete_vertex(v);
    }
  }
  kept.resize(used);
  for(Face_handle f : dropped) part.tds().delete_face(f);
  for(const auto& r : replaced) part.tds().delete_vertex(r.first);
  part.tds().delete_vertex(part.infinite_vertex());
  cdt.tds().faces().merge(part.tds().faces());
  cdt.tds().vertices().merge(part.tds().vertices());
  made.insert(made.end(), kept.begin(), kept.end());
  for(const typename CDT::Edge& o : open) {
    const Face_handle g = o.first;
    const int k = o.second;
    Point_pair e(g->vertex(CDT::ccw(k))->point(), g->vertex(CDT::cw(k))->point());
    auto out = tables.outside.find(e);
    if(out != tables.outside.end()) {
      g->set_neighbor(k, out->second.first);
      out->second.first->set_neighbor(out->second.second, g);
      continue;
    }
    // an interface edge: joined to the other part's face, released
    Point_pair twin(e.second, e.first);
    auto other = open_interfaces.find(twin);
    if(other == open_interfaces.end()) {
      g->set_neighbor(k, Face_handle());
      open_interfaces.emplace(e, std::make_pair(g, k));
      continue;
    }
    const Face_handle h = other->second.first;
    const int j = other->second.second;
    g->set_neighbor(k, h);
    h->set_neighbor(j, g);
    g->set_constraint(k, false);
    h->set_constraint(j, false);
    seams.emplace_back(g, k);
    open_interfaces.erase(other);
  }
}

// The merge without a search and without a copy: the in-domain faces of
// `cdt` are replaced by the parts' in-domain faces (`splice_part()`),
// linked to each other within a part as they were, to the faces outside the
// domain across its boundary edges (which the parts share with `cdt`: they
// were made from its constraints), and to the other part's faces across
// the interfaces, which are released (not constrained); Lawson's flips from
// the interface edges then make the mesh constrained Delaunay across them.
// Everything is matched before anything changes: false (and `cdt` and the
// parts as they were) when the parts do not fit (`parts_fit()`; the caller
// meshes in one piece instead). The parts, which counted their time stamps
// in the ranges of `bases` (`start_time_stamps()`), are left empty; the
// vertices they brought are appended to `made`.
template <class CDT>
bool stitch_parts(CDT& cdt, std::vector<CDT>& parts, const Time_stamp_bases& bases,
                  std::vector<typename CDT::Vertex_handle>& made)
{
  typedef typename CDT::Point Point;
  typedef typename CDT::Face_handle Face_handle;
  Stitch_tables<CDT> tables(cdt);
  if(!parts_fit(cdt, parts, tables)) return false;
  for(Face_handle f : tables.domain_faces) cdt.tds().delete_face(f);
  std::unordered_map<std::pair<Point, Point>, std::pair<Face_handle, int>, Point_pair_hash<Point> > open_interfaces;
  std::vector<typename CDT::Edge> seams;
  for(CDT& part : parts) splice_part(cdt, part, tables, open_interfaces, seams, made);
  raise_time_stamp_counter(cdt.tds().faces(), bases.of_faces(parts.size()));
  raise_time_stamp_counter(cdt.tds().vertices(), bases.of_vertices(parts.size()));
  CGAL_assertion(open_interfaces.empty());
  lawson_flips(cdt, seams, [](Face_handle, Face_handle) {});
  return true;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_PART_SPLICING_2_H
