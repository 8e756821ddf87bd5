// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_INTERFACE_BAND_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_INTERFACE_BAND_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Smoothing_statistics.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lawson_flips.h>
#include <CGAL/Advancing_front_mesh_2/internal/Quality_smoother.h>
#include <CGAL/Advancing_front_mesh_2/internal/Star_smoother.h>

#include <CGAL/Handle_hash_function.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <stdexcept>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The merge of two meshes that share an interface, when neither is in the
// same memory as the other (the parts of a decomposed domain on different
// processes): only a band of triangles on each side of the interface is
// brought together, the interface is released there and Lawson's flips make
// the band constrained Delaunay across it; the vertices near the interface
// are then smoothed (the seam), as mesh_in_parallel_2() does with the whole
// mesh in one triangulation.
//
// The band's outer edges (its triangles' edges that no other band triangle
// shares and that are not input constraints) are held as constraints: the
// meshes beyond them are not here. The merged band fits the rest of the
// meshes unchanged when every band triangle at an outer edge is still a
// triangle of the band afterwards: the edges inside each mesh were locally
// Delaunay before and stay so, the edges the flips made are, and an outer
// edge has the same two triangles as before. Otherwise the merge reports
// failure and the caller widens the band; it fails only when flips or moves
// reach the band's edge.

// Triangles by their points, as one process hands them to another.
template <class Point>
struct Triangle_soup_2
{
  std::vector<Point> points;
  std::vector<std::array<std::size_t, 3> > triangles; // counter-clockwise
  // per triangle: bit k is set when the edge opposite its vertex k is an
  // input constraint (kept; an interface edge is not one)
  std::vector<unsigned char> constrained;

};

struct Band_merge_statistics
{
  std::size_t band_triangles = 0, outer_edges = 0, flips = 0, seam_vertices = 0;
  Smoothing_statistics seam_smoothing;
};

// The soups' triangles in `band` (empty before), their outer edges held as
// constraints (and listed in `outer`) and every other edge released unless
// an input constraint; the band's faces are in the domain, the others not.
// Throws std::logic_error when the soups do not form one triangulation (a
// triangle that is no face once all their edges are in, or one given
// twice), or the triangulation's exception when their edges cross.
template <class CDT, class Point>
std::vector<std::array<typename CDT::Vertex_handle, 3> >
insert_band(const std::vector<const Triangle_soup_2<Point>*>& soups, CDT& band,
            std::vector<typename CDT::Edge>& released,
            std::vector<std::pair<typename CDT::Vertex_handle, typename CDT::Vertex_handle> >& outer,
            std::vector<std::vector<typename CDT::Vertex_handle> >* soup_vertices = nullptr)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  std::vector<std::array<Vertex_handle, 3> > triangles;
  // every edge once, constrained when any soup says so; how many triangles
  // have it. Edges are keyed by the order their vertices were first met,
  // not by address, so that the flips (in the order of the released edges)
  // and the result depend on the soups only.
  struct Edge_use
  {
    Vertex_handle a, b;
    int triangles;
    bool constrained;
  };
  std::map<Vertex_handle, std::size_t> ordinal;
  std::map<std::pair<std::size_t, std::size_t>, Edge_use> edges;
  Face_handle hint;
  for(const Triangle_soup_2<Point>* soup : soups) {
    std::vector<Vertex_handle> vh;
    vh.reserve(soup->points.size());
    for(const Point& p : soup->points) {
      vh.push_back(band.insert(p, hint)); // an equal point gives the same vertex
      hint = vh.back()->face();
      ordinal.emplace(vh.back(), ordinal.size());
    }
    for(std::size_t t = 0; t < soup->triangles.size(); ++t) {
      const std::array<std::size_t, 3>& tri = soup->triangles[t];
      triangles.push_back({{vh[tri[0]], vh[tri[1]], vh[tri[2]]}});
      for(int k = 0; k < 3; ++k) {
        Vertex_handle a = vh[tri[(k + 1) % 3]], b = vh[tri[(k + 2) % 3]];
        std::size_t i = ordinal[a], j = ordinal[b];
        if(j < i) {
          std::swap(a, b);
          std::swap(i, j);
        }
        Edge_use& e = edges.emplace(std::make_pair(i, j), Edge_use{a, b, 0, false}).first->second;
        ++e.triangles;
        e.constrained = e.constrained || ((soup->constrained[t] >> k) & 1) != 0;
      }
    }
    if(soup_vertices != nullptr) soup_vertices->push_back(std::move(vh));
  }
  for(const auto& e : edges) band.insert_constraint(e.second.a, e.second.b);
  for(auto f = band.all_faces_begin(); f != band.all_faces_end(); ++f) f->set_in_domain(false);
  for(const auto& t : triangles) {
    Face_handle f;
    // a face met twice: the same triangle on both sides
    if(!band.is_face(t[0], t[1], t[2], f) || f->is_in_domain())
      throw std::logic_error("interface band: the triangles on the two sides overlap");
    f->set_in_domain(true);
  }
  outer.clear();
  released.clear();
  for(const auto& entry : edges) {
    const Edge_use& e = entry.second;
    Face_handle f;
    int i;
    if(!band.is_edge(e.a, e.b, f, i))
      throw std::logic_error("interface band: an edge of the triangles is not an edge of the band");
    if(e.triangles > 2)
      throw std::logic_error("interface band: an edge is shared by more than two triangles");
    if(e.triangles == 1) {
      if(!e.constrained) outer.emplace_back(e.a, e.b);
      continue; // held: an outer edge or an input constraint at the band's edge
    }
    if(e.constrained) continue; // an input constraint inside the band
    const Face_handle g = f->neighbor(i);
    f->set_constraint(i, false);
    g->set_constraint(g->index(f), false);
    released.emplace_back(f, i);
  }
  return triangles;
}

// Merges the soups' triangles (the bands on the two sides of an interface,
// which share its points) into `band`, constrained Delaunay but for the
// input constraints; then smooths, `passes` times, the vertices for which
// `in_seam(v)` holds, and whose star lies in the band away from its outer
// edges. Returns false when the merge reached an outer edge (the caller
// widens the band); `band` then holds the partial result. `soup_vertices`,
// when given, receives the vertex of `band` at each point of each soup.
template <class CDT, class Point, class In_seam>
bool merge_interface_band(const std::vector<const Triangle_soup_2<Point>*>& soups, const In_seam& in_seam,
                          std::size_t passes, CDT& band, Band_merge_statistics& st,
                          std::vector<std::vector<typename CDT::Vertex_handle> >* soup_vertices = nullptr)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  st = Band_merge_statistics();
  std::vector<typename CDT::Edge> released;
  std::vector<std::pair<Vertex_handle, Vertex_handle> > outer;
  st.band_triangles = insert_band(soups, band, released, outer, soup_vertices).size();
  st.outer_edges = outer.size();
  // the triangles at the outer edges, which must stay, and their vertices,
  // which must not move (a triangle at an input constraint may change: the
  // mesh need not be Delaunay across a constraint)
  std::vector<std::array<Vertex_handle, 3> > at_outer_edges;
  std::unordered_set<Vertex_handle, Handle_hash_function> held;
  for(const auto& e : outer) {
    Face_handle f;
    int i;
    band.is_edge(e.first, e.second, f, i);
    if(band.is_infinite(f) || !f->is_in_domain()) {
      const Face_handle g = f->neighbor(i);
      i = g->index(f);
      f = g;
    }
    at_outer_edges.push_back({{f->vertex(0), f->vertex(1), f->vertex(2)}});
    held.insert(at_outer_edges.back().begin(), at_outer_edges.back().end());
  }
  st.flips = lawson_flips(band, released, [](Face_handle, Face_handle) {});
  std::vector<Vertex_handle> seam;
  for(auto v = band.finite_vertices_begin(); v != band.finite_vertices_end(); ++v)
    if(held.count(v) == 0 && in_seam(v->point())) seam.push_back(v);
  st.seam_vertices = seam.size();
  if(!seam.empty() && passes > 0) st.seam_smoothing = smooth_vertices_with<Quality_moves>(band, seam, passes);
  for(const auto& t : at_outer_edges) {
    Face_handle f;
    if(!band.is_face(t[0], t[1], t[2], f)) return false;
  }
  return true;
}

// Puts the soup's triangles in an order that depends on their points only
// (by their points' coordinates, least first), and its points in the order
// the triangles first meet them; `handles`, when given, is permuted with
// the triangles. Two processes that hold the same triangles in different
// orders (a part in memory and the same part streamed) then merge them
// into the same mesh.
template <class Point, class Handle>
void sort_soup(Triangle_soup_2<Point>& soup, std::vector<Handle>* handles = nullptr)
{
  const std::size_t n = soup.triangles.size();
  typedef std::array<std::pair<double, double>, 3> Key;
  std::vector<Key> keys(n);
  for(std::size_t t = 0; t < n; ++t) {
    for(std::size_t k = 0; k < 3; ++k) {
      const Point& p = soup.points[soup.triangles[t][k]];
      keys[t][k] = std::make_pair(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    }
    std::sort(keys[t].begin(), keys[t].end());
  }
  std::vector<std::size_t> order(n);
  for(std::size_t t = 0; t < n; ++t) order[t] = t;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  Triangle_soup_2<Point> sorted;
  std::vector<std::size_t> new_index(soup.points.size(), std::size_t(-1));
  std::vector<Handle> sorted_handles;
  for(std::size_t t : order) {
    // the triangle's points numbered least first, whatever its rotation
    std::array<std::size_t, 3> by_key = soup.triangles[t];
    std::sort(by_key.begin(), by_key.end(), [&](std::size_t a, std::size_t b) {
      const Point &p = soup.points[a], &q = soup.points[b];
      return std::make_pair(CGAL::to_double(p.x()), CGAL::to_double(p.y())) <
             std::make_pair(CGAL::to_double(q.x()), CGAL::to_double(q.y()));
    });
    for(std::size_t i : by_key)
      if(new_index[i] == std::size_t(-1)) {
        new_index[i] = sorted.points.size();
        sorted.points.push_back(soup.points[i]);
      }
    std::array<std::size_t, 3> tri;
    for(std::size_t k = 0; k < 3; ++k) tri[k] = new_index[soup.triangles[t][k]];
    sorted.triangles.push_back(tri);
    sorted.constrained.push_back(soup.constrained[t]);
    if(handles != nullptr) sorted_handles.push_back((*handles)[t]);
  }
  soup = std::move(sorted);
  if(handles != nullptr) *handles = std::move(sorted_handles);
}

// The finite faces `f` of `cdt` for which `keep(f)` holds, counter-clockwise,
// by their points (each point once, in the order first met); the edge
// opposite vertex k is an input constraint when `constrained(f, k)` holds.
// `faces`, when given, receives the faces in the soup's order.
template <class CDT, class Keep, class Constrained>
Triangle_soup_2<typename CDT::Point> triangles_of(const CDT& cdt, const Keep& keep, const Constrained& constrained,
                                                   std::vector<typename CDT::Face_handle>* faces = nullptr)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  Triangle_soup_2<typename CDT::Point> soup;
  std::map<Vertex_handle, std::size_t> index;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!keep(f)) continue;
    std::array<std::size_t, 3> t;
    unsigned char flags = 0;
    for(int k = 0; k < 3; ++k) {
      const Vertex_handle v = f->vertex(k);
      const auto inserted = index.emplace(v, soup.points.size());
      if(inserted.second) soup.points.push_back(v->point());
      t[k] = inserted.first->second;
      if(constrained(f, k)) flags |= static_cast<unsigned char>(1u << k);
    }
    soup.triangles.push_back(t);
    soup.constrained.push_back(flags);
    if(faces != nullptr) faces->push_back(f);
  }
  return soup;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_INTERFACE_BAND_2_H
