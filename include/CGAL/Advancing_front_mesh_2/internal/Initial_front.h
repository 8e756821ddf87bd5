// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_INITIAL_FRONT_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_INITIAL_FRONT_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Front_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_triangles.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_visibility.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// Step 1 of Mavriplis (1992): the boundary forms the initial front. The
// in-domain faces of the marked triangulation are removed; the constrained
// edges that bound the domain become front edges with the outside face
// behind them, and interior constraints front edges on both sides.
template <class Front, class Visibility, class Triangles>
class Initial_front
{
public:
  typedef typename Front::Context Context;
  typedef typename Front::Vid Vid;
  typedef typename Front::Vertex_handle Vertex_handle;
  typedef typename Front::Face_handle Face_handle;

  Initial_front(Context& ctx, Front& front, Visibility& visibility, Triangles& triangles)
    : ctx_(ctx), front_(front), visibility_(visibility), triangles_(triangles) {}

  // Returns false when there is nothing to mesh.
  bool build();

private:
  // A boundary edge to become a front edge, directed with the soon
  // unmeshed side on its left.
  struct Pending
  {
    Vid u, v;
    Face_handle behind;
    int index;
    bool constrained;
  };

  void reset_search_structures(double xmin, double ymin, double xmax, double ymax);
  std::vector<Pending> boundary_edges(const std::vector<Face_handle>& domain_faces);
  void remove_domain_faces(const std::vector<Face_handle>& domain_faces);
  void index_constraints(const std::vector<Pending>& pending);

  Context& ctx_;
  Front& front_;
  Visibility& visibility_;
  Triangles& triangles_;
  std::array<double, 4> box_ = {{0, 0, 0, 0}}; // of the domain's vertices
  double span_ = 0;
};

template <class Front, class V, class T>
bool Initial_front<Front, V, T>::build()
{
  std::vector<Face_handle> domain_faces;
  double xmin = (std::numeric_limits<double>::max)(), ymin = xmin;
  double xmax = -xmin, ymax = -xmin;
  for(auto f = ctx_.tr.finite_faces_begin(); f != ctx_.tr.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    domain_faces.push_back(f);
    for(int i = 0; i < 3; ++i) {
      const double vx = ctx_.ix(f->vertex(i)->point()), vy = ctx_.iy(f->vertex(i)->point());
      xmin = (std::min)(xmin, vx); xmax = (std::max)(xmax, vx);
      ymin = (std::min)(ymin, vy); ymax = (std::max)(ymax, vy);
    }
  }
  if(domain_faces.empty()) return false;
  reset_search_structures(xmin, ymin, xmax, ymax);
  // every vertex of the domain starts active: on the front, or free
  for(Face_handle f : domain_faces)
    for(int i = 0; i < 3; ++i) front_.activate(f->vertex(i));
  const std::vector<Pending> pending = boundary_edges(domain_faces);
  remove_domain_faces(domain_faces);
  index_constraints(pending);
  for(const Pending& p : pending) front_.add_edge(p.u, p.v, p.behind, p.index, p.constrained);
  return !front_.empty();
}

// The circle index's root box: circles of triangles that will ever exist lie
// near the domain; generous padding keeps the overflow list short. Leaf
// sizes (32 circles, 16 points) measured best among 8 to 64 on the
// benchmark's square: fewer, fuller leaves cost less to descend than they
// add to the scans (2% fewer instructions than 16 and 8).
template <class Front, class V, class T>
void Initial_front<Front, V, T>::reset_search_structures(double xmin, double ymin, double xmax, double ymax)
{
  box_ = {{xmin, ymin, xmax, ymax}};
  span_ = (std::max)(xmax - xmin, ymax - ymin);
  front_.front_triangle_circles.reset(xmin - span_, ymin - span_, xmax + span_, ymax + span_, 2 * span_, 32);
  front_.active_points.reset(xmin, ymin, xmax, ymax, 16);
}

template <class Front, class V, class T>
std::vector<typename Initial_front<Front, V, T>::Pending>
Initial_front<Front, V, T>::boundary_edges(const std::vector<Face_handle>& domain_faces)
{
  std::vector<Pending> pending;
  for(Face_handle f : domain_faces) {
    triangles_.domain_area += std::abs(ctx_.triangle_area(f));
    for(int i = 0; i < 3; ++i) {
      Face_handle g = f->neighbor(i);
      // edge i of f, directed with f (soon unmeshed) on its left
      const Vid u = front_.activate(f->vertex(Context::ccw(i))), v = front_.activate(f->vertex(Context::cw(i)));
      if(!g->is_in_domain()) {
        // the boundary of the domain: the mesh marking guarantees it is constrained
        CGAL_assertion(f->is_constrained(i));
        pending.push_back(Pending{u, v, g, g->index(f), true});
      } else if(f->is_constrained(i)) {
        // an interior constraint: both of its sides are front edges
        pending.push_back(Pending{u, v, Face_handle(), -1, true});
      }
    }
  }
  return pending;
}

// The in-domain faces go; the outside faces' links to them are cut first.
template <class Front, class V, class T>
void Initial_front<Front, V, T>::remove_domain_faces(const std::vector<Face_handle>& domain_faces)
{
  for(Face_handle f : domain_faces) {
    for(int i = 0; i < 3; ++i) {
      Face_handle g = f->neighbor(i);
      if(!g->is_in_domain()) g->set_neighbor(g->index(f), Face_handle());
    }
  }
  for(Face_handle f : domain_faces) ctx_.tds().delete_face(f);
}

// The input constraints never change: a static index of them, as diametral
// circles, answers the visibility questions of the circle search.
template <class Front, class V, class T>
void Initial_front<Front, V, T>::index_constraints(const std::vector<Pending>& pending)
{
  const std::array<double, 4>& b = box_;
  visibility_.constraint_circles.reset(b[0] - span_, b[1] - span_, b[2] + span_, b[3] + span_, 2 * span_, 16);
  visibility_.constraint_hubs.clear();
  auto once = [](const Pending& p) { return !(p.u > p.v && p.behind == Face_handle()); }; // interior ones twice
  std::unordered_map<Vid, std::size_t> degree;
  for(const Pending& p : pending)
    if(once(p)) {
      ++degree[p.u];
      ++degree[p.v];
    }
  auto is_hub = [&](Vid v) { return degree[v] >= visibility_.constraint_hubs.min_degree; };
  // a constraint goes to its first end point's hub, or to its second's, or
  // into the index as itself
  std::map<Vid, std::vector<Vertex_handle> > spokes; // in id order: the same index every run
  for(const Pending& p : pending) {
    if(!once(p)) continue;
    if(is_hub(p.u) || is_hub(p.v)) {
      const bool at_u = is_hub(p.u);
      spokes[at_u ? p.u : p.v].push_back(front_.vertex[at_u ? p.v : p.u]);
      continue;
    }
    const double dx = front_.x(p.v) - front_.x(p.u), dy = front_.y(p.v) - front_.y(p.u);
    visibility_.constraint_circles.insert(0.5 * (front_.x(p.u) + front_.x(p.v)), 0.5 * (front_.y(p.u) + front_.y(p.v)),
                                          0.5 * length(dx, dy),
                                          std::make_pair(front_.vertex[p.u], front_.vertex[p.v]));
  }
  for(auto& h : spokes) {
    double reach = 0;
    for(const Vertex_handle& w : h.second)
      reach = (std::max)(reach, length(ctx_.ix(w->point()) - front_.x(h.first), ctx_.iy(w->point()) - front_.y(h.first)));
    visibility_.constraint_circles.insert(front_.x(h.first), front_.y(h.first), reach,
                                          std::make_pair(front_.vertex[h.first], front_.vertex[h.first]));
    visibility_.constraint_hubs.add(front_.vertex[h.first], std::move(h.second), ctx_.pred);
  }
  visibility_.constraint_circles.shrink_to_fit();
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_INITIAL_FRONT_H
