// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_INPUT_TAGS_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_INPUT_TAGS_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>

#include <CGAL/enum.h>

#include <cstddef>
#include <stdexcept>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace IO {
namespace internal {

// The markers and regions of a mesh found on its input rather than on the
// mesh, for meshes that are never whole in memory (streamed, or spread over
// MPI ranks). The mesh refines the input without changing its boundary, so
// a copy of the input triangulation (its constraints and in-domain marks as
// insert_poly() left them, before meshing), whose size is that of the
// boundary, holds them all:
// - a vertex of the mesh is an input vertex when it is at one (found by
//   point location in the copy), and has its marker; the mesher puts no
//   vertex on a constraint that is not an input vertex, so every other
//   vertex has marker 0;
// - a triangle gets the attribute of the region of the input face its
//   interior starts in: at its first vertex `a`, the face of the copy whose
//   angle at `a` holds the direction of the triangle's first edge (or the
//   face holding `a`, or the side of the edge holding it), decided with the
//   kernel's orientation predicate only, so exactly with exact predicates;
// - the segments are the constrained edges of the copy beside the domain,
//   with the domain on their left (from the first domain face seen).
// Point locations start from the face of the previous one.
template <class CDT>
class Input_tags_2
{
public:
  typedef typename CDT::Point Point;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Vertex_handle Vertex_handle;
  static constexpr std::size_t none = ~std::size_t(0);

  // a segment: the ordinals of its input vertices, the domain on its left
  struct Segment
  {
    std::size_t a, b;
    int marker;
  };

  Input_tags_2(const CDT& input, const Markers_and_regions_2<CDT>& tags) : copy_(input)
  {
    has_regions_ = tags.has_regions();
    if(has_regions_) {
      Markers_and_regions_2<CDT> own;
      for(const auto& r : tags.regions()) own.add_region(r.seed, r.attribute, r.max_area);
      own.mark_regions(copy_);
      attributes_.push_back(0.);
      for(auto f = copy_.finite_faces_begin(); f != copy_.finite_faces_end(); ++f)
        if(f->is_in_domain()) face_attribute_[&*f] = own.region_attribute(f);
      for(const auto& r : tags.regions()) attributes_.push_back(r.attribute);
    }
    for(auto v = copy_.finite_vertices_begin(); v != copy_.finite_vertices_end(); ++v) {
      vertex_ordinal_[&*v] = copy_vertices_.size();
      copy_vertices_.push_back(v);
    }
    markers_.assign(copy_vertices_.size(), 0);
    auto ordinal_of = [&](Vertex_handle v) {
      typename CDT::Locate_type lt;
      int li = 0;
      const Face_handle f = copy_.locate(v->point(), lt, li);
      if(lt != CDT::VERTEX) throw std::logic_error("Input_tags_2: an input vertex is not a vertex of the copy");
      return vertex_ordinal_.at(&*f->vertex(li));
    };
    if(input.dimension() < 2) return;
    for(auto v = input.finite_vertices_begin(); v != input.finite_vertices_end(); ++v)
      markers_[ordinal_of(v)] = tags.vertex_marker(input, v);
    for(auto e = input.finite_edges_begin(); e != input.finite_edges_end(); ++e) {
      Face_handle f = e->first;
      int i = e->second;
      if(!input.is_constrained(*e)) continue;
      if(input.is_infinite(f) || !f->is_in_domain()) {
        const Face_handle g = f->neighbor(i);
        if(input.is_infinite(g) || !g->is_in_domain()) continue;
        i = g->index(f);
        f = g;
      }
      segments_.push_back({ordinal_of(f->vertex(CDT::ccw(i))), ordinal_of(f->vertex(CDT::cw(i))),
                           tags.edge_marker(input, f, i)});
    }
  }

  // whether the input has regions, and their attributes (0 first, for the
  // triangles outside every region)
  bool has_regions() const { return has_regions_; }
  const std::vector<double>& attributes() const { return attributes_; }

  std::size_t number_of_input_vertices() const { return copy_vertices_.size(); }
  const Point& input_point(std::size_t ordinal) const { return copy_vertices_[ordinal]->point(); }
  int marker(std::size_t ordinal) const { return markers_[ordinal]; }
  const std::vector<Segment>& segments() const { return segments_; }

  // the ordinal of the input vertex at `p`, or `none`
  std::size_t input_vertex_at(const Point& p)
  {
    if(copy_.dimension() != 2) return none;
    typename CDT::Locate_type lt;
    int li = 0;
    hint_ = copy_.locate(p, lt, li, hint_);
    return lt == CDT::VERTEX ? vertex_ordinal_.at(&*hint_->vertex(li)) : none;
  }

  // The attribute of the input face the triangle (a, b, c) starts in at a.
  double region_attribute(const Point& a, const Point& b, const Point& c)
  {
    if(copy_.dimension() < 2) return 0.;
    typename CDT::Locate_type lt;
    int li = 0;
    hint_ = copy_.locate(a, lt, li, hint_);
    const auto orientation = copy_.geom_traits().orientation_2_object();
    if(lt == CDT::FACE) return attribute_of(hint_);
    if(lt == CDT::EDGE) {
      // hint_ lies left of s -> t; the triangle is on c's side if b is on the line
      const Point& s = hint_->vertex(CDT::ccw(li))->point();
      const Point& t = hint_->vertex(CDT::cw(li))->point();
      CGAL::Orientation o = orientation(s, t, b);
      if(o == CGAL::COLLINEAR) o = orientation(s, t, c);
      return attribute_of(o == CGAL::LEFT_TURN ? hint_ : hint_->neighbor(li));
    }
    if(lt != CDT::VERTEX) return 0.;
    // the face (a, p, q) whose angle [a->p, a->q) holds the direction a->b:
    // the triangle's interior starts just counter-clockwise of a->b
    const Vertex_handle v = hint_->vertex(li);
    auto f = copy_.incident_faces(v), end = f;
    do {
      if(copy_.is_infinite(f)) continue;
      const int k = f->index(v);
      const Point& p = f->vertex(CDT::ccw(k))->point();
      const Point& q = f->vertex(CDT::cw(k))->point();
      if(orientation(a, p, b) != CGAL::RIGHT_TURN && orientation(a, q, b) == CGAL::RIGHT_TURN)
        return attribute_of(f);
    } while(++f != end);
    return 0.;
  }

private:
  double attribute_of(Face_handle f) const
  {
    const auto it = face_attribute_.find(&*f);
    return it == face_attribute_.end() ? 0. : it->second;
  }

  CDT copy_;
  bool has_regions_ = false;
  std::vector<double> attributes_;
  std::unordered_map<const void*, double> face_attribute_; // per in-domain face of copy_
  std::vector<Vertex_handle> copy_vertices_;
  std::unordered_map<const void*, std::size_t> vertex_ordinal_;
  std::vector<int> markers_; // per vertex of copy_
  std::vector<Segment> segments_;
  Face_handle hint_;
};

} // namespace internal
} // namespace IO
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_IO_INTERNAL_INPUT_TAGS_2_H
