// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESHER_2_H
#define CGAL_ADVANCING_FRONT_MESHER_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/Default_visitor.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_return_code.h>
#include <CGAL/Advancing_front_mesh_2/Sizing_fields.h>
#include <CGAL/Advancing_front_mesh_2/Statistics.h>
#include <CGAL/Advancing_front_mesh_2/internal/Dynamic_point_index.h>
#include <CGAL/Advancing_front_mesh_2/internal/Front_predicates.h>
#include <CGAL/Advancing_front_mesh_2/internal/Lifted_circle_octree.h>

#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <list>
#include <queue>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Generates a mesh of the domain of a constrained Delaunay triangulation with
the advancing-front Delaunay algorithm of D. J. Mavriplis, "An Advancing
Front Delaunay Triangulation Algorithm Designed for Robustness" (1992).

The boundary edges form the initial front. The shortest front edge is taken
first; either an existing front point closes a Delaunay triangle on it within
the local size bound, or a new point is placed ahead of the front along the
edge's perpendicular bisector and all Delaunay triangles it forms with nearby
front points are built at once. Triangles exist only behind the front, every
operation is local, and every combinatorial decision uses the traits' exact
predicates. Input constraints are never split, and the result is a
constrained Delaunay triangulation of its vertices.

The mesh is built directly in the triangulation data structure of `cdt`:
the in-domain faces are removed, the front advances over the emptied region,
and at the end the triangulation is complete and valid again, its in-domain
faces flagged with `set_in_domain(true)`, exactly like the result of
`CGAL::Delaunay_mesher_2`.

\tparam CDT a `Constrained_Delaunay_triangulation_2` or a
  `Constrained_triangulation_plus_2` of one, whose face base models
  `DelaunayMeshFaceBase_2` (for example `Delaunay_mesh_face_base_2`).
\tparam SizingField a model of `AdvancingFrontSizingField_2`: callable as
  `FT(const Point_2&)`, returning the target edge length `h` at a point.
\tparam Visitor a model of `AdvancingFrontMeshVisitor_2`.

<b>Sizes.</b> The paper bounds triangle circumradii by rho(x); users think in
edge lengths. The sizing field gives the target edge length h(x) and the
mesher uses rho(x) = h(x) / sqrt(3), the circumradius of the equilateral
triangle of side h.
*/
template <class CDT_,
          class SizingField_ = Advancing_front_mesh_2::Uniform_sizing_field_2<typename CDT_::Geom_traits>,
          class Visitor_ = Advancing_front_mesh_2::Default_visitor>
class Advancing_front_mesher_2
{
public:
  typedef CDT_ CDT;
  typedef CDT_ Triangulation;
  typedef SizingField_ Sizing_field;
  typedef Visitor_ Visitor;
  typedef typename CDT::Geom_traits Geom_traits;
  typedef typename Geom_traits::FT FT;
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef typename CDT::Face_handle Face_handle;
  typedef typename CDT::Triangulation_data_structure Tds;
  typedef std::list<Point> Seeds;
  typedef typename Seeds::const_iterator Seeds_const_iterator;

private:
  typedef std::uint32_t Vid;
  typedef std::uint64_t Edge_key;
  static constexpr Vid no_vertex = (std::numeric_limits<Vid>::max)();

  struct Handle_hash
  {
    template <class H>
    std::size_t operator()(const H& h) const { return std::hash<const void*>()(&*h); }
  };

  // A front edge is directed with the unmeshed region on its left.
  struct Front_edge
  {
    Face_handle behind;  // face on the meshed side (mesh or outside face), null on a virgin side of a constraint
    int behind_index = -1;
    bool constrained = false;
    std::uint32_t version = 0;
    std::size_t circle_item = 0;
  };

  struct Face_record
  {
    std::size_t circle_item;
    int front_edges;
  };

  struct Queue_entry
  {
    double length;
    Edge_key key;
    std::uint32_t version;
    bool operator<(const Queue_entry& o) const
    {
      // std::priority_queue is a max-heap: invert to pop the shortest edge;
      // ties broken by key so that runs are deterministic
      if(length != o.length) return length > o.length;
      return key > o.key;
    }
  };

  struct Neighbourhood
  {
    double cx = 0, cy = 0, radius = 0;
    std::vector<std::size_t> vertices;
    std::vector<Edge_key> edges;
  };

  struct Circle
  {
    double cx, cy, r;
  };

  typedef Advancing_front_mesh_2::internal::Lifted_circle_octree<Face_handle> Triangle_octree;
  typedef Advancing_front_mesh_2::internal::Lifted_circle_octree<Edge_key> Edge_octree;

public:
  /// \name Creation
  /// @{

  /*!
  Creates a mesher for `cdt`. The triangulation must stay alive and must not
  be modified by anything else while the mesher works on it.
  */
  explicit Advancing_front_mesher_2(CDT& cdt,
                                    const Sizing_field& sizing = Sizing_field(),
                                    const Visitor& visitor = Visitor())
    : cdt_(cdt), sizing_(sizing), visitor_(visitor), pred_(cdt.geom_traits())
  {}

  /// @}

  /// \name Domain
  /// @{

  /*!
  Sets the seeds, exactly as `Delaunay_mesher_2::set_seeds()`: with
  `mark == false` (default) the connected components (bounded by
  constraints) containing a seed are holes; with `mark == true` they are the
  domain. The unbounded component is never meshed. Without seeds every
  bounded component is meshed.
  */
  template <class InputIterator>
  void set_seeds(InputIterator b, InputIterator e, bool mark = false)
  {
    seeds_.assign(b, e);
    seeds_mark_ = mark;
    initialized_ = false;
  }

  void clear_seeds()
  {
    seeds_.clear();
    seeds_mark_ = false;
    initialized_ = false;
  }

  Seeds_const_iterator seeds_begin() const { return seeds_.begin(); }
  Seeds_const_iterator seeds_end() const { return seeds_.end(); }

  /// @}

  /// \name Limits
  /// @{

  /// Stops after `n` front edges have been processed (0: no limit).
  void set_iteration_limit(std::size_t n) { iteration_limit_ = n; }
  /// Stops after `seconds` seconds of meshing (0: no limit).
  void set_time_limit(double seconds) { time_limit_ = seconds; }

  /// @}

  /// \name Meshing
  /// @{

  /*!
  Meshes the domain. Returns `MESH_COMPLETE`, or the limit that stopped the
  advancing front; in every case the triangulation is a valid mesh of the
  whole domain (see `Advancing_front_mesh_2::Mesh_return_code`).

  \throws std::invalid_argument if the sizing field returns a value that is
  not a positive finite number.
  */
  Advancing_front_mesh_2::Mesh_return_code refine_mesh()
  {
    if(!initialized_) init();
    const auto start = std::chrono::steady_clock::now();
    Advancing_front_mesh_2::Mesh_return_code rc = Advancing_front_mesh_2::MESH_COMPLETE;
    std::size_t steps = 0;
    while(!queue_.empty()) {
      if(iteration_limit_ != 0 && steps >= iteration_limit_) {
        rc = Advancing_front_mesh_2::ITERATION_LIMIT_REACHED;
        break;
      }
      if(time_limit_ > 0 && (steps & 63) == 0 &&
         seconds_since(start) > time_limit_) {
        rc = Advancing_front_mesh_2::TIME_LIMIT_REACHED;
        break;
      }
      try {
        if(!step()) break;
      } catch(...) {
        // leave a valid triangulation behind before reporting the error
        close_remaining_front();
        finish();
        throw;
      }
      ++steps;
    }
    if(rc != Advancing_front_mesh_2::MESH_COMPLETE) close_remaining_front();
    finish();
    stats_.meshing_time += seconds_since(start);
    return rc;
  }

  /*!
  Marks the domain from the seeds, removes the in-domain faces and builds
  the initial front from the constrained edges that bound the domain.
  Called by `refine_mesh()` and `step_by_step_refine_mesh()` when needed.
  */
  void init()
  {
    const auto start = std::chrono::steady_clock::now();
    clear_state();
    initialized_ = true;
    finished_ = false;
    if(cdt_.dimension() < 2) {
      finished_ = true;
      return;
    }
    CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> >::mark_facets(
      cdt_, seeds_.begin(), seeds_.end(), seeds_mark_);
    build_front();
    visitor_.on_init(*this);
    stats_.init_time += seconds_since(start);
  }

  /*!
  Processes one front edge. Returns `false` when the mesh is complete
  (then the triangulation is valid again). Between two calls the
  triangulation data structure is partial: only the faces behind the front
  exist, so it must not be used through the triangulation's own functions
  (locate, insert, is_valid) before this function has returned `false`.
  */
  bool step_by_step_refine_mesh()
  {
    if(!initialized_) init();
    if(finished_) return false;
    try {
      if(step()) return true;
    } catch(...) {
      close_remaining_front();
      finish();
      throw;
    }
    finish();
    return false;
  }

  /// Returns `true` when the front is empty and the mesh complete.
  bool is_refinement_done() const { return initialized_ && finished_; }

  /// @}

  /// \name Access
  /// @{

  const CDT& triangulation() const { return cdt_; }
  const Sizing_field& sizing_field() const { return sizing_; }
  const Visitor& visitor() const { return visitor_; }
  Visitor& visitor() { return visitor_; }
  const Advancing_front_mesh_2::Statistics& statistics() const { return stats_; }
  /// number of front edges now
  std::size_t front_size() const { return front_.size(); }

  /*!
  Checks the front invariants (for tests and debugging, O(front size)):
  every front vertex has as many incoming as outgoing front edges, every
  front edge is recorded at both end points, and every front edge's face on
  the meshed side really has that edge.
  */
  bool is_front_valid() const
  {
    std::size_t counted = 0;
    for(Vid v = 0; v < out_.size(); ++v) {
      if(out_[v].size() != in_[v].size()) return false;
      for(Vid w : out_[v]) {
        auto it = front_.find(key(v, w));
        if(it == front_.end()) return false;
        if(std::find(in_[w].begin(), in_[w].end(), v) == in_[w].end()) return false;
        const Front_edge& fe = it->second;
        if(fe.behind != Face_handle()) {
          const int i = fe.behind_index;
          if(fe.behind->vertex(cw(i)) != vertex_[v] || fe.behind->vertex(ccw(i)) != vertex_[w])
            return false;
          if(fe.behind->neighbor(i) != Face_handle()) return false;
        }
        ++counted;
      }
    }
    return counted == front_.size();
  }

  /// @}

private:
  // ---------------------------------------------------------------- basics
  static int ccw(int i) { return (i + 1) % 3; }
  static int cw(int i) { return (i + 2) % 3; }
  static Edge_key key(Vid u, Vid v) { return (Edge_key(u) << 32) | Edge_key(v); }
  static Vid source(Edge_key k) { return Vid(k >> 32); }
  static Vid target(Edge_key k) { return Vid(k & 0xffffffffu); }

  template <class T>
  static double seconds_since(const T& start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  Tds& tds() { return cdt_.tds(); }
  const Point& pt(Vid v) const { return vertex_[v]->point(); }
  double x(Vid v) const { return xy_[v][0]; }
  double y(Vid v) const { return xy_[v][1]; }

  void clear_state()
  {
    front_.clear();
    out_.clear();
    in_.clear();
    vertex_.clear();
    xy_.clear();
    tri_count_.clear();
    vid_.clear();
    face_records_.clear();
    queue_ = std::priority_queue<Queue_entry>();
    index_.clear();
    stats_ = Advancing_front_mesh_2::Statistics();
    meshed_area_ = 0;
    domain_area_ = 0;
  }

  Vid add_vertex(Vertex_handle vh)
  {
    const Vid id = static_cast<Vid>(vertex_.size());
    if(vertex_.size() >= std::size_t(no_vertex) - 1)
      throw std::length_error("Advancing_front_mesher_2: too many vertices");
    vertex_.push_back(vh);
    xy_.push_back({{CGAL::to_double(vh->point().x()), CGAL::to_double(vh->point().y())}});
    out_.emplace_back();
    in_.emplace_back();
    tri_count_.push_back(0);
    vid_.emplace(vh, id);
    return id;
  }

  Vid id_of(Vertex_handle vh) const
  {
    auto it = vid_.find(vh);
    CGAL_assertion(it != vid_.end());
    return it->second;
  }

  // A vertex is active (searchable as a close point) while it has front
  // edges, or while no triangle touches it yet (a free point or a vertex
  // whose triangles were all removed by a cavity).
  void update_vertex_state(Vid v)
  {
    if(!out_[v].empty() || !in_[v].empty() || tri_count_[v] == 0)
      index_.insert(v, x(v), y(v));
    else
      index_.remove(v);
  }

  static Circle circle_of(double ax, double ay, double bx, double by, double cx, double cy)
  {
    // circumcircle relative to a, which keeps the rounding error small for
    // coordinates far from the origin
    // and in a frame scaled to unit size, so that the cubic terms neither
    // overflow nor underflow for very large or very small coordinates
    const double scale = (std::max)({std::abs(bx - ax), std::abs(by - ay), std::abs(cx - ax), std::abs(cy - ay)});
    if(!(scale > 0) || !std::isfinite(scale))
      return Circle{ax, ay, std::numeric_limits<double>::infinity()};
    const double bax = (bx - ax) / scale, bay = (by - ay) / scale, cax = (cx - ax) / scale, cay = (cy - ay) / scale;
    const double d = 2 * (bax * cay - bay * cax);
    const double b2 = bax * bax + bay * bay, c2 = cax * cax + cay * cay;
    const double ux = (cay * b2 - bay * c2) / d, uy = (bax * c2 - cax * b2) / d;
    return Circle{ax + ux * scale, ay + uy * scale, std::hypot(ux, uy) * scale};
  }

  Circle circle_of(Vid a, Vid b, Vid c) const
  {
    return circle_of(x(a), y(a), x(b), y(b), x(c), y(c));
  }

  Circle circle_of(Face_handle f) const
  {
    return circle_of(id_of(f->vertex(0)), id_of(f->vertex(1)), id_of(f->vertex(2)));
  }

  double target_circumradius(double mx, double my)
  {
    const FT h = sizing_(Point(mx, my));
    const double hd = CGAL::to_double(h);
    if(!(hd > 0) || !std::isfinite(hd)) {
      std::ostringstream os;
      os.precision(17);
      os << "Advancing_front_mesher_2: the sizing field returned " << hd << " at (" << mx << ", "
         << my << "); sizes must be positive finite numbers";
      throw std::invalid_argument(os.str());
    }
    return hd / std::sqrt(3.);
  }

  // ------------------------------------------------------------ the front
  void add_front_edge(Vid u, Vid v, Face_handle behind, int behind_index, bool constrained)
  {
    CGAL_assertion(front_.find(key(u, v)) == front_.end());
    Front_edge fe;
    fe.behind = behind;
    fe.behind_index = behind_index;
    fe.constrained = constrained;
    fe.version = ++version_counter_;
    const double mx = 0.5 * (x(u) + x(v)), my = 0.5 * (y(u) + y(v));
    const double dx = x(v) - x(u), dy = y(v) - y(u);
    const double len = std::hypot(dx, dy);
    fe.circle_item = edge_octree_.insert(mx, my, 0.5 * len, key(u, v));
    front_.emplace(key(u, v), fe);
    out_[u].push_back(v);
    in_[v].push_back(u);
    if(behind != Face_handle() && behind->is_in_domain()) add_front_edge_to_face(behind);
    queue_.push(Queue_entry{len, key(u, v), fe.version});
    stats_.largest_front = (std::max)(stats_.largest_front, front_.size());
    update_vertex_state(u);
    update_vertex_state(v);
  }

  void remove_front_edge(Vid u, Vid v)
  {
    auto it = front_.find(key(u, v));
    CGAL_assertion(it != front_.end());
    const Front_edge fe = it->second;
    front_.erase(it);
    edge_octree_.remove(fe.circle_item);
    out_[u].erase(std::find(out_[u].begin(), out_[u].end(), v));
    in_[v].erase(std::find(in_[v].begin(), in_[v].end(), u));
    if(fe.behind != Face_handle() && fe.behind->is_in_domain()) remove_front_edge_from_face(fe.behind);
    update_vertex_state(u);
    update_vertex_state(v);
  }

  // A face enters the circle octree with its first front edge and leaves
  // it with its last: the octree holds exactly the front triangles.
  void add_front_edge_to_face(Face_handle f)
  {
    auto it = face_records_.find(f);
    if(it != face_records_.end()) {
      ++it->second.front_edges;
      return;
    }
    const Circle c = circle_of(f);
    face_records_.emplace(f, Face_record{triangle_octree_.insert(c.cx, c.cy, c.r, f), 1});
    stats_.largest_live_triangles = (std::max)(stats_.largest_live_triangles, face_records_.size());
  }

  void remove_front_edge_from_face(Face_handle f)
  {
    auto it = face_records_.find(f);
    CGAL_assertion(it != face_records_.end());
    if(--it->second.front_edges == 0) {
      triangle_octree_.remove(it->second.circle_item);
      face_records_.erase(it);
    }
  }

  void build_front()
  {
    std::vector<Face_handle> domain_faces;
    double xmin = (std::numeric_limits<double>::max)(), ymin = xmin;
    double xmax = -xmin, ymax = -xmin;
    for(auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      domain_faces.push_back(f);
      for(int i = 0; i < 3; ++i) {
        Vertex_handle vh = f->vertex(i);
        if(vid_.find(vh) == vid_.end()) {
          const Vid id = add_vertex(vh);
          xmin = (std::min)(xmin, x(id)); xmax = (std::max)(xmax, x(id));
          ymin = (std::min)(ymin, y(id)); ymax = (std::max)(ymax, y(id));
        }
      }
    }
    if(domain_faces.empty()) {
      finished_ = true;
      return;
    }
    // The octrees' root box: circles of triangles that will ever exist lie
    // near the domain; generous padding keeps the overflow list short.
    const double span = (std::max)(xmax - xmin, ymax - ymin);
    triangle_octree_.reset(xmin - span, ymin - span, xmax + span, ymax + span, 2 * span);
    edge_octree_.reset(xmin - span, ymin - span, xmax + span, ymax + span, 2 * span);

    struct Pending { Vid u, v; Face_handle behind; int index; bool constrained; };
    std::vector<Pending> pending;
    for(Face_handle f : domain_faces) {
      domain_area_ += std::abs(triangle_area(f));
      for(int i = 0; i < 3; ++i) {
        Face_handle g = f->neighbor(i);
        // edge i of f, directed with f (soon unmeshed) on its left
        const Vid u = id_of(f->vertex(ccw(i))), v = id_of(f->vertex(cw(i)));
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
    for(Face_handle f : domain_faces) {
      for(int i = 0; i < 3; ++i) {
        Face_handle g = f->neighbor(i);
        if(!g->is_in_domain()) g->set_neighbor(g->index(f), Face_handle());
      }
    }
    for(Face_handle f : domain_faces) tds().delete_face(f);
    // the input constraints never change: a static index of them answers
    // the visibility questions of the circle search
    constraint_octree_.reset(xmin - span, ymin - span, xmax + span, ymax + span, 2 * span);
    for(const Pending& p : pending) {
      if(p.u > p.v && p.behind == Face_handle()) continue; // interior constraint: once
      const double dx = x(p.v) - x(p.u), dy = y(p.v) - y(p.u);
      constraint_octree_.insert(0.5 * (x(p.u) + x(p.v)), 0.5 * (y(p.u) + y(p.v)),
                                0.5 * std::hypot(dx, dy), key(p.u, p.v));
    }
    for(const Pending& p : pending) add_front_edge(p.u, p.v, p.behind, p.index, p.constrained);
    for(Vid v = 0; v < vertex_.size(); ++v) update_vertex_state(v);
    if(front_.empty()) finished_ = true;
  }

  double triangle_area(Face_handle f) const
  {
    const double ax = CGAL::to_double(f->vertex(0)->point().x()), ay = CGAL::to_double(f->vertex(0)->point().y());
    const double bx = CGAL::to_double(f->vertex(1)->point().x()), by = CGAL::to_double(f->vertex(1)->point().y());
    const double cx = CGAL::to_double(f->vertex(2)->point().x()), cy = CGAL::to_double(f->vertex(2)->point().y());
    return 0.5 * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
  }

  // ------------------------------------------------- creating and removing
  // Creates the triangle (a, b, c), counter-clockwise, in the unmeshed
  // region. Each of its edges either closes the front edge that faces it or
  // becomes a new front edge facing the other way. Appends new front edges
  // to `created` when given.
  Face_handle make_triangle(Vid a, Vid b, Vid c, std::vector<Edge_key>* created = nullptr)
  {
    CGAL_precondition(pred_.orientation(pt(a), pt(b), pt(c)) == LEFT_TURN);
    Face_handle f = tds().create_face(vertex_[a], vertex_[b], vertex_[c]);
    f->set_in_domain(true);
    const std::array<Vid, 3> vs = {{a, b, c}};
    for(int k = 0; k < 3; ++k) {
      // edge k of f is opposite vertex k, directed vs[k+1] -> vs[k+2] with f on its left
      const Vid s = vs[ccw(k)], t = vs[cw(k)];
      auto it = front_.find(key(s, t));
      if(it != front_.end()) {
        const Front_edge fe = it->second;
        f->set_constraint(k, fe.constrained);
        if(fe.behind != Face_handle()) {
          f->set_neighbor(k, fe.behind);
          fe.behind->set_neighbor(fe.behind_index, f);
        } else {
          f->set_neighbor(k, Face_handle());
          // a virgin side of a constraint: the other side now faces f
          auto rev = front_.find(key(t, s));
          if(rev != front_.end()) {
            rev->second.behind = f;
            rev->second.behind_index = k;
            add_front_edge_to_face(f);
          }
        }
        remove_front_edge(s, t);
      } else {
        f->set_constraint(k, false);
        f->set_neighbor(k, Face_handle());
        add_front_edge(t, s, f, k, false);
        if(created) created->push_back(key(t, s));
      }
    }
    for(Vid v : vs) {
      vertex_[v]->set_face(f);
      ++tri_count_[v];
      update_vertex_state(v);
    }
    meshed_area_ += std::abs(triangle_area(f));
    visitor_.on_face_created(f);
    return f;
  }

  // Removes a mesh face whose circle was broken. Its edges facing the
  // remaining mesh (or the outside) become front edges; the front edges it
  // had disappear into the unmeshed region, except constraints, which stay
  // front edges on both sides.
  void remove_triangle(Face_handle f, std::vector<Edge_key>* created)
  {
    visitor_.on_face_removed(f);
    std::array<Vid, 3> vs;
    for(int k = 0; k < 3; ++k) vs[k] = id_of(f->vertex(k));
    for(int k = 0; k < 3; ++k) {
      const Vid s = vs[ccw(k)], t = vs[cw(k)];
      Face_handle g = f->neighbor(k);
      const bool constrained = f->is_constrained(k);
      if(g == Face_handle()) {
        // the unmeshed region is beyond: front edge t -> s has f behind it
        CGAL_assertion(front_.find(key(t, s)) != front_.end());
        if(constrained) {
          auto rev = front_.find(key(t, s));
          rev->second.behind = Face_handle();
          rev->second.behind_index = -1;
          remove_front_edge_from_face(f);
          add_front_edge(s, t, Face_handle(), -1, true);
          if(created) created->push_back(key(s, t));
        } else {
          remove_front_edge(t, s);
        }
      } else {
        const int j = g->index(f);
        g->set_neighbor(j, Face_handle());
        add_front_edge(s, t, g, j, constrained);
        if(created) created->push_back(key(s, t));
      }
    }
    meshed_area_ -= std::abs(triangle_area(f));
    tds().delete_face(f);
    for(Vid v : vs) {
      --tri_count_[v];
      update_vertex_state(v);
    }
    ++stats_.triangles_removed;
  }

  // -------------------------------------------------- the neighbourhood
  void gather(double cx, double cy, double radius, Neighbourhood& n)
  {
    n.cx = cx;
    n.cy = cy;
    n.radius = radius;
    n.vertices.clear();
    n.edges.clear();
    index_.query(cx, cy, radius, n.vertices);
    ++stats_.point_search_queries;
    edge_octree_.query(cx, cy, radius, [&n](Edge_key k) { n.edges.push_back(k); });
    ++stats_.edge_octree_queries;
  }

  // Is the direction from front vertex v towards q inside the unmeshed
  // region at v? The unmeshed sectors at v run counter-clockwise from each
  // outgoing front edge to the first incoming one. Directions strictly
  // inside a sector qualify, and so do the sector's own bounding front
  // edges when q is their other end point (vertex id qid): the segment is
  // then that front edge, which a triangle may close.
  bool in_free_sector(Vid v, const Point& q, Vid qid = no_vertex) const
  {
    if(out_[v].empty()) return in_[v].empty();
    const Point& pv = pt(v);
    for(Vid o : out_[v]) {
      Vid closing = no_vertex;
      for(Vid i : in_[v])
        if(closing == no_vertex || pred_.turns_before(pv, pt(o), pt(i), pt(closing))) closing = i;
      if(closing == no_vertex) continue;
      if(qid != no_vertex && (qid == o || qid == closing)) return true;
      if(pred_.turn_region(pv, pt(o), q) == 3) continue;
      if(pred_.turns_before(pv, pt(o), q, pt(closing))) return true;
    }
    return false;
  }

  // Does front edge (g, h) block the segment s-t (s, t given as vertex ids,
  // or no_vertex for the new point)?
  bool edge_blocks(Vid g, Vid h, Vid s, const Point& ps, Vid t, const Point& pt_) const
  {
    if((g == s && h == t) || (g == t && h == s)) return false;
    const bool gs = (g == s), gt = (g == t), hs = (h == s), ht = (h == t);
    if(gs || hs) return pred_.overlap_from_shared_end(ps, pt(gs ? h : g), pt_);
    if(gt || ht) return pred_.overlap_from_shared_end(pt_, pt(gt ? h : g), ps);
    return pred_.closed_segments_meet(ps, pt_, pt(g), pt(h));
  }

  // Is the open segment s-t inside the unmeshed region: leaving s and t
  // into free sectors, crossing no front edge and passing through no
  // vertex? Complete when the segment lies in the neighbourhood's disk.
  bool visible(Vid s, const Point& ps, Vid t, const Point& pt_, const Neighbourhood& n) const
  {
    if(s != no_vertex && !in_free_sector(s, pt_, t)) return false;
    if(t != no_vertex && !in_free_sector(t, ps, s)) return false;
    for(Edge_key k : n.edges) {
      if(front_.find(k) == front_.end()) continue;
      if(edge_blocks(source(k), target(k), s, ps, t, pt_)) return false;
    }
    for(std::size_t z : n.vertices) {
      if(z == s || z == t) continue;
      if(pred_.in_open_segment(ps, pt_, pt(Vid(z)))) return false;
      // edges created after the neighbourhood was gathered all have an end
      // point in it, so the adjacency lists cover them
      for(Vid w : out_[z])
        if(edge_blocks(Vid(z), w, s, ps, t, pt_)) return false;
    }
    return true;
  }

  // Step 5, Merriam's iteration: the Delaunay apex of front edge a -> b
  // among the neighbourhood's vertices visible from both end points, i.e.
  // the candidate whose circle through a and b contains no other candidate.
  Vid delaunay_apex(Vid a, Vid b, const Neighbourhood& n)
  {
    const Point& pa = pt(a);
    const Point& pb = pt(b);
    candidates_.clear();
    for(std::size_t z : n.vertices) {
      const Vid c = Vid(z);
      if(c == a || c == b) continue;
      const Point& pc = pt(c);
      if(pred_.orientation(pa, pb, pc) != LEFT_TURN) continue;
      if(!in_free_sector(a, pc, c) || !in_free_sector(b, pc, c)) continue;
      if(!in_free_sector(c, pa, a) || !in_free_sector(c, pb, b)) continue;
      candidates_.push_back(c);
    }
    while(!candidates_.empty()) {
      std::size_t best = 0;
      for(std::size_t i = 1; i < candidates_.size(); ++i) {
        ++stats_.incircle_tests;
        if(pred_.strictly_inside_circle(pa, pb, pt(candidates_[best]), pt(candidates_[i]))) best = i;
      }
      const Vid c = candidates_[best];
      if(visible(a, pa, c, pt(c), n) && visible(b, pb, c, pt(c), n)) return c;
      candidates_.erase(candidates_.begin() + best);
    }
    return no_vertex;
  }

  // ------------------------------------------------------------- one step
  bool step()
  {
    while(!queue_.empty()) {
      const Queue_entry e = queue_.top();
      queue_.pop();
      auto it = front_.find(e.key);
      if(it == front_.end() || it->second.version != e.version) continue;
      ++stats_.front_edges_processed;
      process_edge(source(e.key), target(e.key));
      // A new point may leave the edge open (its apex after the cavity was
      // another point): the edge stays on the front and must be queued again.
      auto left = front_.find(e.key);
      if(left != front_.end()) queue_.push(Queue_entry{e.length, e.key, left->second.version});
      visitor_.on_progress(domain_area_ > 0 ? (std::min)(1., meshed_area_ / domain_area_) : 1.);
      return true;
    }
    return false;
  }

  void process_edge(Vid a, Vid b)
  {
    const double ax = x(a), ay = y(a), bx = x(b), by = y(b);
    const double L = std::hypot(bx - ax, by - ay);
    const double mx = 0.5 * (ax + bx), my = 0.5 * (ay + by);
    const double nx = -(by - ay) / L, ny = (bx - ax) / L; // unit normal towards the unmeshed side
    const double rho = target_circumradius(mx, my);       // step 3
    const double accept = closure_tolerance * rho;

    // step 6's ideal distance from the midpoint along the bisector: the
    // point making a triangle of circumradius rho, or the diametral circle
    // when rho is smaller than half the edge
    const double d_target = (rho >= 0.5 * L) ? rho + std::sqrt(rho * rho - 0.25 * L * L) : 0.5 * L;
    // The search covers every circle through a and b that matters: those
    // small enough to accept, and those whose centre lies before d_target
    // (which limit the new point's position, Fig. 7).
    const double radius = (std::max)(2 * accept, d_target + std::sqrt(d_target * d_target + 0.25 * L * L));
    gather(mx, my, radius, nbh_);                                 // step 4
    const Vid w = delaunay_apex(a, b, nbh_);                      // step 5
    double d = d_target;
    if(w != no_vertex) {
      const Circle c = circle_of(a, b, w);
      const double centre_offset = std::hypot(c.cx - mx, c.cy - my);
      const bool complete = centre_offset + c.r <= radius;
      if(complete && c.r <= accept) {                             // step 6: close
        close_on_existing_point(a, b, w);
        return;
      }
      const double h_w = (c.cx - mx) * nx + (c.cy - my) * ny;     // signed height of its centre
      if(h_w < d_target) {
        if(h_w < placement_floor * L) {
          // no room for a point between the edge and the circle: close
          ++stats_.forced_closures;
          close_on_existing_point(a, b, w);
          return;
        }
        d = h_w;                                                  // upper clamp (Fig. 7)
      }
    }
    const double px = mx + d * nx, py = my + d * ny;
    if(insert_point(a, b, px, py, d, rho)) return;
    ++stats_.rejected_points;
    ++stats_.forced_closures;
    forced_closure(a, b, radius);
  }

  void close_on_existing_point(Vid a, Vid b, Vid c)
  {
    ++stats_.triangles_closed_on_existing_points;
    make_triangle(a, b, c);
  }

  // Closes a -> b on its constrained Delaunay apex whatever its size. The
  // unmeshed region is a polygonal region bounded by the front, so the apex
  // exists; the search grows until the apex's circle lies in the searched
  // disk, which makes it the true apex.
  void forced_closure(Vid a, Vid b, double radius)
  {
    const double mx = 0.5 * (x(a) + x(b)), my = 0.5 * (y(a) + y(b));
    const double L = std::hypot(x(b) - x(a), y(b) - y(a));
    double r = (std::max)(radius, L);
    for(;;) {
      gather(mx, my, r, nbh_);
      // the search is exhaustive once it holds every active vertex (or its
      // radius stopped being a number): the loop ends on that, not on a count
      const bool everything = nbh_.vertices.size() >= index_.size() || !std::isfinite(r);
      const Vid w = delaunay_apex(a, b, nbh_);
      if(w != no_vertex) {
        const Circle c = circle_of(a, b, w);
        const double needed = std::hypot(c.cx - mx, c.cy - my) + c.r;
        if(needed <= r || everything) {
          close_on_existing_point(a, b, w);
          return;
        }
        r = (std::max)(2 * r, needed * (1 + 1e-9));
      } else {
        if(everything) {
          throw std::logic_error("Advancing_front_mesher_2: internal error: a front edge has no "
                                 "visible apex (the front is inconsistent)");
        }
        r *= 2;
      }
    }
  }

  // The circle of face f contains p and p can see f, as constrained
  // Delaunay insertion requires: p is inside f, or the segment from p to a
  // point of f (its centroid, or the midpoint of one of its front edges)
  // crosses no input constraint. Non-constraint front edges do not hide
  // anything: they are not edges of the final triangulation's constraints.
  // Faces reached only through the mesh are found by the neighbour walk
  // (Fig. 6). Without this test, a triangle whose circle reaches across a
  // thin wall (a plate, a hole) would be removed for a point that cannot
  // see it, opening a cavity that point cannot fill.
  bool is_broken(Face_handle f, const Point& p, double px, double py)
  {
    ++stats_.incircle_tests;
    if(!pred_.strictly_inside_circle(f->vertex(0)->point(), f->vertex(1)->point(),
                                     f->vertex(2)->point(), p))
      return false;
    const Vid v0 = id_of(f->vertex(0)), v1 = id_of(f->vertex(1)), v2 = id_of(f->vertex(2));
    bool inside = true;
    for(int i = 0; i < 3; ++i)
      if(pred_.orientation(f->vertex(ccw(i))->point(), f->vertex(cw(i))->point(), p) == RIGHT_TURN)
        inside = false;
    if(inside) return true;
    if(sees_point(p, px, py, (x(v0) + x(v1) + x(v2)) / 3, (y(v0) + y(v1) + y(v2)) / 3)) return true;
    for(int i = 0; i < 3; ++i) {
      if(f->neighbor(i) != Face_handle()) continue;
      const Vid g = id_of(f->vertex(ccw(i))), h = id_of(f->vertex(cw(i)));
      if(sees_point(p, px, py, 0.5 * (x(g) + x(h)), 0.5 * (y(g) + y(h)))) return true;
    }
    return false;
  }

  // Does the segment from p to (qx, qy) cross no input constraint? The end
  // point is rounded; this only selects which triangles are removed.
  bool sees_point(const Point& p, double px, double py, double qx, double qy)
  {
    const Point q(qx, qy);
    bool blocked = false;
    ++stats_.edge_octree_queries;
    constraint_octree_.query(0.5 * (px + qx), 0.5 * (py + qy), 0.5 * std::hypot(qx - px, qy - py),
                             [&](Edge_key k) {
      if(blocked) return;
      const Point& pu = pt(source(k));
      const Point& pv = pt(target(k));
      // a proper crossing only: touching an end point does not hide
      const Orientation o1 = pred_.orientation(p, q, pu), o2 = pred_.orientation(p, q, pv);
      if(o1 == COLLINEAR || o2 == COLLINEAR || o1 == o2) return;
      const Orientation o3 = pred_.orientation(pu, pv, p), o4 = pred_.orientation(pu, pv, q);
      if(o3 == COLLINEAR || o4 == COLLINEAR || o3 == o4) return;
      blocked = true;
    });
    return !blocked;
  }

  // Steps 6-12 for a new point p = (px, py) ahead of front edge a -> b.
  // Returns false (leaving the mesh unchanged) when p is not acceptable.
  bool insert_point(Vid a, Vid b, double px, double py, double d, double rho)
  {
    if(!std::isfinite(px) || !std::isfinite(py)) return false;
    const Point p(px, py);
    if(pred_.orientation(pt(a), pt(b), p) != LEFT_TURN) return false;

    // steps 7-8: broken front triangles from the circle octree, interior
    // ones by walking across unconstrained edges
    broken_.clear();
    broken_set_.clear();
    ++stats_.triangle_octree_queries;
    triangle_octree_.query(px, py, 0., [this, &p, px, py](Face_handle f) {
      if(broken_set_.find(f) == broken_set_.end() && is_broken(f, p, px, py)) {
        broken_set_.insert(f);
        broken_.push_back(f);
      }
    });
    for(std::size_t i = 0; i < broken_.size(); ++i) {
      Face_handle f = broken_[i];
      for(int k = 0; k < 3; ++k) {
        if(f->is_constrained(k)) continue;
        Face_handle g = f->neighbor(k);
        if(g == Face_handle() || !g->is_in_domain() || broken_set_.count(g)) continue;
        ++stats_.incircle_tests;
        if(pred_.strictly_inside_circle(g->vertex(0)->point(), g->vertex(1)->point(),
                                        g->vertex(2)->point(), p)) {
          broken_set_.insert(g);
          broken_.push_back(g);
        }
      }
    }
    // step 10: the size bound grows to the largest broken circle
    const Circle cp = circle_of(x(a), y(a), x(b), y(b), px, py);
    double rho_new = (std::max)(rho, cp.r);
    for(Face_handle f : broken_) rho_new = (std::max)(rho_new, circle_of(f).r);
    if(rho_new > (std::max)(rho, cp.r)) ++stats_.size_bound_raised;

    // step 9: remove them, remembering them to restore them if p is rejected
    removed_.clear();
    cavity_edges_.clear();
    for(Face_handle f : broken_) {
      removed_.push_back({{id_of(f->vertex(0)), id_of(f->vertex(1)), id_of(f->vertex(2))}});
      remove_triangle(f, &cavity_edges_);
    }

    // Triangles about p are accepted up to the local bound, and up to the
    // raised bound of step 10 when they are not needles: a large cavity is
    // reconnected to p as the paper does (which is what lets fronts of very
    // different sizes merge, Fig. 9), but a cavity vertex nearly in line
    // with p and a short cavity edge is left to later steps instead of
    // making a sliver. Every accepted circle passes through p with radius
    // at most `accept_raised`, so the disk of twice that about p holds
    // every point that matters.
    const double accept = closure_tolerance * (std::max)(rho, cp.r);
    const double accept_raised = closure_tolerance * rho_new;
    const double star_radius = (std::max)({2 * accept_raised, std::hypot(px - x(a), py - y(a)),
                                           std::hypot(px - x(b), py - y(b))}) * (1 + 1e-9);
    gather(px, py, star_radius, nbh_);
    if(!is_acceptable_point(a, b, p, px, py, d)) {
      for(const std::array<Vid, 3>& t : removed_) make_triangle(t[0], t[1], t[2]);
      stats_.triangles_removed -= removed_.size();
      return false;
    }

    // p is inside the unmeshed region: insert it
    Vertex_handle vh = tds().create_vertex();
    vh->set_point(p);
    const Vid pid = add_vertex(vh);
    update_vertex_state(pid);
    ++stats_.points_inserted;
    visitor_.on_point_inserted(vh);

    // steps 11-12: the Delaunay triangles about p within the size bound,
    // found by closing, with Merriam's iteration, the front edges that can
    // reach p: the current edge, the cavity's boundary, and then each front
    // edge at p in turn, which turns the fan about p in both directions
    gather(px, py, star_radius, nbh_);
    work_.clear();
    work_.push_back(key(a, b));
    for(Edge_key k : cavity_edges_) work_.push_back(k);
    std::vector<Edge_key> created;
    while(!work_.empty()) {
      const Edge_key k = work_.back();
      work_.pop_back();
      if(front_.find(k) == front_.end()) continue;
      const Vid u = source(k), v = target(k);
      const bool at_p = (u == pid || v == pid);
      if(!at_p && pred_.orientation(pt(u), pt(v), p) != LEFT_TURN) continue;
      if(std::hypot(x(u) - px, y(u) - py) > star_radius || std::hypot(x(v) - px, y(v) - py) > star_radius)
        continue;
      const Vid w = delaunay_apex(u, v, nbh_);
      if(w == no_vertex) continue;
      if(!at_p && w != pid) continue;
      const Circle c = circle_of(u, v, w);
      if(std::hypot(c.cx - px, c.cy - py) + c.r > star_radius) continue;
      if(c.r > accept && !(u == a && v == b) &&
         (c.r > accept_raised || radius_ratio(u, v, w) < raised_bound_min_quality))
        continue;
      created.clear();
      make_triangle(u, v, w, &created);
      ++stats_.triangles_around_new_points;
      for(Edge_key e : created)
        if(source(e) == pid || target(e) == pid) work_.push_back(e);
    }
    return true;
  }

  // A placed point is kept only if it lies strictly inside the unmeshed
  // region (seen from a and b through the region, so not across the front
  // or a constraint) and not too close to any front point or edge: such a
  // point would make a needle, and the closure fallback does better there.
  bool is_acceptable_point(Vid a, Vid b, const Point& p, double px, double py, double d) const
  {
    const double min_dist = point_clearance * d;
    for(std::size_t z : nbh_.vertices) {
      if(std::hypot(x(Vid(z)) - px, y(Vid(z)) - py) < min_dist) return false;
      if(pt(Vid(z)) == p) return false;
    }
    if(!visible(a, pt(a), no_vertex, p, nbh_) || !visible(b, pt(b), no_vertex, p, nbh_)) return false;
    auto too_close = [&](Vid g, Vid h) {
      return segment_distance(px, py, x(g), y(g), x(h), y(h)) < min_dist;
    };
    for(Edge_key k : nbh_.edges)
      if(front_.find(k) != front_.end() && too_close(source(k), target(k))) return false;
    for(std::size_t z : nbh_.vertices)
      for(Vid w : out_[z])
        if(too_close(Vid(z), w)) return false;
    return true;
  }

  double radius_ratio(Vid a, Vid b, Vid c) const
  {
    const double l0 = std::hypot(x(b) - x(c), y(b) - y(c)), l1 = std::hypot(x(a) - x(c), y(a) - y(c)),
                 l2 = std::hypot(x(a) - x(b), y(a) - y(b));
    const double area = 0.5 * std::abs((x(b) - x(a)) * (y(c) - y(a)) - (y(b) - y(a)) * (x(c) - x(a)));
    const double s = 0.5 * (l0 + l1 + l2);
    return 8 * area * area / (s * l0 * l1 * l2);
  }

  static double segment_distance(double px, double py, double ax, double ay, double bx, double by)
  {
    const double dx = bx - ax, dy = by - ay;
    const double l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
    t = (std::max)(0., (std::min)(1., t));
    return std::hypot(px - (ax + t * dx), py - (ay + t * dy));
  }

  // ---------------------------------------------------------- finishing
  // Used when a limit stops the run: closes the remaining front on
  // existing points only, which always terminates and leaves a valid mesh.
  void close_remaining_front()
  {
    // every front edge gets a fresh queue entry, so none can be missed
    for(const auto& fe : front_) {
      const Vid u = source(fe.first), v = target(fe.first);
      const double dx = x(v) - x(u), dy = y(v) - y(u);
      queue_.push(Queue_entry{std::hypot(dx, dy), fe.first, fe.second.version});
    }
    while(!queue_.empty()) {
      const Queue_entry e = queue_.top();
      queue_.pop();
      auto it = front_.find(e.key);
      if(it == front_.end() || it->second.version != e.version) continue;
      const Vid a = source(e.key), b = target(e.key);
      forced_closure(a, b, std::hypot(x(b) - x(a), y(b) - y(a)));
    }
  }

  void finish()
  {
    if(finished_) return;
    finished_ = true;
    CGAL_assertion(front_.empty());
    if(!front_.empty()) close_remaining_front(); // never expected; keeps the result valid
    restore_delaunay_property();
    // vertices may still point at faces deleted during meshing
    for(auto f = cdt_.all_faces_begin(); f != cdt_.all_faces_end(); ++f)
      for(int i = 0; i < 3; ++i) f->vertex(i)->set_face(f);
    std::size_t faces = 0;
    for(auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f)
      if(f->is_in_domain()) ++faces;
    stats_.number_of_faces = faces;
    stats_.number_of_vertices = cdt_.number_of_vertices();
    stats_.point_search_rebuilds = index_.number_of_rebuilds();
    CGAL_expensive_postcondition(cdt_.is_valid());
  }

  // Lawson's flips on unconstrained in-domain edges. The advancing front
  // builds a constrained Delaunay triangulation by itself, so this finds
  // nothing to flip (the tests assert it); it is kept as a guarantee.
  void restore_delaunay_property()
  {
    std::vector<std::pair<Face_handle, int> > stack;
    for(auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f)
      if(f->is_in_domain())
        for(int i = 0; i < 3; ++i) stack.emplace_back(f, i);
    while(!stack.empty()) {
      Face_handle f = stack.back().first;
      const int i = stack.back().second;
      stack.pop_back();
      if(f->is_constrained(i)) continue;
      Face_handle g = f->neighbor(i);
      if(!f->is_in_domain() || !g->is_in_domain() || cdt_.is_infinite(g) || cdt_.is_infinite(f)) continue;
      const int j = g->index(f);
      if(!pred_.strictly_inside_circle(f->vertex(0)->point(), f->vertex(1)->point(),
                                       f->vertex(2)->point(), g->vertex(j)->point()))
        continue;
      // the triangulation's flip keeps the constraint flags right
      cdt_.flip(f, i);
      ++stats_.delaunay_repair_flips;
      for(int k = 0; k < 3; ++k) {
        stack.emplace_back(f, k);
        stack.emplace_back(g, k);
      }
    }
  }

  // ------------------------------------------------------------ tuning
  // A triangle on an existing point is accepted up to this factor over
  // the size bound rho; a little slack avoids placing a point next to an
  // existing one when the closing triangle is barely too large.
  static constexpr double closure_tolerance = 1.25;
  // A new point clamped closer than this fraction of the edge length is not
  // placed: the existing apex is used instead.
  static constexpr double placement_floor = 0.3;
  // A new point must keep this fraction of its distance to the edge from
  // every other front point and edge.
  static constexpr double point_clearance = 0.5;
  // Triangles about a new point larger than the local bound (allowed by the
  // raised bound of step 10) must have at least this radius ratio.
  static constexpr double raised_bound_min_quality = 0.25;

  // ------------------------------------------------------------ members
  CDT& cdt_;
  Sizing_field sizing_;
  Visitor visitor_;
  Advancing_front_mesh_2::internal::Front_predicates<Geom_traits> pred_;
  Seeds seeds_;
  bool seeds_mark_ = false;
  bool initialized_ = false;
  bool finished_ = false;
  std::size_t iteration_limit_ = 0;
  double time_limit_ = 0;

  std::unordered_map<Edge_key, Front_edge> front_;
  std::vector<boost::container::small_vector<Vid, 2> > out_, in_;
  std::vector<Vertex_handle> vertex_;
  std::vector<std::array<double, 2> > xy_;
  std::vector<std::uint32_t> tri_count_;
  std::unordered_map<Vertex_handle, Vid, Handle_hash> vid_;
  std::unordered_map<Face_handle, Face_record, Handle_hash> face_records_;
  std::priority_queue<Queue_entry> queue_;
  std::uint32_t version_counter_ = 0;
  Advancing_front_mesh_2::internal::Dynamic_point_index index_;
  Triangle_octree triangle_octree_;
  Edge_octree edge_octree_;
  Edge_octree constraint_octree_;
  double meshed_area_ = 0, domain_area_ = 0;
  Advancing_front_mesh_2::Statistics stats_;

  // scratch space reused across steps
  Neighbourhood nbh_;
  std::vector<Vid> candidates_;
  std::vector<Face_handle> broken_;
  std::unordered_set<Face_handle, Handle_hash> broken_set_;
  std::vector<std::array<Vid, 3> > removed_;
  std::vector<Edge_key> cavity_edges_;
  std::vector<Edge_key> work_;
};

namespace Advancing_front_mesh_2 {
namespace internal {

template <class T, class = void>
struct Has_size_bound : std::false_type {};
template <class T>
struct Has_size_bound<T, decltype(void(std::declval<const T&>().size_bound()))> : std::true_type {};

// Turns what the user passed as "size" into a sizing field: a number is a
// uniform target edge length, a Mesh_2 size criteria object gives its
// size bound, anything else must be callable as FT(const Point_2&).
template <class Gt, class T, class = void>
struct Sizing_field_maker
{
  typedef T type;
  static const T& make(const T& t) { return t; }
};
template <class Gt, class T>
struct Sizing_field_maker<Gt, T, std::enable_if_t<std::is_arithmetic<T>::value ||
                                                  std::is_same<T, typename Gt::FT>::value> >
{
  typedef Uniform_sizing_field_2<Gt> type;
  static type make(const T& t)
  {
    // checked before the triangulation is touched
    const double h = CGAL::to_double(t);
    if(!(h > 0) || !std::isfinite(h))
      throw std::invalid_argument("advancing_front_mesh_2: the target edge length must be a positive finite number");
    return type(typename Gt::FT(t));
  }
};
template <class Gt, class T>
struct Sizing_field_maker<Gt, T, std::enable_if_t<Has_size_bound<T>::value> >
{
  typedef Size_criteria_sizing_field_2<T, Gt> type;
  static type make(const T& t)
  {
    if(!(t.size_bound() > 0))
      throw std::invalid_argument("advancing_front_mesh_2: the Mesh_2 criteria have no size bound "
                                  "(size_bound() == 0); an advancing front needs a size");
    return type(t);
  }
};

} // namespace internal
} // namespace Advancing_front_mesh_2

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Meshes the domain of `cdt` (seeds as in `refine_Delaunay_mesh_2()`: with
`mark == false` the components containing a seed are holes).

\param cdt the constrained Delaunay triangulation holding the constraints
\param seeds_begin, seeds_end the seeds
\param size either a number (the uniform target edge length `h`), a sizing
  field callable as `FT(const Point_2&)` returning `h` at a point (a lambda,
  Mesh_2's `Lipschitz_sizing_field_2`, ...), or a Mesh_2 size criteria object
  such as `Delaunay_mesh_size_criteria_2` (see
  `Advancing_front_mesh_2::Size_criteria_sizing_field_2` for the mapping)
\param mark the meaning of the seeds
\param np optional named parameters among:
\cgalNamedParamsBegin
  \cgalParamNBegin{visitor}
    \cgalParamDescription{a model of `AdvancingFrontMeshVisitor_2`}
    \cgalParamDefault{`Advancing_front_mesh_2::Default_visitor()`}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{stop after this many front edges (0: no limit)}
    \cgalParamDefault{0}
  \cgalParamNEnd
  \cgalParamNBegin{maximum_running_time}
    \cgalParamDescription{stop after this many seconds (0: no limit)}
    \cgalParamDefault{0}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns how the run ended; the triangulation is a valid mesh in every case.
\throws std::invalid_argument when the size is not a positive finite number
  (or the sizing field returns one that is not)
*/
template <class CDT, class InputIterator, class Size,
          class NamedParameters = parameters::Default_named_parameters>
Advancing_front_mesh_2::Mesh_return_code
advancing_front_mesh_2(CDT& cdt, InputIterator seeds_begin, InputIterator seeds_end,
                       const Size& size, bool mark = false,
                       const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CDT::Geom_traits Gt;
  typedef Advancing_front_mesh_2::internal::Sizing_field_maker<Gt, Size> Maker;
  typedef typename internal_np::Lookup_named_param_def<internal_np::visitor_t, NamedParameters,
                                                       Advancing_front_mesh_2::Default_visitor>::type Visitor;
  Visitor visitor = choose_parameter<Advancing_front_mesh_2::Default_visitor>(get_parameter(np, internal_np::visitor));
  Advancing_front_mesher_2<CDT, typename Maker::type, Visitor> mesher(cdt, Maker::make(size), visitor);
  mesher.set_seeds(seeds_begin, seeds_end, mark);
  mesher.set_iteration_limit(choose_parameter(get_parameter(np, internal_np::number_of_iterations), std::size_t(0)));
  mesher.set_time_limit(choose_parameter(get_parameter(np, internal_np::maximum_running_time), 0.));
  return mesher.refine_mesh();
}

/*!
\ingroup PkgAdvancingFrontMesh2Ref
Same as above without seeds: every bounded component is meshed.
*/
template <class CDT, class Size, class NamedParameters = parameters::Default_named_parameters>
Advancing_front_mesh_2::Mesh_return_code
advancing_front_mesh_2(CDT& cdt, const Size& size,
                       const NamedParameters& np = parameters::default_values())
{
  std::list<typename CDT::Point> no_seeds;
  return advancing_front_mesh_2(cdt, no_seeds.begin(), no_seeds.end(), size, false, np);
}

} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESHER_2_H
