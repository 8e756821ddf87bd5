// An experiment, not part of the package: what would one step of the
// mesher cost if the unmeshed region stayed triangulated? Issue 22 asks the
// serial mesher to be as fast as Triangle, and our step loop spends most of
// its instructions finding, among the front points near an edge, the apex
// that is visible from the edge (Merriam's iteration with the free-sector
// and crossing tests, Delaunay_apex.h, Front_visibility.h): the unmeshed
// region has no triangles to tell what is visible. Rebay's frontal-Delaunay
// method (J. Comput. Phys. 106, 1993) keeps the Delaunay triangulation of
// the boundary points as the unmeshed region's triangulation, places the
// new point ahead of a front edge as Mavriplis does, and inserts it by
// Bowyer-Watson: the conflict zone replaces the apex search, the broken
// circles' search and the visibility tests at once.
//
// This program meshes one input both ways, from the same constrained
// Delaunay triangulation of it, at a uniform size or under a graded field,
// and prints the meshing time (fastest of the runs), the triangle count,
// the quality and the independent checker's verdict of each. The
// experiment's loop is deliberately plain: CGAL's CDT as it is, a size
// function, no answer yet for the faces whose new point it must refuse. It
// takes the active triangles in one of two orders:
// - largest circumradius first (a binary heap), as Rebay and Gmsh's
//   Frontal-Delaunay take them: consecutive steps then jump along the whole
//   front, and from 1e5 to 1e6 triangles the time per triangle grew by 53
//   to 87% over four runs of the script (cache misses);
// - by classes of circumradius over the accepted one a quarter octave wide,
//   the largest class first, and within a class the newest first: the next
//   step mostly works next to the last point, and the time per triangle
//   grew by 31 to 40% (doc/Advancing_front_mesh_2/benchmark/step_loop_results.md).
//
//   frontal_delaunay_experiment INPUT.poly H [RUNS]      (uniform size H)
//   frontal_delaunay_experiment --radial-airfoil [RUNS]  (a graded field)
//   frontal_delaunay_experiment --random [DOMAINS]       (the tests' random domains)
#include "bench_common.h" // first: it defines the allocation functions (heap_meter.h)

#include "afm_geometries.h"
#include "afm_random_pslg.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>
#include <CGAL/Advancing_front_mesh_2/refine_to_minimum_angle_2.h>
#include <CGAL/Advancing_front_mesh_2/split_constraints_to_size_2.h>
#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_criteria_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <iterator>
#include <list>
#include <queue>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef afm_test::Poly_data Poly_data;

// ------------------------------------------------ the frontal-Delaunay loop

// A face's state: accepted (small enough, final) or not, and a stamp that
// names this incarnation of the face (the queue's entries of a face the
// insertions destroyed or reused carry an older stamp).
//
// A face is queued again whenever a step beside it considers it: in the
// class order that makes it the newest, which keeps the next steps beside
// the last one (queued once instead, the square at 1e5 came out slower, 98.08%
// above 0.9 instead of 98.61%, for 100 heap bytes a triangle instead of 132:
// the stale entries stay in the queue until popped).
struct Face_state
{
  unsigned stamp = 0;
  bool accepted = false;
};

typedef CGAL::Triangulation_vertex_base_2<K> Vb;
typedef CGAL::Constrained_triangulation_face_base_2<K> Cfb;
typedef CGAL::Triangulation_face_base_with_info_2<Face_state, K, Cfb> Ifb;
typedef CGAL::Delaunay_mesh_face_base_2<K, Ifb> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<
  K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag> Frontal_cdt;
typedef Frontal_cdt::Face_handle Frontal_face;

struct Frontal_statistics
{
  std::size_t inserted = 0;
  std::size_t given_up = 0; // faces kept because their point fell outside the domain, on the
                            // cavity's boundary or within a quarter of the size of a constraint
};

double circumradius(Frontal_face f)
{
  return std::sqrt(CGAL::squared_radius(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
}

// The active faces, in one of the two orders above. An entry is a face
// with its circumradius over the accepted one and its stamp when pushed.
struct Active_entry
{
  double size_ratio;
  Frontal_face face;
  unsigned stamp;
  bool operator<(const Active_entry& o) const { return size_ratio < o.size_ratio; }
};

class Active_faces
{
public:
  explicit Active_faces(bool local_order) : local_(local_order) {}
  bool empty() const { return size_ == 0; }
  void push(const Active_entry& e)
  {
    ++size_;
    if(!local_) {
      heap_.push(e);
      return;
    }
    const std::size_t c = class_of(e.size_ratio);
    if(c >= classes_.size()) classes_.resize(c + 1);
    classes_[c].push_back(e);
    top_ = (std::max)(top_, c);
  }
  Active_entry pop()
  {
    --size_;
    if(!local_) {
      const Active_entry e = heap_.top();
      heap_.pop();
      return e;
    }
    while(classes_[top_].empty()) --top_;
    const Active_entry e = classes_[top_].back();
    classes_[top_].pop_back();
    return e;
  }

private:
  // quarter octaves of the ratio (all ratios up to 1 share class 0; the
  // largest classes are capped)
  std::size_t class_of(double size_ratio) const
  {
    const double octaves = std::log2((std::max)(size_ratio, 1.));
    return std::size_t((std::min)(4 * octaves, 1000.));
  }

  bool local_;
  std::size_t size_ = 0, top_ = 0;
  std::priority_queue<Active_entry> heap_;
  std::vector<std::vector<Active_entry> > classes_;
};

// the target edge length at a point
typedef std::function<double(double, double)> Size_function;

Frontal_statistics frontal_delaunay(Frontal_cdt& cdt, const std::list<Point>& seeds, const Size_function& size,
                                    bool local_order)
{
  CGAL::Delaunay_mesher_2<Frontal_cdt, CGAL::Delaunay_mesh_criteria_2<Frontal_cdt> >::mark_facets(
    cdt, seeds.begin(), seeds.end(), false);
  // a face is final once its circumradius is at most h / sqrt(2), 1.22 times
  // the equilateral triangle's (Gmsh's bound), h the size at its centroid;
  // the new point aims at the equilateral triangle's circumradius h / sqrt(3)
  // for the size at the front edge's midpoint
  auto size_ratio = [&](Frontal_face f) {
    const Point& a = f->vertex(0)->point();
    const Point& b = f->vertex(1)->point();
    const Point& c = f->vertex(2)->point();
    return circumradius(f) * std::sqrt(2.) / size((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
  };
  Active_faces active(local_order);
  unsigned stamp = 0;
  // across edge i of f lies the meshed region or the domain's boundary
  auto on_front = [&](Frontal_face f, int i) {
    const Frontal_face g = f->neighbor(i);
    return f->is_constrained(i) || cdt.is_infinite(g) || !g->is_in_domain() || g->info().accepted;
  };
  auto consider = [&](Frontal_face f) {
    if(cdt.is_infinite(f) || !f->is_in_domain() || f->info().accepted) return;
    for(int i = 0; i < 3; ++i)
      if(on_front(f, i)) {
        active.push(Active_entry{size_ratio(f), f, f->info().stamp});
        return;
      }
  };
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    f->info().stamp = ++stamp;
    f->info().accepted = f->is_in_domain() && size_ratio(f) <= 1;
  }
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) consider(f);

  Frontal_statistics st;
  std::vector<Frontal_face> conflicts;
  std::vector<Frontal_cdt::Edge> hole;
  while(!active.empty()) {
    const Active_entry entry = active.pop();
    const Frontal_face f = entry.face;
    if(f->info().stamp != entry.stamp || f->info().accepted) continue; // destroyed, reused or done since
    // its shortest front edge a -> b (the face on its left)
    int edge = -1;
    double l2 = 0;
    for(int i = 0; i < 3; ++i) {
      if(!on_front(f, i)) continue;
      const double li = CGAL::squared_distance(f->vertex(Frontal_cdt::cw(i))->point(),
                                               f->vertex(Frontal_cdt::ccw(i))->point());
      if(edge < 0 || li < l2) {
        edge = i;
        l2 = li;
      }
    }
    // (an accepted neighbour may have gone in a later cavity that spared f:
    // f is queued again when a neighbour is accepted)
    if(edge < 0) continue;
    const Point& a = f->vertex(Frontal_cdt::ccw(edge))->point();
    const Point& b = f->vertex(Frontal_cdt::cw(edge))->point();
    const double mx = 0.5 * (a.x() + b.x()), my = 0.5 * (a.y() + b.y()), half = 0.5 * std::sqrt(l2);
    double nx = a.y() - b.y(), ny = b.x() - a.x();
    const double nl = std::sqrt(nx * nx + ny * ny);
    nx /= nl;
    ny /= nl;
    // Rebay's point: on the edge's bisector, making a triangle of the target
    // circumradius, but not beyond the face's own circumcircle (whose
    // centre lies at height q over the edge); where the face is obtuse at
    // its apex the point may fall on or outside that circle, and the
    // insertion then leaves f for a later step
    const Point c = CGAL::circumcenter(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    const double q = (c.x() - mx) * nx + (c.y() - my) * ny;
    const double rho = size(mx, my) / std::sqrt(3.);
    const double r = (std::min)((std::max)(rho, half), (half * half + q * q) / (2 * (std::max)(q, 1e-300)));
    const double d = r + std::sqrt((std::max)(0., r * r - half * half));
    const Point p(mx + d * nx, my + d * ny);
    conflicts.clear();
    hole.clear();
    cdt.get_conflicts_and_boundary(p, std::back_inserter(conflicts), std::back_inserter(hole), f);
    // the new point must lie strictly inside the cavity's boundary, or the
    // star would hold a flat triangle (a point on a constraint); the
    // boundary's edges are given by the faces outside it
    bool inside = !conflicts.empty() && !cdt.is_infinite(conflicts.front()) && conflicts.front()->is_in_domain();
    // and keep a quarter of the size from the constraints there: a point a
    // rounding error inside a boundary segment makes a valid but flat
    // triangle, which the checker rightly reads as a point on the segment
    const double clearance2 = 0.0625 * 3 * rho * rho; // (h / 4)^2
    for(std::size_t i = 0; inside && i < hole.size(); ++i) {
      const Frontal_face g = hole[i].first;
      const int j = hole[i].second;
      const Point& u = g->vertex(Frontal_cdt::ccw(j))->point();
      const Point& w = g->vertex(Frontal_cdt::cw(j))->point();
      inside = CGAL::orientation(u, w, p) == CGAL::RIGHT_TURN &&
               !(g->is_constrained(j) && CGAL::squared_distance(K::Segment_2(u, w), p) < clearance2);
    }
    if(!inside) {
      // the point falls outside the domain, on a vertex or on the cavity's
      // boundary: the face stays
      f->info().accepted = true;
      ++st.given_up;
      for(int i = 0; i < 3; ++i) consider(f->neighbor(i));
      continue;
    }
    for(Frontal_face g : conflicts) g->info().stamp = 0;
    const Frontal_cdt::Vertex_handle v = cdt.star_hole(p, hole.begin(), hole.end(), conflicts.begin(), conflicts.end());
    ++st.inserted;
    auto fc = cdt.incident_faces(v), done = fc;
    do {
      fc->set_in_domain(true);
      fc->info().stamp = ++stamp;
      fc->info().accepted = size_ratio(fc) <= 1;
    } while(++fc != done);
    do {
      const Frontal_face g = fc;
      consider(g);
      consider(g->neighbor(g->index(v)));
    } while(++fc != done);
  }
  return st;
}

// ------------------------------------------------------------ measurement

// The meshing's fastest time, and the heap it added at its peak (first run).
struct Timing
{
  double seconds = 0;
  int runs = 0;
  std::size_t peak_bytes = 0;
};

template <class CDT>
void report(const std::string& name, const CDT& cdt, const Poly_data& in, const Timing& t, const std::string& extra)
{
  const afm_check::Mesh m = afm_test::extract_mesh(cdt);
  const afm_bench::Quality q = afm_bench::quality(m);
  const afm_check::Report r = afm_test::check_split_mesh(in, m);
  std::cout << "| " << name << " | " << m.triangles.size() << " | " << t.seconds << " (fastest of " << t.runs
            << ") | " << double(t.peak_bytes) / double(m.triangles.size()) << " | " << q.mean << " | "
            << 100 * q.share_above_0_9 << "% | " << q.min << " | "
            << (r.ok ? std::string("valid") : "INVALID: " + r.summary()) << " | " << extra << " |\n";
}

// Meshes `in` `runs` times with `mesh(cdt, seeds)`, timed from the input's
// triangulation to the finished mesh; keeps the first run's mesh in `kept`.
template <class CDT, class Mesh>
Timing fastest_of(int runs, const Poly_data& in, CDT& kept, Mesh mesh)
{
  Timing t;
  t.runs = runs;
  for(int run = 0; run < runs; ++run) {
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    const std::list<Point> seeds = afm_test::seeds_of<CDT>(in);
    afm_bench::Meter meter;
    meter.start();
    mesh(cdt, seeds);
    meter.stop();
    if(run == 0 || meter.seconds() < t.seconds) t.seconds = meter.seconds();
    if(run == 0) {
      t.peak_bytes = meter.peak_bytes();
      kept = cdt;
    }
  }
  return t;
}

// Ours, then the experiment in both orders, on `in` under `size`; with
// `split`, both discretise the boundary to the size first (ours in its
// refiner, the experiment by the same split_constraints_to_size_2()).
void compare(const Poly_data& in, const Size_function& size, bool split, int runs, bool refined_rows)
{
  std::cout << "| step loop | triangles | meshing seconds | peak heap bytes / triangle | mean radius ratio | "
               "share > 0.9 | min radius ratio | checker | notes |\n|---|--:|--:|--:|--:|--:|--:|---|---|\n";
  typedef afm_test::Types<K>::CDT CDT;
  auto sizing = [&size](const Point& p) { return K::FT(size(p.x(), p.y())); };
  // with `refine`, Mesh_2's refinement of the triangles below 20 degrees
  // (refine_to_minimum_angle_2(), afmesh_2 --min-angle 20) follows the loop,
  // timed with it
  const std::string then_refined = ", then Mesh_2's refinement below 20 degrees";
  for(const bool refine : {false, true}) {
    if(refine && !refined_rows) break;
    CDT ours;
    std::size_t refinement_points = 0;
    bool first_run = true;
    const Timing ours_timing = fastest_of(runs, in, ours, [&](CDT& cdt, const std::list<Point>& seeds) {
      CGAL::Advancing_front_mesher_2<CDT, decltype(sizing)> mesher(cdt, sizing);
      mesher.set_constraint_splitting(split);
      mesher.set_seeds(seeds.begin(), seeds.end());
      mesher.refine_mesh();
      // (the first run's count, as its mesh is the one reported)
      const std::size_t points =
        refine ? CGAL::Advancing_front_mesh_2::refine_to_minimum_angle_2(cdt, 20).points_inserted : 0;
      if(first_run) refinement_points = points;
      first_run = false;
    });
    report(std::string("ours (Mavriplis, apex search and visibility)") + (refine ? then_refined : ""), ours, in,
           ours_timing,
           std::to_string(ours.number_of_vertices() - in.points.size() - refinement_points) + " points" +
             (refine ? ", " + std::to_string(refinement_points) + " points by the refinement" : ""));
    for(const bool local_order : {false, true}) {
      Frontal_cdt kept;
      Frontal_statistics st;
      bool first = true;
      const Timing timing = fastest_of(runs, in, kept, [&](Frontal_cdt& cdt, const std::list<Point>& seeds) {
        if(split) CGAL::Advancing_front_mesh_2::split_constraints_to_size_2(cdt, sizing);
        const Frontal_statistics this_run = frontal_delaunay(cdt, seeds, size, local_order);
        const std::size_t points =
          refine ? CGAL::Advancing_front_mesh_2::refine_to_minimum_angle_2(cdt, 20).points_inserted : 0;
        if(first) {
          st = this_run;
          refinement_points = points;
        }
        first = false;
      });
      report(std::string(local_order ? "experiment (Rebay), radius classes, newest first"
                                     : "experiment (Rebay), largest circumradius first") +
               (refine ? then_refined : ""),
             kept, in, timing,
             std::to_string(st.inserted) + " points, " + std::to_string(st.given_up) + " faces given up" +
               (refine ? ", " + std::to_string(refinement_points) + " points by the refinement" : ""));
    }
  }
}

// The worst triangles of the experiment: those below a radius ratio of
// 0.05, and of them the needles on a constrained edge shorter than a tenth
// of the size (a short input segment, or two input points close together,
// under a uniform size: the loop accepts a triangle by its circumradius
// alone, and the needle's is about half the size).
struct Worst_triangles
{
  std::size_t below_0_05 = 0, on_short_constraint = 0;
};

Worst_triangles worst_triangles(const Frontal_cdt& cdt, double h)
{
  Worst_triangles w;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    std::array<std::array<double, 2>, 3> p;
    for(int i = 0; i < 3; ++i) p[i] = {{f->vertex(i)->point().x(), f->vertex(i)->point().y()}};
    if(afm_bench::radius_ratio(p[0], p[1], p[2]) >= 0.05) continue;
    ++w.below_0_05;
    for(int i = 0; i < 3; ++i) {
      const std::array<double, 2>& a = p[Frontal_cdt::ccw(i)];
      const std::array<double, 2>& b = p[Frontal_cdt::cw(i)];
      if(f->is_constrained(i) && std::hypot(b[0] - a[0], b[1] - a[1]) < 0.1 * h) {
        ++w.on_short_constraint;
        break;
      }
    }
  }
  return w;
}

// The test suite's random domains (holes, free points, interior segments,
// sharp angles, any scale) at a uniform size, their boundaries discretised
// to it: ours and the experiment (circle classes), each also followed by
// Mesh_2's Delaunay refinement of its triangles below 20 degrees
// (refine_to_minimum_angle_2(), afmesh_2 --min-angle 20), summed up.
void random_domains(int n)
{
  typedef afm_test::Types<K>::CDT CDT;
  struct Summary
  {
    int valid = 0, below_0_05 = 0;
    double share_sum = 0;
    std::vector<double> minima;
  } ours, ours_refined, experiment, refined;
  int experiment_better = 0;
  std::size_t given_up = 0, triangles = 0, refinement_points = 0;
  Worst_triangles worst;
  auto add = [](Summary& s, const afm_check::Mesh& m, const afm_check::Report& r) {
    const afm_bench::Quality q = afm_bench::quality(m);
    s.valid += r.ok;
    s.share_sum += q.share_above_0_9;
    s.minima.push_back(q.min);
    s.below_0_05 += q.min < 0.05;
    return q.share_above_0_9;
  };
  for(int seed = 0; seed < n; ++seed) {
    afm_random::Generator g{std::uint64_t(seed)};
    const afm_random::Domain d = g.domain();
    const double h = g.uniform(0.01, 0.03) * d.scale;
    auto sizing = [h](const Point&) { return K::FT(h); };
    CDT cdt;
    afm_test::build_cdt(cdt, d.pslg);
    const std::list<Point> seeds = afm_test::seeds_of<CDT>(d.pslg);
    CGAL::Advancing_front_mesher_2<CDT, decltype(sizing)> mesher(cdt, sizing);
    mesher.set_seeds(seeds.begin(), seeds.end());
    mesher.refine_mesh();
    const afm_check::Mesh m = afm_test::extract_mesh(cdt);
    const double ours_share = add(ours, m, afm_test::check_split_mesh(d.pslg, m));
    CGAL::Advancing_front_mesh_2::refine_to_minimum_angle_2(cdt, 20);
    const afm_check::Mesh om = afm_test::extract_mesh(cdt);
    add(ours_refined, om, afm_test::check_split_mesh(d.pslg, om));
    Frontal_cdt fcdt;
    afm_test::build_cdt(fcdt, d.pslg);
    CGAL::Advancing_front_mesh_2::split_constraints_to_size_2(fcdt, sizing);
    given_up += frontal_delaunay(fcdt, afm_test::seeds_of<Frontal_cdt>(d.pslg), [h](double, double) { return h; }, true)
                  .given_up;
    const Worst_triangles w = worst_triangles(fcdt, h);
    worst.below_0_05 += w.below_0_05;
    worst.on_short_constraint += w.on_short_constraint;
    const afm_check::Mesh fm = afm_test::extract_mesh(fcdt);
    triangles += fm.triangles.size();
    experiment_better += add(experiment, fm, afm_test::check_split_mesh(d.pslg, fm)) > ours_share;
    refinement_points += CGAL::Advancing_front_mesh_2::refine_to_minimum_angle_2(fcdt, 20).points_inserted;
    const afm_check::Mesh rm = afm_test::extract_mesh(fcdt);
    add(refined, rm, afm_test::check_split_mesh(d.pslg, rm));
  }
  std::cout << "| " << n << " random domains | valid | mean share > 0.9 | median smallest radius ratio | "
               "domains with one below 0.05 |\n|---|--:|--:|--:|--:|\n";
  for(Summary* s : {&ours, &ours_refined, &experiment, &refined}) {
    std::sort(s->minima.begin(), s->minima.end());
    std::cout << "| "
              << (s == &ours           ? "ours"
                  : s == &ours_refined ? "ours, then Mesh_2's refinement below 20 degrees"
                  : s == &experiment   ? "experiment (Rebay), radius classes, newest first"
                                       : "experiment, then Mesh_2's refinement below 20 degrees")
              << " | " << s->valid << " | " << 100 * s->share_sum / n << "% | " << s->minima[s->minima.size() / 2]
              << " | " << s->below_0_05 << " |\n";
  }
  std::cout << "\nThe experiment's share is the higher on " << experiment_better << " of " << n
            << " domains; it gave up " << given_up << " faces in all. Of its " << triangles << " triangles, "
            << worst.below_0_05 << " lie below a radius ratio of 0.05, " << worst.on_short_constraint
            << " of them on a constrained edge shorter than a tenth of the size; the refinement to 20 degrees "
               "after the experiment inserted "
            << refinement_points << " points.\n";
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string usage = "usage: frontal_delaunay_experiment INPUT.poly H [RUNS]\n"
                            "       frontal_delaunay_experiment --radial-airfoil [RUNS]\n"
                            "       frontal_delaunay_experiment --random [DOMAINS]\n";
  if(argc < 2) {
    std::cerr << usage;
    return 1;
  }
  try {
    if(std::string(argv[1]) == "--random") {
      const int domains = argc > 2 ? std::atoi(argv[2]) : 40;
      if(domains < 1) {
        std::cerr << "DOMAINS must be at least 1\n";
        return 1;
      }
      random_domains(domains);
      return 0;
    }
    if(std::string(argv[1]) == "--radial-airfoil") {
      // graded_quality's steeper-than-gentle radial case: the four elements
      // (15 and 64 points per element side, the boundary at the size) under
      // h = 0.004 + 0.03 d, d the distance from the main element's mid-chord;
      // ours without its boundary discretisation, as there
      const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
      const Poly_data in = afm_geometry::multi_element_airfoil(15, 64);
      compare(in, [](double x, double y) { return 0.004 + 0.03 * std::hypot(x - 0.5, y); }, false, (std::max)(runs, 1),
              true);
      return 0;
    }
    if(argc < 3) {
      std::cerr << usage;
      return 1;
    }
    const Poly_data in = CGAL::Advancing_front_mesh_2::IO::read_poly(argv[1]);
    const double h = std::atof(argv[2]);
    const int runs = argc > 3 ? std::atoi(argv[3]) : 3;
    if(!(h > 0) || runs < 1) {
      std::cerr << "H must be positive and RUNS at least 1\n";
      return 1;
    }
    compare(in, [h](double, double) { return h; }, true, runs, false);
  } catch(const std::exception& e) {
    std::cerr << argv[1] << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}
