// afmesh_2_mpi: the domain cut into parts, the same way on every rank, and
// this rank's part meshed.
//
// Every rank reads the input and makes the size field, the boundary
// discretisation and the cuts itself: they are deterministic and cost a
// small fraction of the meshing, and no rank waits for another before it
// meshes. The cuts are those of mesh_in_parallel_2() (strips across the
// longer axis, balanced by the triangle count the size field predicts),
// one part per rank; a domain too small for as many parts of 2,000
// triangles has fewer parts, and the ranks beyond them have nothing to
// mesh.
#ifndef AFMESH_2_MPI_PARTS_H
#define AFMESH_2_MPI_PARTS_H

#include "../afmesh_2/meshing.h"
#include "channel.h"

#include <CGAL/Advancing_front_mesh_2/Mesh_sink_2.h>
#include <CGAL/Advancing_front_mesh_2/mesh_in_parallel_2.h>

#include <algorithm>
#include <array>
#include <functional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace afmesh_2_mpi {

namespace AFM = CGAL::Advancing_front_mesh_2;

template <class K>
using CDT = typename afmesh_2::Types<K>::CDT;

// The decomposition, the same on every rank.
template <class K>
struct Decomposition
{
  typedef typename K::Point_2 Point;
  AFM::internal::Strip_plan plan;
  std::size_t parts = 1;
  std::string one_part_reason; // why the domain is one part, when it is
  std::vector<std::vector<std::vector<Point> > > chains_of_cut;
  std::vector<std::vector<std::pair<Point, Point> > > constraints;
  std::vector<std::vector<Point> > free_points;
  // the points of each cut's interface chains, and the largest size there
  std::vector<std::set<std::pair<double, double> > > interface_points;
  std::vector<double> interface_size;
  AFM::Parallel_mesh_statistics cut_statistics;
};

inline std::pair<double, double> key_of(double x, double y) { return std::make_pair(x, y); }

template <class Point>
std::pair<double, double> key_of(const Point& p)
{
  return key_of(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
}

// Plans `ranks` parts of the domain of `in` and makes the cuts in in.cdt
// (the markers follow the segments they split, and `on_split_segment(a, b,
// v)` is told that the segment a-b was split at v).
template <class K>
Decomposition<K> decompose(afmesh_2::Input<K>& in, int ranks,
                           const std::function<void(const typename K::Point_2&, const typename K::Point_2&,
                                                    const typename K::Point_2&)>& on_split_segment = {})
{
  typedef CDT<K> Cdt;
  typedef CGAL::Delaunay_mesher_2<Cdt, CGAL::Delaunay_mesh_criteria_2<Cdt> > Mesh_2_mesher;
  Decomposition<K> d;
  const std::vector<typename K::Point_2> seeds(in.seeds.begin(), in.seeds.end());
  // holes are given by seeds (mark = false), as afmesh_2 does
  Mesh_2_mesher::mark_facets(in.cdt, seeds.begin(), seeds.end(), false);
  auto on_split = [&in, &on_split_segment](typename Cdt::Vertex_handle a, typename Cdt::Vertex_handle b,
                                           typename Cdt::Vertex_handle v) {
    in.tags.split_constraint(a, b, v);
    if(on_split_segment) on_split_segment(a->point(), b->point(), v->point());
  };
  if(ranks > 1 && in.cdt.dimension() == 2) d.plan = AFM::internal::plan_strips(in.cdt, in.sizing, std::size_t(ranks));
  if(!d.plan.cuts.empty()) {
    try {
      d.chains_of_cut = AFM::internal::make_cuts(in.cdt, in.sizing, d.plan, seeds, false, on_split, d.cut_statistics);
    } catch(const std::runtime_error& e) {
      d.one_part_reason = std::string("a cut could not be made: ") + e.what();
      d.plan.cuts.clear();
      d.chains_of_cut.clear();
    }
    Mesh_2_mesher::mark_facets(in.cdt, seeds.begin(), seeds.end(), false);
  } else if(ranks > 1) {
    d.one_part_reason = "the domain is too small for two parts";
  }
  d.parts = d.plan.cuts.size() + 1;
  AFM::internal::part_inputs(in.cdt, d.plan, d.constraints, d.free_points);
  for(const auto& chains : d.chains_of_cut) {
    std::set<std::pair<double, double> > points;
    double size = 0;
    for(const auto& chain : chains)
      for(const auto& p : chain) {
        points.insert(key_of(p));
        size = (std::max)(size, CGAL::to_double(in.sizing(p)));
      }
    d.interface_points.push_back(std::move(points));
    d.interface_size.push_back(size);
  }
  return d;
}

// The narrowest part against the width its interface bands need (8
// interface sizes on each side, bands.h, and a triangle's reach beyond):
// their ratio, 1 or more when every part is wide enough.
template <class K>
double narrowest_part_ratio(const Decomposition<K>& d, double band_sizes)
{
  double ratio = 1e300;
  for(std::size_t r = 1; r + 1 < d.parts; ++r) {
    const double width = d.plan.cuts[r].position - d.plan.cuts[r - 1].position;
    const double s = d.interface_size[r - 1], t = d.interface_size[r];
    ratio = (std::min)(ratio, width / (band_sizes * (s + t) + 3 * (std::max)(s, t)));
  }
  return ratio;
}

// A point pair as a key: a directed edge.
typedef std::array<double, 4> Edge_key;
template <class Point>
Edge_key edge_key(const Point& a, const Point& b)
{
  return {{CGAL::to_double(a.x()), CGAL::to_double(a.y()), CGAL::to_double(b.x()), CGAL::to_double(b.y())}};
}

// Whether the parts fit the domain, as mesh_in_parallel_2()'s parts_fit()
// asks of the threads' parts, but on the parts' inputs before meshing (the
// meshing keeps each part's domain) and across the ranks: the open edges
// of each part's domain (directed, the domain on their left) lie on the
// domain's boundary or on an interface, the rank on the other side of an
// interface has the same edges the other way, the parts together have the
// domain's whole boundary, and each part holds its free points. Collective:
// every rank calls it with its part (none: `part_cdt` empty).
template <class K>
bool parts_fit(const afmesh_2::Input<K>& in, const Decomposition<K>& d, std::size_t part, const CDT<K>& part_cdt,
               int rank, int ranks)
{
  typedef CDT<K> Cdt;
  if(d.parts == 1) return true;
  // the domain's boundary, directed, and each cut's interface edges
  std::set<Edge_key> outside;
  for(auto f = in.cdt.finite_faces_begin(); f != in.cdt.finite_faces_end(); ++f) {
    if(!f->is_in_domain()) continue;
    for(int k = 0; k < 3; ++k) {
      const auto g = f->neighbor(k);
      if(in.cdt.is_infinite(g) || !g->is_in_domain())
        outside.insert(edge_key(f->vertex(Cdt::ccw(k))->point(), f->vertex(Cdt::cw(k))->point()));
    }
  }
  std::vector<std::set<Edge_key> > on_cut(d.parts > 0 ? d.parts - 1 : 0);
  bool fits = true;
  std::uint64_t boundary_edges = 0;
  if(part < d.parts && part_cdt.dimension() == 2) {
    for(auto f = part_cdt.finite_faces_begin(); f != part_cdt.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      for(int k = 0; k < 3; ++k) {
        const auto g = f->neighbor(k);
        if(!part_cdt.is_infinite(g) && g->is_in_domain()) continue;
        const auto& a = f->vertex(Cdt::ccw(k))->point();
        const auto& b = f->vertex(Cdt::cw(k))->point();
        if(outside.count(edge_key(a, b)) > 0) {
          ++boundary_edges;
          continue;
        }
        bool found = false;
        for(std::size_t c : {part - 1, part})
          if(c < on_cut.size() && d.interface_points[c].count(key_of(a)) > 0 &&
             d.interface_points[c].count(key_of(b)) > 0) {
            on_cut[c].insert(edge_key(a, b));
            found = true;
            break;
          }
        fits = fits && found; // the part's domain ends inside the domain
      }
    }
    for(const auto& p : d.free_points[part]) {
      typename Cdt::Locate_type lt;
      int li = 0;
      const auto f = part_cdt.locate(p, lt, li);
      bool held = false;
      if(lt == Cdt::VERTEX) {
        auto fc = part_cdt.incident_faces(f->vertex(li)), done = fc;
        do {
          held = held || (!part_cdt.is_infinite(fc) && fc->is_in_domain());
        } while(++fc != done);
      }
      fits = fits && held;
    }
  }
  // the interface above, reversed, must be the rank above's interface below
  if(part < d.parts && part + 1 < d.parts) {
    std::vector<double> mine;
    for(const Edge_key& e : on_cut[part]) mine.insert(mine.end(), {e[2], e[3], e[0], e[1]});
    send_vector(mine, rank + 1, FIT);
  }
  if(part < d.parts && part >= 1 && part - 1 < on_cut.size()) {
    const std::vector<double> below = receive_vector<double>(rank - 1, FIT);
    std::set<Edge_key> theirs;
    for(std::size_t i = 0; i + 3 < below.size(); i += 4) theirs.insert({{below[i], below[i + 1], below[i + 2], below[i + 3]}});
    fits = fits && theirs == on_cut[part - 1];
  }
  (void)ranks;
  const bool whole_boundary = sum_over_ranks(boundary_edges) == outside.size();
  return all_ranks(fits) && whole_boundary;
}

template <class K>
using Sink = AFM::Mesh_sink_2<typename K::Point_2>;

// Part `part` built in `part_cdt`.
template <class K>
void build_part(const afmesh_2::Input<K>& in, const Decomposition<K>& d, std::size_t part, CDT<K>& part_cdt)
{
  AFM::internal::build_part(in.cdt, d.plan, part, d.constraints[part], d.chains_of_cut, d.free_points[part],
                            part_cdt);
}

template <class K>
using Part_mesher = CGAL::Advancing_front_mesher_2<CDT<K>, afmesh_2::Cli_sizing_field<K> >;

// The checkpoints of a part meshed in streaming mode (afmesh_2's restart
// facility, the mesher's own): to `file` after every `every` more
// triangles (0: none), stopping after the first with `stop`; `resume`
// continues from `file` instead of starting. `user_data` is stored in them
// (the run's digest).
struct Part_checkpoints
{
  std::size_t every = 0;
  std::string file, user_data;
  bool stop = false, resume = false;
};

// Meshes with `mesher`, set up for its part or for the whole domain.
template <class K>
AFM::Mesh_return_code mesh_with(const afmesh_2::Options& opt, Part_mesher<K>& mesher, Sink<K>* sink,
                                const Part_checkpoints& ck, AFM::Statistics& st)
{
  if(sink != nullptr) mesher.set_output_sink(sink);
  mesher.set_pocket_priority(!opt.no_pocket_priority);
  // --time-limit and --max-steps: each rank's, for its part (the front
  // left is closed on existing points, as afmesh_2 does)
  mesher.set_time_limit(opt.time_limit);
  mesher.set_iteration_limit(opt.max_steps);
  // the mesher's state, the pocket priority with it, from the checkpoint
  if(ck.resume) mesher.resume(ck.file);
  if(ck.every > 0) mesher.set_checkpoint(ck.every, ck.file, ck.user_data, ck.stop);
  const AFM::Mesh_return_code rc = mesher.refine_mesh();
  st = mesher.statistics();
  return rc;
}

// The part built in `part_cdt` meshed (in streaming mode when `sink` is
// given); returns the mesher's code. A resumed part is meshed in a
// triangulation of its own: its state is the checkpoint's.
template <class K>
AFM::Mesh_return_code mesh_part(const afmesh_2::Options& opt, const afmesh_2::Input<K>& in, CDT<K>& part_cdt,
                                Sink<K>* sink, const Part_checkpoints& ck, AFM::Statistics& st)
{
  CDT<K> resumed;
  Part_mesher<K> mesher(ck.resume ? resumed : part_cdt, in.sizing);
  if(!ck.resume) mesher.use_domain_marks();
  return mesh_with<K>(opt, mesher, sink, ck, st);
}

// The domain in one part: meshed as afmesh_2 does on one thread (in
// streaming mode when `sink` is given).
template <class K>
AFM::Mesh_return_code mesh_whole(const afmesh_2::Options& opt, afmesh_2::Input<K>& in, Sink<K>* sink,
                                 const Part_checkpoints& ck, AFM::Statistics& st)
{
  CDT<K> resumed;
  Part_mesher<K> mesher(ck.resume ? resumed : in.cdt, in.sizing);
  mesher.set_seeds(in.seeds.begin(), in.seeds.end());
  mesher.set_constraint_splitting(false); // load_input() did it
  return mesh_with<K>(opt, mesher, sink, ck, st);
}

// --smooth N on a part meshed in memory, before its interfaces are merged:
// afmesh_2's smoother, its vertices on constrained edges held (the input's
// segments and the cuts: the interfaces stay as the neighbours have them)
// and its free input points too; the seams are smoothed when the
// interfaces are merged (bands.h).
template <class K>
AFM::Smoothing_statistics smooth_part(const afmesh_2::Options& opt, CDT<K>& part_cdt,
                                      const std::vector<typename K::Point_2>& free_points)
{
  typedef typename CDT<K>::Vertex_handle Vertex_handle;
  if(opt.smooth == 0 || part_cdt.dimension() != 2) return AFM::Smoothing_statistics();
  std::set<std::pair<double, double> > held_points;
  for(const auto& p : free_points) held_points.insert({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
  auto held = boost::make_function_property_map<Vertex_handle>([&held_points](Vertex_handle v) {
    return held_points.count({CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())}) > 0;
  });
  const auto np = CGAL::parameters::number_of_iterations(opt.smooth).vertex_is_constrained_map(held);
  return opt.smoother == "laplacian" ? CGAL::laplacian_smooth_mesh_2(part_cdt, np)
                                     : CGAL::quality_smooth_mesh_2(part_cdt, np);
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_PARTS_H
