// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STRIP_DECOMPOSITION_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STRIP_DECOMPOSITION_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesh_2/internal/Segment_size_division.h>
#include <CGAL/Advancing_front_mesh_2/split_constraints_to_size_2.h>

#include <CGAL/Handle_hash_function.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {
namespace internal {

// The decomposition of a meshing domain into parts that mesh independently:
// strips across the domain's longer axis, cut where the triangle count the
// size field predicts is divided evenly. Each cut is a line (x = c or
// y = c) placed clear of the input's vertices and crossing its constraints
// at a good angle; the constraints are split where they cross it, and the
// pieces of the line inside the domain (the interfaces) are discretised to
// the size field, once, so that the parts on both sides share their points.
// The parts are then meshed as separate domains, by threads or by other
// processes, and their meshes merged: the interfaces are not constraints,
// and the merged triangulation is constrained Delaunay across them.

// How one strip boundary was placed.
struct Strip_cut
{
  double position = 0;         // the line's coordinate along the axis
  double vertex_clearance = 0; // distance to the nearest vertex, in local sizes
  double crossing_sine = 1;    // least sine of the angles the constraints cross it at
};

struct Strip_plan
{
  int axis = 0;                     // 0: the cuts are lines x = c; 1: y = c
  std::vector<Strip_cut> cuts;      // increasing
  std::vector<double> estimated;    // the predicted triangle count of each part
  double estimated_total = 0;
};

// The triangle count a uniform mesh of edge length h has per unit area.
inline double triangles_per_area(double h) { return 1 / (0.4330127018922193 * h * h); }

// The predicted triangle count per slice along `axis`: the domain sampled on
// a grid of cells (`slices` along the axis), each in-domain cell centre
// counting its cell's area divided by the area of an equilateral triangle
// of the local size.
template <class CDT, class Field>
std::vector<double> predicted_triangles_by_slice(const CDT& cdt, const Field& field, int axis, double lo, double hi,
                                                 double other_lo, double other_hi, std::size_t slices,
                                                 std::size_t other_slices)
{
  typedef typename CDT::Point Point;
  typedef typename CDT::Face_handle Face_handle;
  std::vector<double> count(slices, 0.);
  const double step = (hi - lo) / double(slices), other_step = (other_hi - other_lo) / double(other_slices);
  const double cell_area = step * other_step;
  Face_handle hint;
  for(std::size_t j = 0; j < other_slices; ++j) {
    for(std::size_t i = 0; i < slices; ++i) {
      const double a = lo + (double(i) + 0.5) * step, b = other_lo + (double(j) + 0.5) * other_step;
      const Point p = axis == 0 ? Point(a, b) : Point(b, a);
      typename CDT::Locate_type lt;
      int li;
      const Face_handle f = cdt.locate(p, lt, li, hint);
      hint = f;
      if(lt == CDT::OUTSIDE_CONVEX_HULL || lt == CDT::OUTSIDE_AFFINE_HULL || cdt.is_infinite(f) ||
         !f->is_in_domain())
        continue;
      const double h = CGAL::to_double(field(p));
      if(!(h > 0) || !std::isfinite(h)) continue;
      count[i] += cell_area * triangles_per_area(h);
    }
  }
  return count;
}

// The constrained edges that bound or cross the domain, as vertex pairs.
template <class CDT>
std::vector<std::pair<typename CDT::Vertex_handle, typename CDT::Vertex_handle> >
domain_constraints(const CDT& cdt)
{
  std::vector<std::pair<typename CDT::Vertex_handle, typename CDT::Vertex_handle> > out;
  const Constraint_touches_domain<CDT> touches{&cdt};
  for(auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if(!cdt.is_constrained(*e) || !touches(*e)) continue;
    out.emplace_back(e->first->vertex(CDT::ccw(e->second)), e->first->vertex(CDT::cw(e->second)));
  }
  return out;
}

inline double coordinate(double x, double y, int axis) { return axis == 0 ? x : y; }

// What a cut must keep clear of: the vertices, with the local size at each
// and whether a constraint ends there, and the constraints, by the axis
// coordinates of their ends, their length and their extent along the axis.
struct Cut_obstacles
{
  struct Vertex_record
  {
    double along, h;
    bool on_constraint;
  };
  std::vector<Vertex_record> vertices;
  std::vector<std::array<double, 4> > segments;
};

template <class CDT, class Field>
Cut_obstacles cut_obstacles(const CDT& cdt, const Field& field, int axis)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  Cut_obstacles o;
  const auto constraints = domain_constraints(cdt);
  std::unordered_set<Vertex_handle, Handle_hash_function> on_constraints;
  for(const auto& c : constraints) {
    on_constraints.insert(c.first);
    on_constraints.insert(c.second);
  }
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    const double x = CGAL::to_double(v->point().x()), y = CGAL::to_double(v->point().y());
    o.vertices.push_back(Cut_obstacles::Vertex_record{coordinate(x, y, axis), CGAL::to_double(field(v->point())),
                                                      on_constraints.count(v) > 0});
  }
  for(const auto& c : constraints) {
    const double ax = CGAL::to_double(c.first->point().x()), ay = CGAL::to_double(c.first->point().y());
    const double bx = CGAL::to_double(c.second->point().x()), by = CGAL::to_double(c.second->point().y());
    const double a = coordinate(ax, ay, axis), b = coordinate(bx, by, axis);
    o.segments.push_back({{a, b, std::sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay)), std::abs(b - a)}});
  }
  return o;
}

// A cut at `c`, judged: a cut may pass exactly through vertices of the
// constraints (they are then its crossings, and no constraint is split next
// to them into a short piece), not through free points, not along a
// constraint; it must keep clear of the other vertices and cross the
// constraints steeply.
inline Strip_cut evaluate_cut(const Cut_obstacles& o, double c)
{
  Strip_cut cut;
  cut.position = c;
  cut.vertex_clearance = std::numeric_limits<double>::infinity();
  for(const Cut_obstacles::Vertex_record& v : o.vertices) {
    const double d = std::abs(v.along - c);
    if(d == 0) {
      if(!v.on_constraint) cut.vertex_clearance = 0;
    } else {
      cut.vertex_clearance = (std::min)(cut.vertex_clearance, v.h > 0 ? d / v.h : 0.);
    }
  }
  for(const auto& s : o.segments) {
    if(s[0] == c && s[1] == c) cut.vertex_clearance = 0; // along it
    else if((s[0] - c) * (s[1] - c) <= 0 && s[2] > 0) cut.crossing_sine = (std::min)(cut.crossing_sine, s[3] / s[2]);
  }
  return cut;
}

// The predicted counts of a domain by slice along an axis from `lo`, and
// their running sums.
struct Slice_counts
{
  double lo = 0, step = 0;
  std::vector<double> slice, cumulative; // cumulative[i]: the slices before i

  // the count below the coordinate `c`
  double below(double c) const
  {
    const std::size_t along = slice.size();
    const double u = (std::min)(double(along), (std::max)(0., (c - lo) / step));
    const std::size_t j = (std::min)(along - 1, std::size_t(u));
    return cumulative[j] + (u - double(j)) * slice[j];
  }
};

// The k-th of `parts` cuts: where the cumulative count reaches its share,
// or at the nearest place within 3% of the extent and 4% of a part's count
// that keeps half the local size clear of the vertices off it and crosses
// the constraints at 45 degrees or more: the candidates are the places
// every quarter slice and the constraint vertices there. Where there is
// none, the best place found (the part meshes either way, only the quality
// next to the interface suffers); a score of 0 or less when no place is
// usable. `previous` is the cut before (none for the first).
inline std::pair<Strip_cut, double> choose_cut(const Slice_counts& counts, const Cut_obstacles& obstacles, double hi,
                                               std::size_t k, std::size_t parts, const Strip_cut* previous)
{
  const double lo = counts.lo, step = counts.step;
  const std::size_t along = counts.slice.size();
  const double total = counts.cumulative.back();
  const double window = 0.03 * (hi - lo);
  const std::size_t max_candidates = 256;
  const double share = total * double(k) / double(parts);
  const std::size_t i = std::size_t(std::upper_bound(counts.cumulative.begin(), counts.cumulative.end(), share) -
                                    counts.cumulative.begin());
  const std::size_t slice_index = (std::min)(along - 1, i == 0 ? 0 : i - 1);
  const double in_slice = counts.slice[slice_index] > 0
                            ? (share - counts.cumulative[slice_index]) / counts.slice[slice_index]
                            : 0.5;
  const double target = lo + (double(slice_index) + (std::min)(1., (std::max)(0., in_slice))) * step;
  // within the window, and moving at most 4% of a part's count across
  auto balanced_enough = [&](double c) {
    return std::abs(c - target) <= window && std::abs(counts.below(c) - share) <= 0.04 * total / double(parts);
  };
  std::vector<double> candidates(1, target);
  // by index: far from the origin, adding a quarter slice may not move c
  const int quarters = int(std::ceil(window / (step / 4)));
  for(int q = -quarters; q <= quarters; ++q) {
    const double c = target + q * (step / 4);
    if(balanced_enough(c)) candidates.push_back(c);
  }
  for(const Cut_obstacles::Vertex_record& v : obstacles.vertices)
    if(v.on_constraint && balanced_enough(v.along)) candidates.push_back(v.along);
  std::sort(candidates.begin(), candidates.end(),
            [target](double a, double b) { return std::abs(a - target) < std::abs(b - target); });
  if(candidates.size() > max_candidates) candidates.resize(max_candidates);
  Strip_cut best;
  double best_score = -1;
  for(double c : candidates) {
    if(!(c > lo) || !(c < hi)) continue;
    if(previous != nullptr && !(c > previous->position + step)) continue;
    const Strip_cut cut = evaluate_cut(obstacles, c);
    const double score = (std::min)(cut.vertex_clearance / 0.5, cut.crossing_sine / 0.7071);
    if(score > best_score) {
      best = cut;
      best_score = score;
    }
    if(score >= 1) break;
  }
  return std::make_pair(best, best_score);
}

// Plans `parts` strips (fewer when the domain is too small for them: each
// part should hold at least `min_part_triangles`). The cuts are not made.
template <class CDT, class Field>
Strip_plan plan_strips(const CDT& cdt, const Field& field, std::size_t parts, double min_part_triangles = 2000,
                       std::size_t samples_along = 512)
{
  Strip_plan plan;
  if(cdt.dimension() < 2 || parts < 2) return plan;
  // the domain's bounding box
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    for(int k = 0; k < 3; ++k) {
      const double x = CGAL::to_double(f->vertex(k)->point().x()), y = CGAL::to_double(f->vertex(k)->point().y());
      x0 = (std::min)(x0, x); x1 = (std::max)(x1, x);
      y0 = (std::min)(y0, y); y1 = (std::max)(y1, y);
    }
  }
  if(!(x1 > x0) || !(y1 > y0) || !std::isfinite(x1 - x0) || !std::isfinite(y1 - y0)) return plan;
  plan.axis = (x1 - x0) >= (y1 - y0) ? 0 : 1;
  const double lo = plan.axis == 0 ? x0 : y0, hi = plan.axis == 0 ? x1 : y1;
  const double olo = plan.axis == 0 ? y0 : x0, ohi = plan.axis == 0 ? y1 : x1;
  const std::size_t along = samples_along;
  const std::size_t across = (std::max)(std::size_t(16), (std::min)(along, std::size_t(double(along) * (ohi - olo) / (hi - lo)) + 1));
  Slice_counts counts;
  counts.lo = lo;
  counts.step = (hi - lo) / double(along);
  counts.slice = predicted_triangles_by_slice(cdt, field, plan.axis, lo, hi, olo, ohi, along, across);
  counts.cumulative.assign(along + 1, 0.);
  for(std::size_t i = 0; i < along; ++i) counts.cumulative[i + 1] = counts.cumulative[i] + counts.slice[i];
  const double total = counts.cumulative.back();
  plan.estimated_total = total;
  // in doubles: a tiny size predicts more triangles than a size_t holds
  const double fitting = std::floor(total / min_part_triangles);
  if(!(fitting >= 2)) return plan;
  if(fitting < double(parts)) parts = std::size_t(fitting);

  const Cut_obstacles obstacles = cut_obstacles(cdt, field, plan.axis);
  for(std::size_t k = 1; k < parts; ++k) {
    const auto chosen = choose_cut(counts, obstacles, hi, k, parts, plan.cuts.empty() ? nullptr : &plan.cuts.back());
    if(chosen.second > 0) plan.cuts.push_back(chosen.first);
  }
  // the predicted count of each part, from the slices
  plan.estimated.assign(plan.cuts.size() + 1, 0.);
  for(std::size_t i = 0; i < along; ++i) {
    const double centre = lo + (double(i) + 0.5) * counts.step;
    std::size_t part = 0;
    while(part < plan.cuts.size() && plan.cuts[part].position < centre) ++part;
    plan.estimated[part] += counts.slice[i];
  }
  return plan;
}

// Splits every constraint that bounds or crosses the domain where it
// crosses the cut; returns the crossings: the vertices made there (on the
// constraints, rounded) and the constraints' vertices on the line. Throws std::runtime_error when a cut could not be placed on
// its constraint (the caller meshes in one part instead).
template <class CDT, class OnSplit>
std::vector<typename CDT::Vertex_handle> cut_constraints(CDT& cdt, int axis, double c, OnSplit& on_split)
{
  typedef typename CDT::Vertex_handle Vertex_handle;
  std::vector<Vertex_handle> made;
  auto record = [&](Vertex_handle a, Vertex_handle b, Vertex_handle v) {
    made.push_back(v);
    on_split(a, b, v);
  };
  Constraint_split_statistics st;
  std::unordered_set<Vertex_handle, Handle_hash_function> on_line;
  for(const auto& e : domain_constraints(cdt)) {
    const double a = coordinate(CGAL::to_double(e.first->point().x()), CGAL::to_double(e.first->point().y()), axis);
    const double b = coordinate(CGAL::to_double(e.second->point().x()), CGAL::to_double(e.second->point().y()), axis);
    // a vertex on the line is a crossing as it is
    if(a == c && on_line.insert(e.first).second) made.push_back(e.first);
    if(b == c && on_line.insert(e.second).second) made.push_back(e.second);
    if(!((a - c) * (b - c) < 0)) continue;
    const std::vector<double> t(1, (c - a) / (b - a));
    split_constrained_edge(cdt, e.first, e.second, t, record, st);
  }
  if(st.points_skipped > 0)
    throw std::runtime_error("a constraint could not be split where it crosses the cut");
  return made;
}

// The interfaces along one cut: the pieces of the line between consecutive
// crossing points that lie inside the domain, each discretised to the size
// field (end points included, in order along the line).
template <class CDT, class Field>
std::vector<std::vector<typename CDT::Point> >
interface_chains(const CDT& cdt, const Field& field, int axis, std::vector<typename CDT::Vertex_handle> crossings)
{
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  const int other = 1 - axis;
  auto along = [other](Vertex_handle v) {
    return coordinate(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()), other);
  };
  std::sort(crossings.begin(), crossings.end(), [&](Vertex_handle u, Vertex_handle v) { return along(u) < along(v); });
  std::vector<std::vector<Point> > chains;
  for(std::size_t j = 0; j + 1 < crossings.size(); ++j) {
    const double ax = CGAL::to_double(crossings[j]->point().x()), ay = CGAL::to_double(crossings[j]->point().y());
    const double bx = CGAL::to_double(crossings[j + 1]->point().x()), by = CGAL::to_double(crossings[j + 1]->point().y());
    if(!(along(crossings[j + 1]) > along(crossings[j])))
      throw std::runtime_error("two constraints cross the cut at the same point");
    const Point mid(0.5 * (ax + bx), 0.5 * (ay + by));
    typename CDT::Locate_type lt;
    int li;
    const auto f = cdt.locate(mid, lt, li);
    if(lt != CDT::FACE) {
      if(lt == CDT::EDGE && !cdt.is_constrained(typename CDT::Edge(f, li)) && f->is_in_domain() &&
         !cdt.is_infinite(f->neighbor(li)) && f->neighbor(li)->is_in_domain()) {
        // inside the domain, on an edge between two domain faces
      } else if(lt == CDT::EDGE && !cdt.is_constrained(typename CDT::Edge(f, li)) &&
                (cdt.is_infinite(f) || !f->is_in_domain())) {
        continue;
      } else {
        throw std::runtime_error("the cut runs along a constraint or through a vertex");
      }
    } else if(cdt.is_infinite(f) || !f->is_in_domain()) {
      continue;
    }
    const double length = std::sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
    const std::vector<double> ts = segment_cut_parameters(length, [&](double t) {
      return CGAL::to_double(field(Point(ax + t * (bx - ax), ay + t * (by - ay))));
    });
    std::vector<Point> chain(1, crossings[j]->point());
    for(double t : ts) chain.push_back(Point(ax + t * (bx - ax), ay + t * (by - ay)));
    chain.push_back(crossings[j + 1]->point());
    chains.push_back(std::move(chain));
  }
  return chains;
}

// The part (0 .. cuts.size()) of a point, by its coordinate along the axis.
inline std::size_t part_of(double coordinate_along_axis, const std::vector<Strip_cut>& cuts)
{
  std::size_t part = 0;
  while(part < cuts.size() && cuts[part].position < coordinate_along_axis) ++part;
  return part;
}

} // namespace internal
} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_INTERNAL_STRIP_DECOMPOSITION_2_H
