// Copyright (c) 2026 The Advancing_front_mesh_2 authors.
// All rights reserved.
//
// This file is part of the Advancing_front_mesh_2 add-on package for CGAL.
//
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Author(s) : The Advancing_front_mesh_2 authors

#ifndef CGAL_ADVANCING_FRONT_MESH_2_MESH_IN_PARALLEL_2_H
#define CGAL_ADVANCING_FRONT_MESH_2_MESH_IN_PARALLEL_2_H

#include <CGAL/license/Advancing_front_mesh_2.h>

#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Strip_decomposition_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Part_splicing_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Quality_smoother.h>
#include <CGAL/Advancing_front_mesh_2/internal/Star_smoother.h>

#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Handle_hash_function.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <exception>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Advancing_front_mesh_2 {

/*!
\ingroup PkgAdvancingFrontMesh2Ref

What `mesh_in_parallel_2()` did.
*/
struct Parallel_mesh_statistics
{
  /// the threads asked for, and the parts the domain was cut into (1: meshed
  /// in one piece, by today's serial mesher)
  std::size_t threads = 1, parts = 1;
  /// 0 when the cuts are lines x = c, 1 when y = c
  int axis = 0;
  /// the cut positions, increasing
  std::vector<double> cuts;
  /// the predicted and the actual triangle count of each part
  std::vector<double> predicted_triangles;
  std::vector<std::size_t> part_triangles;
  /// the points the cuts and their interfaces added to the boundary
  std::size_t cut_points = 0, interface_points = 0;
  /// why the domain was meshed in one piece, when it was (empty otherwise)
  std::string one_piece_reason;
  /// whether the parts' triangles were stitched into the triangulation
  /// (false: meshed in one piece)
  bool stitched = false;
  /// the vertices near the cuts that were smoothed, and what the smoothing did
  std::size_t seam_vertices = 0;
  Smoothing_statistics seam_smoothing;
  /// seconds: planning and cutting, meshing the parts (wall clock), merging,
  /// smoothing the seams
  double decomposition_time = 0, meshing_time = 0, merge_time = 0, seam_time = 0;
  /// the statistics of each part's mesher (one entry when meshed in one piece)
  std::vector<Statistics> part_statistics;
};

/*!
\ingroup PkgAdvancingFrontMesh2Ref

The statistics of several meshers as one: the counters summed, the largest
sizes (front, active vertices, ...) the largest of any, the times summed
(CPU time across the parts, not wall-clock time).
*/
inline Statistics sum_of(const std::vector<Statistics>& parts)
{
  Statistics s;
  for(const Statistics& p : parts) {
    s.front_edges_processed += p.front_edges_processed;
    s.points_inserted += p.points_inserted;
    s.triangles_closed_on_existing_points += p.triangles_closed_on_existing_points;
    s.forced_closures += p.forced_closures;
    s.rejected_points += p.rejected_points;
    s.triangles_around_new_points += p.triangles_around_new_points;
    s.triangles_removed += p.triangles_removed;
    s.size_bound_raised += p.size_bound_raised;
    s.broken_circle_queries += p.broken_circle_queries;
    s.constraint_index_queries += p.constraint_index_queries;
    s.point_search_queries += p.point_search_queries;
    s.incircle_tests += p.incircle_tests;
    s.largest_front = (std::max)(s.largest_front, p.largest_front);
    s.pockets += p.pockets;
    s.memory_compactions += p.memory_compactions;
    s.largest_active_vertices = (std::max)(s.largest_active_vertices, p.largest_active_vertices);
    s.largest_live_triangles = (std::max)(s.largest_live_triangles, p.largest_live_triangles);
    s.delaunay_repair_flips += p.delaunay_repair_flips;
    s.stream_sweeps += p.stream_sweeps;
    s.largest_triangles_in_memory = (std::max)(s.largest_triangles_in_memory, p.largest_triangles_in_memory);
    s.points_refused_for_finished_triangles += p.points_refused_for_finished_triangles;
    s.finished_triangles_broken += p.finished_triangles_broken;
    s.finished_triangles_held += p.finished_triangles_held;
    s.finished_edges_not_delaunay += p.finished_edges_not_delaunay;
    s.checkpoints_written += p.checkpoints_written;
    s.number_of_vertices += p.number_of_vertices;
    s.number_of_faces += p.number_of_faces;
    s.init_time += p.init_time;
    s.meshing_time += p.meshing_time;
  }
  return s;
}

namespace internal {

inline double parallel_seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// One part of a decomposed domain in a triangulation of its own: the
// constraints on its side of the cuts and the interface chains of the cuts
// around it; its faces are marked by their region (connected across
// unconstrained edges): a region is in the part when its largest face's
// centroid lies between the part's cuts and in the domain of `cdt`.
template <class CDT>
void build_part(const CDT& cdt, const internal::Strip_plan& plan, std::size_t part,
                const std::vector<std::pair<typename CDT::Point, typename CDT::Point> >& constraints,
                const std::vector<std::vector<std::vector<typename CDT::Point> > >& chains_of_cut,
                const std::vector<typename CDT::Point>& free_points, CDT& out)
{
  typedef typename CDT::Point Point;
  typedef typename CDT::Face_handle Face_handle;
  for(const auto& c : constraints) out.insert_constraint(c.first, c.second);
  for(std::size_t cut : {part - 1, part}) {
    if(cut >= chains_of_cut.size()) continue; // part - 1 wraps for part 0
    for(const auto& chain : chains_of_cut[cut])
      for(std::size_t k = 0; k + 1 < chain.size(); ++k) out.insert_constraint(chain[k], chain[k + 1]);
  }
  out.insert(free_points.begin(), free_points.end());
  for(auto f = out.all_faces_begin(); f != out.all_faces_end(); ++f) f->set_in_domain(false);
  if(out.dimension() < 2) return;
  // the regions, by a walk across unconstrained edges
  std::vector<Face_handle> region, stack;
  std::unordered_set<Face_handle, Handle_hash_function> seen;
  for(auto start = out.all_faces_begin(); start != out.all_faces_end(); ++start) {
    if(!seen.insert(start).second) continue;
    region.clear();
    stack.assign(1, start);
    bool infinite = false;
    while(!stack.empty()) {
      const Face_handle f = stack.back();
      stack.pop_back();
      region.push_back(f);
      infinite = infinite || out.is_infinite(f);
      for(int k = 0; k < 3; ++k) {
        const Face_handle g = f->neighbor(k);
        if(f->is_constrained(k) || !seen.insert(g).second) continue;
        stack.push_back(g);
      }
    }
    if(infinite) continue;
    Face_handle largest;
    double largest_area = -1;
    for(Face_handle f : region) {
      const double area = std::abs(CGAL::to_double(out.triangle(f).area()));
      if(area > largest_area) {
        largest_area = area;
        largest = f;
      }
    }
    const Point& p0 = largest->vertex(0)->point();
    const Point& p1 = largest->vertex(1)->point();
    const Point& p2 = largest->vertex(2)->point();
    const double gx = (CGAL::to_double(p0.x()) + CGAL::to_double(p1.x()) + CGAL::to_double(p2.x())) / 3;
    const double gy = (CGAL::to_double(p0.y()) + CGAL::to_double(p1.y()) + CGAL::to_double(p2.y())) / 3;
    if(internal::part_of(internal::coordinate(gx, gy, plan.axis), plan.cuts) != part) continue;
    typename CDT::Locate_type lt;
    int li;
    const Face_handle g = cdt.locate(Point(gx, gy), lt, li);
    // on an edge or a vertex of cdt (symmetric inputs): in the domain when
    // a face there is (the region lies on one side of every constraint)
    bool inside = lt == CDT::FACE && !cdt.is_infinite(g) && g->is_in_domain();
    if(lt == CDT::EDGE) {
      inside = (!cdt.is_infinite(g) && g->is_in_domain()) ||
               (!cdt.is_infinite(g->neighbor(li)) && g->neighbor(li)->is_in_domain());
    } else if(lt == CDT::VERTEX) {
      auto fc = cdt.incident_faces(g->vertex(li)), done = fc;
      do {
        inside = inside || (!cdt.is_infinite(fc) && fc->is_in_domain());
      } while(++fc != done);
    }
    if(!inside) continue;
    for(Face_handle f : region) f->set_in_domain(true);
  }
}

// Makes the planned cuts in `cdt`: the constraints split where they cross
// (`on_split` sees every split; the counts go to `st`) and the interfaces
// discretised to `field`; returns the interface chains of each cut. Throws
// std::runtime_error when a cut cannot be made.
template <class CDT, class Field, class Point, class OnSplit>
std::vector<std::vector<std::vector<Point> > > make_cuts(CDT& cdt, const Field& field, const Strip_plan& plan,
                                                         const std::vector<Point>& seeds, bool mark,
                                                         OnSplit& on_split, Parallel_mesh_statistics& st)
{
  typedef CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> > Mesh_2_mesher;
  std::vector<std::vector<typename CDT::Vertex_handle> > crossings;
  for(const Strip_cut& cut : plan.cuts) {
    crossings.push_back(cut_constraints(cdt, plan.axis, cut.position, on_split));
    st.cut_points += crossings.back().size();
    // the faces the splits made are unmarked: the next cut finds the
    // constraints of the domain by the marks
    Mesh_2_mesher::mark_facets(cdt, seeds.begin(), seeds.end(), mark);
  }
  std::vector<std::vector<std::vector<Point> > > chains_of_cut;
  for(std::size_t k = 0; k < plan.cuts.size(); ++k) {
    chains_of_cut.push_back(interface_chains(cdt, field, plan.axis, crossings[k]));
    for(const auto& chain : chains_of_cut.back()) st.interface_points += chain.size() - 2;
  }
  return chains_of_cut;
}

// Each part's constraints and free points (the domain's vertices on no
// constraint), by the side of the cuts.
template <class CDT>
void part_inputs(const CDT& cdt, const Strip_plan& plan,
                 std::vector<std::vector<std::pair<typename CDT::Point, typename CDT::Point> > >& constraints,
                 std::vector<std::vector<typename CDT::Point> >& free_points)
{
  typedef typename CDT::Point Point;
  const std::size_t parts = plan.cuts.size() + 1;
  constraints.assign(parts, {});
  free_points.assign(parts, {});
  for(const auto& e : domain_constraints(cdt)) {
    const Point &a = e.first->point(), &b = e.second->point();
    const double mx = 0.5 * (CGAL::to_double(a.x()) + CGAL::to_double(b.x()));
    const double my = 0.5 * (CGAL::to_double(a.y()) + CGAL::to_double(b.y()));
    constraints[part_of(coordinate(mx, my, plan.axis), plan.cuts)].emplace_back(a, b);
  }
  for(auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    bool in_domain = false;
    auto f = cdt.incident_faces(v), done = f;
    do {
      in_domain = in_domain || (!cdt.is_infinite(f) && f->is_in_domain());
    } while(++f != done);
    if(!in_domain || cdt.are_there_incident_constraints(v)) continue;
    const double x = CGAL::to_double(v->point().x()), y = CGAL::to_double(v->point().y());
    free_points[part_of(coordinate(x, y, plan.axis), plan.cuts)].push_back(v->point());
  }
}

// Calls `work(i)` for every i < n, on n threads at once.
template <class Work>
void run_on_threads(std::size_t n, Work work)
{
#if defined(__SANITIZE_THREAD__)
  // Under ThreadSanitizer, one std::thread per part: TSan does not see
  // oneTBB's synchronisation (Debian's libtbb is not instrumented) and
  // reports its task hand-overs as races; with threads it checks the
  // parts' own accesses, which are the same code.
  std::vector<std::thread> workers;
  for(std::size_t i = 0; i < n; ++i) workers.emplace_back(work, i);
  for(std::thread& w : workers) w.join();
#elif defined(CGAL_LINKED_WITH_TBB)
  // more threads than cores when asked (TBB limits its workers to the
  // cores otherwise)
  tbb::global_control allowed(tbb::global_control::max_allowed_parallelism, n);
  tbb::task_arena arena{int(n)};
  arena.execute([&] { tbb::parallel_for(std::size_t(0), n, work); });
#else
  for(std::size_t i = 0; i < n; ++i) work(i);
#endif
}

// The seams: where the rows of triangles grown from an interface meet
// those grown from the boundary, triangles are worse than where one front
// sweeps through. Of the vertices the parts made, those within `width`
// local sizes of a cut (the interface points among them, no longer on any
// constraint). The local size is only asked near the cuts: within
// `width` times twice the largest size on the interfaces.
template <class Vertex_handle, class Point, class Field>
std::vector<Vertex_handle> seam_vertices(const std::vector<Vertex_handle>& made, const Strip_plan& plan,
                                         const std::vector<std::vector<std::vector<Point> > >& chains_of_cut,
                                         const Field& field, double width)
{
  double interface_size = 0;
  for(const auto& chains : chains_of_cut)
    for(const auto& chain : chains)
      for(const Point& p : chain) interface_size = (std::max)(interface_size, CGAL::to_double(field(p)));
  std::vector<Vertex_handle> seam;
  for(Vertex_handle v : made) {
    const double x = CGAL::to_double(v->point().x()), y = CGAL::to_double(v->point().y());
    const double a = coordinate(x, y, plan.axis);
    const std::size_t part = part_of(a, plan.cuts);
    for(std::size_t k : {part - 1, part}) {
      if(k >= plan.cuts.size()) continue;
      const double d = std::abs(a - plan.cuts[k].position);
      if(d <= 2 * width * interface_size && d <= width * CGAL::to_double(field(v->point()))) {
        seam.push_back(v);
        break;
      }
    }
  }
  return seam;
}

// The domain of `cdt` meshed by the serial mesher, and `st` saying why
// (what a failed decomposition recorded is not this run's, except the cut
// points made, which stay in the boundary).
template <class Mesher, class CDT, class Field, class Point>
Mesh_return_code mesh_in_one_piece(CDT& cdt, const Field& field, const std::vector<Point>& seeds, bool mark,
                                   bool pocket_priority, const std::string& why,
                                   std::chrono::steady_clock::time_point t_start, Parallel_mesh_statistics& st)
{
  const double cutting = parallel_seconds_since(t_start);
  const std::size_t cut_points = st.cut_points, threads = st.threads;
  st = Parallel_mesh_statistics();
  st.threads = threads;
  st.one_piece_reason = why;
  st.cut_points = cut_points;
  st.decomposition_time = cutting;
  const auto t_mesh = std::chrono::steady_clock::now();
  Mesher mesher(cdt, field);
  mesher.set_seeds(seeds.begin(), seeds.end(), mark);
  mesher.set_constraint_splitting(false);
  mesher.set_pocket_priority(pocket_priority);
  const Mesh_return_code rc = mesher.refine_mesh();
  st.meshing_time = parallel_seconds_since(t_mesh);
  st.part_statistics.assign(1, mesher.statistics());
  st.part_triangles.assign(1, mesher.statistics().number_of_faces);
  return rc;
}

// The parts built and meshed concurrently, each with its own copy of the
// field; returns what went wrong in each (empty when nothing did). The
// statistics and the in-domain triangle count of each part are set.
template <class Mesher, class CDT, class Field>
std::vector<std::string>
mesh_parts(const CDT& cdt, const Strip_plan& plan,
           const std::vector<std::vector<std::pair<typename CDT::Point, typename CDT::Point> > >& constraints,
           const std::vector<std::vector<std::vector<typename CDT::Point> > >& chains_of_cut,
           const std::vector<std::vector<typename CDT::Point> >& free_points, const Field& field,
           bool pocket_priority, std::vector<CDT>& part_cdt, std::vector<Mesh_return_code>& codes,
           const Time_stamp_bases& bases, std::vector<Statistics>& statistics,
           std::vector<std::size_t>& triangles)
{
  const std::size_t parts = part_cdt.size();
  statistics.assign(parts, Statistics());
  triangles.assign(parts, 0);
  std::vector<std::string> failures(parts);
  auto mesh_part = [&](std::size_t i) {
    try {
      start_time_stamps(part_cdt[i], bases, i);
      build_part(cdt, plan, i, constraints[i], chains_of_cut, free_points[i], part_cdt[i]);
      const Field part_field = field;
      Mesher mesher(part_cdt[i], part_field);
      mesher.use_domain_marks();
      mesher.set_pocket_priority(pocket_priority);
      codes[i] = mesher.refine_mesh();
      statistics[i] = mesher.statistics();
      for(auto f = part_cdt[i].finite_faces_begin(); f != part_cdt[i].finite_faces_end(); ++f)
        if(f->is_in_domain()) ++triangles[i];
    } catch(const std::exception& e) {
      failures[i] = e.what();
    }
  };
  run_on_threads(parts, mesh_part);
  return failures;
}

} // namespace internal

/*!
\ingroup PkgAdvancingFrontMesh2Ref

Meshes the domain of `cdt` like `advancing_front_mesh_2()`, on `threads`
threads: the domain is cut into as many strips across its longer axis,
each holding about the same number of triangles as the sizing field
predicts; the constraints are split where they cross a cut, the pieces of
the cuts inside the domain (the interfaces) are discretised to the size
field, every part is meshed in a triangulation of its own with the frontal
mesher, concurrently (Intel oneTBB, when `CGAL_LINKED_WITH_TBB` is defined;
else one part after another), and the parts' triangles are stitched into
`cdt`: the interfaces are released (not constraints) and Lawson's flips make
the mesh constrained Delaunay across them; the mesher's vertices within
three local sizes of a cut are then smoothed (the seams).

The result depends on `threads` (the cuts do), and for a given `threads`
not on the machine or the order the parts finish in. `threads == 1`, a
domain too small for two parts of 2,000 triangles, a domain whose cuts
cannot be made (a constraint that cannot be split where it crosses a cut),
or parts that do not fit together (checked before `cdt` changes) are meshed
in one piece by the serial mesher; the statistics say why. A cut is placed
at the balanced position or, within 3% of the extent and 4% of a part's
predicted count, at the nearest place half a local size clear of every
vertex not on it and crossing the constraints at 45 degrees or more (else
at the best place found). `pocket_priority` is passed to every mesher
(`Advancing_front_mesher_2::set_pocket_priority()`).

Constraints are split to the sizing field first, as `advancing_front_mesh_2()`
does (`split_constraints == false` keeps them, except where a cut
crosses one); `on_split(a, b, v)` is called for every split of a
constrained edge (a, b) at a new vertex v, by the boundary discretisation
and by the cuts.

\tparam CDT as for `Advancing_front_mesher_2`; default constructible
\tparam Size as for `advancing_front_mesh_2()`; the sizing field is copied
  for each part, and its copies are called from different threads at once:
  a field whose copies share mutable state must guard it
\returns the mesher's return code (`MESH_COMPLETE` when every part is)
\throws std::invalid_argument as `advancing_front_mesh_2()`, and when
  `threads == 0`
*/
template <class CDT, class InputIterator, class Size, class OnSplit>
Mesh_return_code mesh_in_parallel_2(CDT& cdt, InputIterator seeds_begin, InputIterator seeds_end, const Size& size,
                                    bool mark, std::size_t threads, Parallel_mesh_statistics& st,
                                    bool split_constraints, OnSplit on_split, bool pocket_priority = true)
{
  typedef typename CDT::Geom_traits Gt;
  typedef typename CDT::Point Point;
  typedef typename CDT::Vertex_handle Vertex_handle;
  typedef internal::Sizing_field_maker<Gt, Size> Maker;
  typedef typename Maker::type Field;
  typedef Advancing_front_mesher_2<CDT, Field> Mesher;
  typedef CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> > Mesh_2_mesher;
  if(threads == 0) throw std::invalid_argument("mesh_in_parallel_2: threads must be at least 1");
  const double seam_width = 3;
  const std::size_t seam_passes = 3;
  st = Parallel_mesh_statistics();
  st.threads = threads;
  const Field field = Maker::make(size);
  const std::vector<Point> seeds(seeds_begin, seeds_end);
  const auto t_start = std::chrono::steady_clock::now();

  auto in_one_piece = [&](const std::string& why) {
    return internal::mesh_in_one_piece<Mesher>(cdt, field, seeds, mark, pocket_priority, why, t_start, st);
  };

  // the domain, and its boundary to the size field (as the serial mesher
  // does it, but with the callback)
  if(cdt.dimension() < 2) return in_one_piece("the triangulation has no faces");
  Mesh_2_mesher::mark_facets(cdt, seeds.begin(), seeds.end(), mark);
  if(split_constraints) {
    split_constraints_to_size_2(cdt, field, Constraint_touches_domain<CDT>{&cdt}, on_split);
    Mesh_2_mesher::mark_facets(cdt, seeds.begin(), seeds.end(), mark);
  }
  if(threads < 2) return in_one_piece("one thread");
  internal::Strip_plan plan = internal::plan_strips(cdt, field, threads);
  if(plan.cuts.empty()) return in_one_piece("the domain is too small for two parts");

  // the cuts: constraints split where they cross, interfaces discretised
  std::vector<std::vector<std::vector<Point> > > chains_of_cut;
  try {
    chains_of_cut = internal::make_cuts(cdt, field, plan, seeds, mark, on_split, st);
  } catch(const std::runtime_error& e) {
    Mesh_2_mesher::mark_facets(cdt, seeds.begin(), seeds.end(), mark);
    return in_one_piece(std::string("a cut could not be made: ") + e.what());
  }
  const std::size_t parts = plan.cuts.size() + 1;
  std::vector<std::vector<std::pair<Point, Point> > > constraints;
  std::vector<std::vector<Point> > free_points;
  internal::part_inputs(cdt, plan, constraints, free_points);
  st.parts = parts;
  st.axis = plan.axis;
  for(const auto& c : plan.cuts) st.cuts.push_back(c.position);
  st.predicted_triangles = plan.estimated;
  st.decomposition_time = internal::parallel_seconds_since(t_start);

  // the parts, meshed concurrently, each with its own copy of the field
  const auto t_mesh = std::chrono::steady_clock::now();
  std::vector<CDT> part_cdt(parts);
  std::vector<Mesh_return_code> codes(parts, MESH_COMPLETE);
  const internal::Time_stamp_bases stamps = internal::time_stamp_bases(cdt);
  const std::vector<std::string> failures =
    internal::mesh_parts<Mesher>(cdt, plan, constraints, chains_of_cut, free_points, field, pocket_priority, part_cdt,
                                 codes, stamps, st.part_statistics, st.part_triangles);
  st.meshing_time = internal::parallel_seconds_since(t_mesh);
  for(const std::string& f : failures)
    if(!f.empty()) {
      // the parts cannot be trusted; the triangulation still holds the
      // input and the cuts
      part_cdt.clear();
      return in_one_piece("a part could not be meshed: " + f);
    }

  // the merge: the parts' triangles stitched into cdt (or, where the parts
  // do not fit, the domain meshed in one piece)
  const auto t_merge = std::chrono::steady_clock::now();
  std::vector<Vertex_handle> new_vertices;
  st.stitched = internal::stitch_parts(cdt, part_cdt, stamps, new_vertices);
  part_cdt.clear();
  // a part's boundary that does not fit the domain's (a region a part did
  // not mark, a free point outside its part): the parts cannot be trusted
  // to cover the domain, and the triangulation is as it was
  if(!st.stitched) return in_one_piece("the parts do not fit together");
  st.merge_time = internal::parallel_seconds_since(t_merge);
  // the seams: the mesher's vertices near the cuts smoothed, with the flips
  // that keep the mesh constrained Delaunay; the input's vertices (free
  // points among them) never move
  const auto t_seams = std::chrono::steady_clock::now();
  const std::vector<Vertex_handle> seam = internal::seam_vertices(new_vertices, plan, chains_of_cut, field, seam_width);
  st.seam_vertices = seam.size();
  st.seam_smoothing = internal::smooth_vertices_with<internal::Quality_moves>(cdt, seam, seam_passes);
  st.seam_time = internal::parallel_seconds_since(t_seams);
  Mesh_return_code rc = MESH_COMPLETE;
  for(Mesh_return_code c : codes)
    if(c != MESH_COMPLETE) rc = c;
  return rc;
}

} // namespace Advancing_front_mesh_2
} // namespace CGAL

#endif // CGAL_ADVANCING_FRONT_MESH_2_MESH_IN_PARALLEL_2_H
