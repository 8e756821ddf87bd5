// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_MARKERS_AND_REGIONS_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_MARKERS_AND_REGIONS_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <unordered_map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

What a solver tags on a mesh, carried from the input to the output:
boundary markers of vertices and of constrained edges, and regions (the
parts of the domain bounded by constraints, each found from a seed point,
with an attribute and an optional area limit). The writers of
`Advancing_front_mesh_2::IO` take an object of this class to write the
markers and regions in every format; `IO::markers_and_regions()` makes one
from a `.poly` file's data.

Vertices and constrained edges are stable through meshing and smoothing
(the mesher inserts vertices but never removes one, and constrained edges
are neither flipped nor split once the front is built), so their markers
are set once, on the input, and carried over the boundary discretisation
with `split_constraint()`. Faces are not stable: `mark_regions()` finds the region of each face
by a flood from the region seeds across unconstrained edges, and is called
on the final mesh (after smoothing, before writing), as Triangle does.

The markers follow Triangle's rules, so that files written from the same
input by Triangle and by us tag the same items:
- a constrained edge has the marker given to it if that is not 0; else 1 if
  it is on the boundary of the domain (a side not in the domain); else 0;
- a vertex has the marker given to it if that is not 0; else the marker of
  the first (in the order they were given) constrained edge at the vertex
  with a marker other than 0; else 1 if it is on the boundary of the
  domain; else 0.

\tparam CDT a `Constrained_Delaunay_triangulation_2` (or
`Constrained_triangulation_plus_2` of one) whose face base is a model of
`DelaunayMeshFaceBase_2`
*/
template <class CDT>
class Markers_and_regions_2
{
public:
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Point Point;

  /// the region of a face reached by no region seed
  static constexpr std::size_t no_region = (std::numeric_limits<std::size_t>::max)();

  /// a region: its seed, its attribute, and its area limit (none when not positive)
  struct Region
  {
    Point seed;
    double attribute;
    double max_area;
  };

  /// gives vertex `v` the boundary marker `marker`
  void set_vertex_marker(Vertex_handle v, int marker) { vertex_markers_[v] = marker; }

  /*!
  gives the constrained edge between vertices `a` and `b` (in either
  order) the boundary marker `marker`. An input segment that the
  triangulation split at points lying on it is several edges: each gets
  its marker.
  */
  void set_constraint_marker(Vertex_handle a, Vertex_handle b, int marker)
  {
    const auto key = edge_key(a, b);
    const auto it = edge_markers_.find(key);
    if(it == edge_markers_.end())
      edge_markers_.emplace(key, Given_marker{next_order_++, marker});
    else
      it->second.marker = marker;
  }

  /*!
  carries the marker given to the constrained edge `(a, b)` over to the two
  edges `(a, v)` and `(v, b)` it was split into at the new vertex `v` (the
  callback of `split_constraints_to_size_2()`). The new vertex gets its
  marker from them by the rules above, as Triangle's vertices on split
  segments do.
  */
  void split_constraint(Vertex_handle a, Vertex_handle b, Vertex_handle v)
  {
    const auto it = edge_markers_.find(edge_key(a, b));
    if(it == edge_markers_.end()) return;
    const Given_marker given = it->second;
    edge_markers_.erase(it);
    edge_markers_[edge_key(a, v)] = given;
    edge_markers_[edge_key(v, b)] = given;
  }

  /*!
  adds a region around `seed`, with `attribute` and the area limit
  `max_area` (none when not positive); returns its index. Where two seeds
  lie in the same region, the later one gives it its attribute and limit.
  */
  std::size_t add_region(const Point& seed, double attribute, double max_area = -1)
  {
    regions_.push_back(Region{seed, attribute, max_area});
    return regions_.size() - 1;
  }

  /// the regions, in the order they were added
  const std::vector<Region>& regions() const { return regions_; }

  /// whether markers were given to vertices or constrained edges
  bool has_markers() const { return !vertex_markers_.empty() || !edge_markers_.empty(); }

  /// whether regions were added
  bool has_regions() const { return !regions_.empty(); }

  /// whether some region has an area limit
  bool has_area_limits() const
  {
    for(const Region& r : regions_)
      if(r.max_area > 0) return true;
    return false;
  }

  /*!
  finds the region of every in-domain face of `cdt`: the faces reachable
  from the face containing a region's seed without crossing a constrained
  edge or leaving the domain. Regions are flooded in order, so a later
  seed in the same region wins. Seeds outside the domain mark nothing.
  Call it again whenever the faces of `cdt` have changed.
  */
  void mark_regions(const CDT& cdt)
  {
    face_regions_.clear();
    face_regions_.reserve(cdt.number_of_faces());
    std::vector<Face_handle> stack;
    for(std::size_t r = 0; r < regions_.size(); ++r) {
      if(cdt.dimension() < 2) break;
      const Face_handle start = cdt.locate(regions_[r].seed);
      if(start == Face_handle() || cdt.is_infinite(start) || !start->is_in_domain()) continue;
      face_regions_[&*start] = r + 1;
      stack.push_back(start);
      while(!stack.empty()) {
        const Face_handle f = stack.back();
        stack.pop_back();
        for(int i = 0; i < 3; ++i) {
          const Face_handle g = f->neighbor(i);
          if(cdt.is_constrained(std::make_pair(f, i)) || cdt.is_infinite(g) || !g->is_in_domain()) continue;
          std::size_t& region_of_g = face_regions_[&*g];
          if(region_of_g == r + 1) continue;
          region_of_g = r + 1;
          stack.push_back(g);
        }
      }
    }
    regions_marked_ = true;
  }

  /*!
  the index of the region of face `f` (into `regions()`), or `no_region`.

  \pre `mark_regions()` was called on the current faces.
  */
  std::size_t region(Face_handle f) const
  {
    if(!regions_marked_) throw std::logic_error("Markers_and_regions_2::region(): call mark_regions() first");
    const auto it = face_regions_.find(&*f);
    return it == face_regions_.end() || it->second == 0 ? no_region : it->second - 1;
  }

  /// the attribute of the region of face `f`, 0 when it has none (as in Triangle)
  double region_attribute(Face_handle f) const
  {
    const std::size_t r = region(f);
    return r == no_region ? 0. : regions_[r].attribute;
  }

  /// the marker of the constrained edge `(f, i)` of `cdt`, by the rules above
  int edge_marker(const CDT& cdt, Face_handle f, int i) const
  {
    const auto it = edge_markers_.find(edge_key(f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i))));
    if(it != edge_markers_.end() && it->second.marker != 0) return it->second.marker;
    return on_domain_boundary(cdt, f, i) ? 1 : 0;
  }

  /// the marker of vertex `v` of `cdt`, by the rules above
  int vertex_marker(const CDT& cdt, Vertex_handle v) const
  {
    const auto given = vertex_markers_.find(v);
    if(given != vertex_markers_.end() && given->second != 0) return given->second;
    const Given_marker* first = nullptr;
    bool boundary = false;
    auto e = cdt.incident_edges(v), end = e;
    if(e == nullptr) return 0;
    do {
      const Face_handle f = e->first;
      const int i = e->second;
      if(!cdt.is_constrained(*e)) continue;
      boundary = boundary || on_domain_boundary(cdt, f, i);
      const auto it = edge_markers_.find(edge_key(f->vertex(CDT::ccw(i)), f->vertex(CDT::cw(i))));
      if(it != edge_markers_.end() && it->second.marker != 0 && (first == nullptr || it->second.order < first->order))
        first = &it->second;
    } while(++e != end);
    if(first != nullptr) return first->marker;
    return boundary ? 1 : 0;
  }

  /// whether edge `(f, i)` has the domain on exactly one side
  static bool on_domain_boundary(const CDT& cdt, Face_handle f, int i)
  {
    const Face_handle g = f->neighbor(i);
    const bool in_f = !cdt.is_infinite(f) && f->is_in_domain();
    const bool in_g = !cdt.is_infinite(g) && g->is_in_domain();
    return in_f != in_g;
  }

private:
  typedef std::pair<Vertex_handle, Vertex_handle> Edge_key;
  struct Given_marker
  {
    std::size_t order; // when it was first given: earlier edges win at a vertex
    int marker;
  };
  // per face (by address), its region + 1; 0 or absent for none
  typedef std::unordered_map<const void*, std::size_t> Face_regions;

  static Edge_key edge_key(Vertex_handle a, Vertex_handle b)
  {
    return std::less<Vertex_handle>()(b, a) ? Edge_key(b, a) : Edge_key(a, b);
  }

  std::map<Vertex_handle, int> vertex_markers_;
  std::map<Edge_key, Given_marker> edge_markers_;
  std::size_t next_order_ = 0;
  std::vector<Region> regions_;
  Face_regions face_regions_;
  bool regions_marked_ = false;
};

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_MARKERS_AND_REGIONS_2_H
