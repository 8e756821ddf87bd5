// afmesh_2_mpi --min-angle: afmesh_2's refinement of the triangles below
// the bound (Mesh_2's Delaunay refinement, refine_to_minimum_angle_2()),
// each rank on its own share once the interfaces are merged, as PCDM
// (Chernikov and Chrisochoides) refines subdomains.
//
// A rank's share is put in a triangulation of its own in which the edges it
// shares with a neighbouring rank (the shared edges: the outer edges of the
// band the rank sent down, and of the band the rank above sent it) are
// constraints. Mesh_2 then refines the share as it refines a domain: where a
// circumcentre would fall beyond a shared edge or encroach on it, the edge
// is split instead. The ranks then work in rounds:
//  1. each rank refines its share (in the later rounds without splitting
//     constraints, then splitting those that its triangles below the bound
//     encroach on, split_encroached_constraints());
//  2. each rank tells its neighbours the points it put on their shared
//     edges, and puts theirs on its own (split_points);
//  3. each rank tells its neighbours the vertex its triangle has opposite
//     each shared edge, and both sides split at its midpoint every edge
//     that is not locally Delaunay between the two triangles
//     (delaunay_across): a point one side inserted near the edge may have
//     put the other side's triangle in conflict with it;
//  4. the rounds end when no rank inserted a point.
// After the last round every edge inside a share is locally Delaunay (the
// share's triangulation is constrained Delaunay), every shared edge is too
// (step 3 found none to split) and no triangle is below the bound but
// where Mesh_2 leaves them (at small input angles) and at corners of the
// shared edges sharper than the bound (split_point()), which with
// --min-angle the band sent down is grown around (round_sharp_corners() in
// bands.h), so that none is left: the whole mesh is
// constrained Delaunay, the shared edges released, as afmesh_2's is.
// A point on a shared edge is inserted by both ranks with the same
// coordinates, so the shares still meet edge to edge. With one part, the
// input's triangulation is refined on rank 0, as afmesh_2 does it.
#ifndef AFMESH_2_MPI_MIN_ANGLE_H
#define AFMESH_2_MPI_MIN_ANGLE_H

#include "channel.h"
#include "parts.h"
#include "pieces.h"
#include "tags.h"

#include <CGAL/Advancing_front_mesh_2/refine_to_minimum_angle_2.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

namespace afmesh_2_mpi {

// What the refinement did over all ranks.
struct Min_angle_figures
{
  AFM::Minimum_angle_statistics total; // the counts summed, the smallest angle the least
  std::uint64_t rounds = 0;
  std::uint64_t shared_points = 0;     // inserted on shared edges (each counted once)
  std::uint64_t delaunay_splits = 0;   // shared edges split by step 3 (each counted once)
  double time = 0;                     // the slowest rank's
};

// The key of an undirected edge: its points' coordinates, the smaller point
// first, so that both sides of a shared edge name it alike.
template <class Point>
Edge_key undirected_key(const Point& a, const Point& b)
{
  const Edge_key ab = edge_key(a, b), ba = edge_key(b, a);
  return (std::min)(ab, ba);
}

// Sends `out` to rank `other` and returns what it sent back; the lower rank
// of the two sends first, so that two blocking sends never wait on each
// other.
inline std::vector<double> swap_with(int rank, int other, const std::vector<double>& out, Tag tag)
{
  if(rank < other) {
    send_vector(out, other, tag);
    return receive_vector<double>(other, tag);
  }
  std::vector<double> in = receive_vector<double>(other, tag);
  send_vector(out, other, tag);
  return in;
}

// The refinement of one rank's share (its triangulation `cdt`, the shared
// edges constrained in it), in the rounds described above; the tags learn
// the points put on segments.
template <class K>
class Share_refinement
{
public:
  typedef CDT<K> Cdt;
  typedef typename Cdt::Vertex_handle Vertex_handle;
  typedef typename Cdt::Face_handle Face_handle;
  typedef typename K::Point_2 Point;

  // `lower` and `upper`: the neighbouring ranks, or -1
  Share_refinement(Cdt& cdt, Share_tags<K>& tags, int rank, int lower, int upper)
      : cdt_(cdt), tags_(tags), rank_(rank), lower_(lower), upper_(upper)
  {
  }

  // Finds the share's edges shared with the neighbours: the edges of one
  // triangle of the share that a neighbour's share has too (an edge of one
  // triangle that no neighbour has is on the domain's boundary, an input
  // constraint). Collective with the neighbours. `once` lists the edges of
  // one triangle, and whether each is an input constraint.
  void find_shared_edges(const std::vector<std::pair<std::pair<Vertex_handle, Vertex_handle>, bool> >& once)
  {
    std::vector<double> mine;
    std::map<Edge_key, std::size_t> index;
    for(std::size_t k = 0; k < once.size(); ++k) {
      const Point &a = once[k].first.first->point(), &b = once[k].first.second->point();
      const Edge_key key = undirected_key(a, b);
      index.emplace(key, k);
      mine.insert(mine.end(), key.begin(), key.end());
      mine.push_back(once[k].second ? 1 : 0);
    }
    std::vector<char> shared(once.size(), 0);
    for(int n : {lower_, upper_}) {
      if(n < 0) continue;
      const std::vector<double> theirs = swap_with(rank_, n, mine, MIN_ANGLE_EDGES);
      for(std::size_t i = 0; i + 4 < theirs.size(); i += 5) {
        const Edge_key key{{theirs[i], theirs[i + 1], theirs[i + 2], theirs[i + 3]}};
        const auto it = index.find(key);
        if(it == index.end()) continue;
        const auto& e = once[it->second];
        if(shared[it->second]) throw std::logic_error("an edge of the share is shared with both neighbours");
        shared[it->second] = 1;
        shared_.emplace(key, Shared_edge{e.first.first, e.first.second, n, e.second || theirs[i + 4] != 0});
      }
    }
    for(std::size_t k = 0; k < once.size(); ++k)
      if(!shared[k] && !once[k].second && !is_segment(once[k].first.first, once[k].first.second))
        throw std::logic_error("an edge of the share's boundary is neither a segment nor shared with a neighbour");
  }

  // The rounds (collective over all ranks); `degrees` in (0, 30].
  void refine(double degrees, std::size_t most_rounds)
  {
    AFM::Minimum_angle_statistics& st = stats_;
    AFM::Minimum_angle_statistics last; // of the last refinement: the share as it is
    for(auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v) known_.insert(&*v);
    const std::size_t vertices_before = cdt_.number_of_vertices();
    const std::size_t lower_vertices_before = shared_vertices(lower_);
    upper_vertices_before_ = shared_vertices(upper_);
    st.angle = degrees;
    for(;;) {
      std::size_t inserted = cdt_.number_of_vertices();
      // 1. the share refined, if it changed since it was last refined, and
      // what that put on shared edges. Mesh_2 run again on a mesh it
      // refined may split a constraint it had left at a small input angle,
      // and there its midpoint can fall outside both triangles of the edge
      // (CGAL issue 781: an assertion in Refine_edges, a crash without
      // assertions; the MESH2D lake at size 0.05 does it): the later rounds
      // split no constraint, as --keep-segments refines; the constraints
      // their triangles' circumcentres encroach on are split here instead
      // (split_encroached_constraints()).
      if(changed_) {
        AFM::Minimum_angle_statistics here = AFM::refine_to_minimum_angle_2(cdt_, degrees, rounds_ == 0);
        if(rounds_ == 0) {
          st.triangles_before = here.triangles_before;
          st.below_before = here.below_before;
        } else
          split_encroached_constraints(degrees, here);
        st.completed = st.completed && here.completed;
        last = here;
        changed_ = false;
      }
      std::map<Edge_key, std::vector<Vertex_handle> > split_here;
      std::vector<double> to_lower, to_upper;
      for(const std::vector<Vertex_handle>& chain : new_chains()) {
        register_splits(chain);
        const auto it = shared_.find(undirected_key(chain.front()->point(), chain.back()->point()));
        if(it == shared_.end()) continue;
        const Edge_key key = it->first;
        const Shared_edge e = it->second;
        shared_.erase(it);
        for(std::size_t k = 0; k + 1 < chain.size(); ++k) add_shared(chain[k], chain[k + 1], e);
        std::vector<double>& out = e.neighbour == lower_ ? to_lower : to_upper;
        out.insert(out.end(), key.begin(), key.end());
        out.push_back(double(chain.size() - 2));
        for(std::size_t k = 1; k + 1 < chain.size(); ++k) {
          out.push_back(CGAL::to_double(chain[k]->point().x()));
          out.push_back(CGAL::to_double(chain[k]->point().y()));
        }
        split_here.emplace(key, chain);
      }
      // 2. the neighbours' points on the shared edges
      for(int n : {lower_, upper_}) {
        if(n < 0) continue;
        const std::vector<double> in = swap_with(rank_, n, n == lower_ ? to_lower : to_upper, MIN_ANGLE_SPLITS);
        for(std::size_t i = 0; i < in.size();) {
          if(i + 5 > in.size()) throw std::logic_error("a malformed list of points on shared edges");
          const Edge_key key{{in[i], in[i + 1], in[i + 2], in[i + 3]}};
          const std::size_t count = std::size_t(in[i + 4]);
          i += 5;
          if(i + 2 * count > in.size()) throw std::logic_error("a malformed list of points on shared edges");
          std::vector<Vertex_handle> chain;
          const auto own = split_here.find(key);
          if(own != split_here.end()) chain = own->second;
          else {
            const auto e = shared_.find(key);
            if(e == shared_.end()) throw std::logic_error("a neighbour split an edge this rank does not share");
            chain = {e->second.a, e->second.b};
          }
          for(std::size_t k = 0; k < count; ++k, i += 2) put_on_chain(chain, Point(in[i], in[i + 1]));
        }
      }
      // 3. the shared edges made locally Delaunay across the ranks
      delaunay_across();
      inserted = cdt_.number_of_vertices() - inserted;
      ++rounds_;
      const bool again = any_rank(inserted > 0);
      if(!again) break;
      if(rounds_ == most_rounds) {
        st.completed = false;
        break;
      }
    }
    // the figures of the share: a point on a shared edge is counted by the
    // lower rank of the two
    st.points_inserted = (cdt_.number_of_vertices() - vertices_before) -
                         (shared_vertices(lower_) - lower_vertices_before);
    // the last refinement's scan is of the share as it is, unless the
    // rounds stopped at their limit; a triangle the rounds changed has a
    // vertex they inserted (an insertion makes only triangles at its point)
    if(changed_) {
      last.triangles_after = last.below_after = 0;
      last.smallest_angle = 180;
      if(cdt_.dimension() == 2)
        for(auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
          if(!f->is_in_domain()) continue;
          const double angle = AFM::internal::smallest_angle_degrees(f->vertex(0)->point(), f->vertex(1)->point(),
                                                                    f->vertex(2)->point());
          ++last.triangles_after;
          last.below_after += angle < degrees * (1 - 1e-9) ? 1 : 0;
          last.smallest_angle = (std::min)(last.smallest_angle, angle);
        }
      if(last.triangles_after == 0) last.smallest_angle = 0;
    }
    st.triangles_after = last.triangles_after;
    st.below_after = last.below_after;
    st.smallest_angle = last.smallest_angle;
    std::unordered_set<const void*> changed;
    for(Vertex_handle v : inserted_) {
      auto f = cdt_.incident_faces(v), done = f;
      do {
        if(!cdt_.is_infinite(f) && f->is_in_domain()) changed.insert(&*f);
      } while(++f != done);
    }
    st.triangles_changed = changed.size();
  }

  const AFM::Minimum_angle_statistics& statistics() const { return stats_; }
  std::size_t rounds() const { return rounds_; }
  // the points the rounds put on the edges shared with the rank above, and
  // the shared edges step 3 split there (each is counted by the lower rank)
  std::size_t upper_points() const { return shared_vertices(upper_) - upper_vertices_before_; }
  std::size_t upper_delaunay_splits() const { return upper_delaunay_splits_; }
  // segments the refinement split, as the tags count them: all but those on
  // edges shared with the rank below (counted there), and all of them
  std::size_t counted_segment_splits() const { return counted_segment_splits_; }
  std::size_t registered_segment_splits() const { return registered_segment_splits_; }
  int lower() const { return lower_; }
  int upper() const { return upper_; }

  // the vertices on edges shared with `neighbour` (none for -1)
  std::vector<Vertex_handle> vertices_shared_with(int neighbour) const
  {
    std::set<Vertex_handle> s;
    if(neighbour >= 0)
      for(const auto& e : shared_)
        if(e.second.neighbour == neighbour) {
          s.insert(e.second.a);
          s.insert(e.second.b);
        }
    return std::vector<Vertex_handle>(s.begin(), s.end());
  }

private:
  // whether a-b is a segment of the input (split to the size, and by the
  // cuts), in either direction
  bool is_segment(Vertex_handle a, Vertex_handle b) const
  {
    auto ordinal = [this](Vertex_handle v) {
      return tags_.input_vertex(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()));
    };
    int marker = 0;
    return tags_.segment(ordinal(a), ordinal(b), marker) || tags_.segment(ordinal(b), ordinal(a), marker);
  }

  std::size_t shared_vertices(int neighbour) const { return vertices_shared_with(neighbour).size(); }

  struct Shared_edge
  {
    Vertex_handle a, b;
    int neighbour;
    bool input; // an input constraint: kept, never made Delaunay
  };

  void add_shared(Vertex_handle a, Vertex_handle b, const Shared_edge& e)
  {
    shared_.emplace(undirected_key(a->point(), b->point()), Shared_edge{a, b, e.neighbour, e.input});
  }

  std::vector<Vertex_handle> constrained_neighbours(Vertex_handle v) const
  {
    std::vector<Vertex_handle> n;
    auto e = cdt_.incident_edges(v), done = e;
    if(e == nullptr) return n;
    do {
      if(!cdt_.is_infinite(*e) && cdt_.is_constrained(*e)) {
        const Vertex_handle a = e->first->vertex(Cdt::cw(e->second)), b = e->first->vertex(Cdt::ccw(e->second));
        n.push_back(a == v ? b : a);
      }
    } while(++e != done);
    return n;
  }

  // The constrained edges the refinement split since the last call, each
  // as the chain of vertices from one end of the edge it split to the other
  // (Mesh_2 splits a constraint into two, so a new vertex on a constraint
  // has two constrained edges); the new vertices become known.
  std::vector<std::vector<Vertex_handle> > new_chains()
  {
    std::vector<Vertex_handle> fresh;
    for(auto v = cdt_.finite_vertices_begin(); v != cdt_.finite_vertices_end(); ++v)
      if(known_.count(&*v) == 0) fresh.push_back(v);
    std::unordered_set<const void*> done;
    std::vector<std::vector<Vertex_handle> > chains;
    auto walk = [&](Vertex_handle from, Vertex_handle to) {
      std::vector<Vertex_handle> path;
      while(known_.count(&*to) == 0) {
        const std::vector<Vertex_handle> n = constrained_neighbours(to);
        if(n.size() != 2) throw std::logic_error("a point the refinement put on a constraint is not inside it");
        path.push_back(to);
        done.insert(&*to);
        const Vertex_handle next = n[0] == from ? n[1] : n[0];
        from = to;
        to = next;
      }
      path.push_back(to);
      return path;
    };
    for(Vertex_handle v : fresh) {
      if(done.count(&*v) > 0) continue;
      const std::vector<Vertex_handle> n = constrained_neighbours(v);
      if(n.empty()) continue; // a circumcentre
      if(n.size() != 2) throw std::logic_error("a point the refinement put on a constraint is not inside it");
      done.insert(&*v);
      std::vector<Vertex_handle> left = walk(v, n[0]), right = walk(v, n[1]);
      std::vector<Vertex_handle> chain(left.rbegin(), left.rend());
      chain.push_back(v);
      chain.insert(chain.end(), right.begin(), right.end());
      chains.push_back(chain);
    }
    for(Vertex_handle v : fresh) {
      known_.insert(&*v);
      inserted_.push_back(v);
    }
    return chains;
  }

  // The tags learn the points on the segments, as the cuts' points: a
  // point on a segment has its marker, and the two halves are segments.
  void register_splits(const std::vector<Vertex_handle>& chain)
  {
    const auto lower = shared_.find(undirected_key(chain.front()->point(), chain.back()->point()));
    const bool counted_below = lower != shared_.end() && lower->second.neighbour == lower_ && lower_ >= 0;
    for(std::size_t k = 1; k + 1 < chain.size(); ++k) split_segment(chain[k - 1], chain.back(), chain[k], counted_below);
  }

  void split_segment(Vertex_handle a, Vertex_handle b, Vertex_handle v, bool counted_below)
  {
    const std::size_t n = tags_.number_of_segments();
    tags_.split_segment(a->point(), b->point(), v->point());
    const std::size_t split = tags_.number_of_segments() - n;
    registered_segment_splits_ += split;
    if(!counted_below) counted_segment_splits_ += split;
  }

  // Puts p on the shared edge that `chain` (its vertices in order, from
  // one end of an edge shared at the start of the round to the other) has
  // it on, unless it is a vertex of the chain already.
  void put_on_chain(std::vector<Vertex_handle>& chain, const Point& p)
  {
    const Point &a = chain.front()->point(), &b = chain.back()->point();
    const double ux = CGAL::to_double(b.x()) - CGAL::to_double(a.x()), uy = CGAL::to_double(b.y()) - CGAL::to_double(a.y());
    auto along = [&](const Point& q) {
      return (CGAL::to_double(q.x()) - CGAL::to_double(a.x())) * ux + (CGAL::to_double(q.y()) - CGAL::to_double(a.y())) * uy;
    };
    const double t = along(p);
    std::size_t k = 0;
    for(; k + 1 < chain.size(); ++k) {
      if(chain[k + 1]->point() == p || chain[k]->point() == p) return;
      if(t < along(chain[k + 1]->point())) break;
    }
    if(k + 1 >= chain.size()) throw std::logic_error("a point of a shared edge is beyond its end");
    const Vertex_handle v = split_shared(chain[k], chain[k + 1], p);
    chain.insert(chain.begin() + std::ptrdiff_t(k + 1), v);
  }

  // Inserts p on the shared edge a-b (both sides do, with the same p).
  Vertex_handle split_shared(Vertex_handle a, Vertex_handle b, const Point& p)
  {
    const auto it = shared_.find(undirected_key(a->point(), b->point()));
    Face_handle f;
    int i = 0;
    if(it == shared_.end() || !cdt_.is_edge(a, b, f, i) || !f->is_constrained(i))
      throw std::logic_error("a point for an edge this rank does not share");
    const Shared_edge e = it->second;
    shared_.erase(it);
    const Vertex_handle v = insert_on_constraint(f, i, p);
    known_.insert(&*v);
    inserted_.push_back(v);
    changed_ = true;
    add_shared(a, v, e);
    add_shared(v, b, e);
    if(e.input) split_segment(a, b, v, e.neighbour == lower_);
    return v;
  }

  // Inserts p on the constrained edge (f, i) (a shared edge or a
  // segment), which it splits; the faces the insertion makes on each side
  // of the edge are in the domain as the face there was (a segment inside
  // the domain has it on both sides, a shared edge or a boundary segment on
  // one). The sides are told by the faces' order around the new vertex,
  // not by where their points are: a face beside the edge can be a sliver
  // whose centre is on the wrong side of the line by rounding (the
  // airfoil's far field on 5 ranks had one, outside the share, and it came
  // out in the domain as a flat triangle).
  Vertex_handle insert_on_constraint(Face_handle f, int i, const Point& p)
  {
    // f's side of a -> b is its left (a face's vertices turn counterclockwise)
    const Vertex_handle a = f->vertex(Cdt::ccw(i)), b = f->vertex(Cdt::cw(i));
    const Face_handle g = f->neighbor(i);
    const bool left_in = !cdt_.is_infinite(f) && f->is_in_domain(), right_in = !cdt_.is_infinite(g) && g->is_in_domain();
    if(!left_in && !right_in) throw std::logic_error("a constraint with no triangle of the share");
    const Vertex_handle v = cdt_.insert(p, Cdt::EDGE, f, i);
    // counterclockwise around v, the faces from v-b to v-a are on the
    // left of a -> b, those from v-a to v-b on its right
    auto fc = cdt_.incident_faces(v), done = fc;
    while(fc->vertex(Cdt::ccw(fc->index(v))) != b)
      if(++fc == done) throw std::logic_error("a point put on a constraint does not split it");
    done = fc;
    bool left = true;
    do {
      fc->set_in_domain(!cdt_.is_infinite(fc) && (left ? left_in : right_in));
      const Vertex_handle last = fc->vertex(Cdt::cw(fc->index(v)));
      if(last == a) left = false;
      if(last == b) left = true;
    } while(++fc != done);
    return v;
  }

  // The constrained edges around the faces of the share in conflict with c
  // (c in their circumcircle) that can be reached from f, in conflict with
  // it, without crossing a constraint: the edges whose encroachment by c
  // Mesh_2 tests (wherever c itself lies). Not the CDT's
  // get_conflicts_and_boundary(), which starts from the face that contains
  // c: beyond a shared edge that face is outside the share, and its zone
  // holds none of the share's edges.
  std::vector<typename Cdt::Edge> constrained_edges_around_conflicts(Face_handle f, const Point& c) const
  {
    std::vector<typename Cdt::Edge> edges;
    std::vector<Face_handle> stack{f};
    std::unordered_set<const void*> seen{&*f};
    while(!stack.empty()) {
      const Face_handle g = stack.back();
      stack.pop_back();
      for(int i = 0; i < 3; ++i) {
        if(g->is_constrained(i)) {
          edges.emplace_back(g, i);
          continue;
        }
        const Face_handle n = g->neighbor(i);
        if(cdt_.is_infinite(n) || !n->is_in_domain() || seen.count(&*n) > 0 || !cdt_.test_conflict(c, n)) continue;
        seen.insert(&*n);
        stack.push_back(n);
      }
    }
    return edges;
  }

  // The smallest angle, in radians, the constrained edge v-w makes with
  // another constraint at v (pi if there is none).
  double angle_at(Vertex_handle v, Vertex_handle w) const
  {
    const double vx = CGAL::to_double(v->point().x()), vy = CGAL::to_double(v->point().y());
    const double wx = CGAL::to_double(w->point().x()) - vx, wy = CGAL::to_double(w->point().y()) - vy;
    double smallest = CGAL_PI;
    for(Vertex_handle u : constrained_neighbours(v)) {
      if(u == w) continue;
      const double ux = CGAL::to_double(u->point().x()) - vx, uy = CGAL::to_double(u->point().y()) - vy;
      smallest = (std::min)(smallest, std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy));
    }
    return smallest;
  }

  // Where split_encroached_constraints() splits the constrained edge a-b,
  // or nothing. At its midpoint, as Mesh_2 splits, but where a-b makes an
  // angle below 60 degrees with another constraint at one end (the apex):
  // there midpoints could split the two edges in turn without end
  // (Ruppert's small input angles), and the split is on a concentric shell
  // around the apex instead (Shewchuk's concentric circular shells, which
  // Mesh_2's clusters also use): at a power of two from it, in the middle
  // third of the edge, so that both edges at the apex are split at the same
  // distances and their short pieces make an isosceles triangle there. The
  // cuts make such apexes where they meet the boundary obliquely (51
  // degrees on the airfoil). An apex below the bound is left as it is: no
  // split makes its triangle good.
  //
  // Both ranks of a shared edge may split it in the same round, each
  // deciding on its own side's constraints; each then inserts the other's
  // point too (step 2). So that two such points are never a rounding error
  // apart, both compute from the edge's key order, and a shell that falls
  // at the midpoint (as it does on the pieces of an edge split on shells
  // before) is the midpoint, computed as the midpoint.
  std::optional<Point> split_point(Vertex_handle a, Vertex_handle b, double degrees) const
  {
    if(undirected_key(a->point(), b->point()) != edge_key(a->point(), b->point())) std::swap(a, b);
    const double at_a = angle_at(a, b), at_b = angle_at(b, a), bound = degrees * CGAL_PI / 180;
    if((std::min)(at_a, at_b) < bound * (1 - 1e-9)) return std::nullopt;
    const double ax = CGAL::to_double(a->point().x()), ay = CGAL::to_double(a->point().y());
    const double bx = CGAL::to_double(b->point().x()), by = CGAL::to_double(b->point().y());
    const Point midpoint((ax + bx) / 2, (ay + by) / 2);
    const bool small_a = at_a < CGAL_PI / 3, small_b = at_b < CGAL_PI / 3;
    if(small_a == small_b) return midpoint;
    const double length = std::hypot(bx - ax, by - ay);
    // the power of two in [length / 3, 2 length / 3] (one is, the interval
    // spans a factor of 2)
    const double shell = std::exp2(std::ceil(std::log2(length / 3)));
    if(std::abs(shell - length / 2) <= 1e-6 * length) return midpoint;
    const double t = (small_a ? shell : length - shell) / length;
    return Point(ax + t * (bx - ax), ay + t * (by - ay));
  }

  // The later rounds' refinement splits no constraint, so a triangle below
  // the bound whose circumcentre encroaches on a constraint (lies in its
  // diametral circle, or beyond it) stays: a neighbour's point on a shared
  // edge makes such triangles next to it, and Mesh_2's circumcentres near
  // them more (the airfoil at size 0.03 on 2 ranks had 11 left, at the
  // airfoil's surface and the far field where the cut meets them). Such a
  // constraint, a shared edge or a segment, is split here, as Mesh_2
  // splits encroached edges, and the share refined again, until
  // no triangle below the bound encroaches on one (split_point() says
  // where, and leaves apexes below the bound); the points on shared edges
  // go to the neighbour in step 2, and the tags learn those on segments
  // (new_chains() finds both). `here` becomes the figures of the share as
  // it is, the points inserted added up.
  void split_encroached_constraints(double degrees, AFM::Minimum_angle_statistics& here)
  {
    typename K::Construct_circumcenter_2 circumcenter;
    for(std::size_t pass = 0; here.below_after > 0; ++pass) {
      // the edges to split, each once (by their vertices: an insertion
      // replaces the faces around it)
      std::map<Edge_key, std::pair<Vertex_handle, Vertex_handle> > encroached;
      for(auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
        if(!f->is_in_domain()) continue;
        const Point &p0 = f->vertex(0)->point(), &p1 = f->vertex(1)->point(), &p2 = f->vertex(2)->point();
        if(!(AFM::internal::smallest_angle_degrees(p0, p1, p2) < degrees * (1 - 1e-9))) continue;
        const Point c = circumcenter(p0, p1, p2);
        for(const auto& e : constrained_edges_around_conflicts(Face_handle(f), c)) {
          const Vertex_handle va = e.first->vertex(Cdt::ccw(e.second)), vb = e.first->vertex(Cdt::cw(e.second));
          const Point &a = va->point(), &b = vb->point();
          const Edge_key key = undirected_key(a, b);
          if(encroached.count(key) > 0) continue;
          // beyond the edge (seen from the conflict zone) or in its
          // diametral circle
          const bool beyond = CGAL::orientation(a, b, c) != CGAL::orientation(a, b, e.first->vertex(e.second)->point());
          if(beyond || CGAL::side_of_bounded_circle(a, b, c) != CGAL::ON_UNBOUNDED_SIDE)
            encroached.emplace(key, std::make_pair(va, vb));
        }
      }
      if(encroached.empty()) return;
      // a safeguard, as the refinement's insertion limit: each pass at
      // least halves the edges it splits, so this is reached only beyond
      // what was measured (at most 3 passes)
      if(pass == 32) {
        here.completed = false;
        return;
      }
      std::size_t splits = 0;
      for(const auto& [key, edge] : encroached) {
        const Vertex_handle a = edge.first, b = edge.second;
        Face_handle f;
        int i = 0;
        if(!cdt_.is_edge(a, b, f, i) || !f->is_constrained(i))
          throw std::logic_error("an encroached constraint is not an edge of the share");
        const std::optional<Point> p = split_point(a, b, degrees);
        if(!p) continue;
        insert_on_constraint(f, i, *p);
        ++splits;
      }
      if(splits == 0) return;
      here.points_inserted += splits;
      const AFM::Minimum_angle_statistics again = AFM::refine_to_minimum_angle_2(cdt_, degrees, false);
      here.points_inserted += again.points_inserted;
      here.triangles_after = again.triangles_after;
      here.below_after = again.below_after;
      here.smallest_angle = again.smallest_angle;
      here.completed = here.completed && again.completed;
    }
  }

  // the vertex of the share's triangle at the shared edge a-b, opposite it
  Point opposite(Vertex_handle a, Vertex_handle b) const
  {
    Face_handle f;
    int i = 0;
    if(!cdt_.is_edge(a, b, f, i)) throw std::logic_error("a shared edge is not an edge of the share");
    if(!f->is_in_domain()) {
      const Face_handle g = f->neighbor(i);
      i = g->index(f);
      f = g;
    }
    return f->vertex(i)->point();
  }

  // Step 3: each side sends the vertex opposite each shared edge that is
  // not an input constraint; an edge whose two opposite vertices are in
  // each other's circle is split at its midpoint by both (they decide on
  // the same points with the same exact predicate: the lower rank's
  // vertex first).
  void delaunay_across()
  {
    for(int n : {lower_, upper_}) {
      if(n < 0) continue;
      std::vector<double> out;
      for(const auto& e : shared_) {
        if(e.second.neighbour != n || e.second.input) continue;
        const Point c = opposite(e.second.a, e.second.b);
        out.insert(out.end(), e.first.begin(), e.first.end());
        out.push_back(CGAL::to_double(c.x()));
        out.push_back(CGAL::to_double(c.y()));
      }
      const std::vector<double> in = swap_with(rank_, n, out, MIN_ANGLE_OPPOSITE);
      std::vector<std::pair<Vertex_handle, Vertex_handle> > to_split;
      for(std::size_t i = 0; i + 5 < in.size(); i += 6) {
        const Edge_key key{{in[i], in[i + 1], in[i + 2], in[i + 3]}};
        const auto it = shared_.find(key);
        if(it == shared_.end() || it->second.neighbour != n)
          throw std::logic_error("a neighbour's shared edge is not shared here");
        const Point theirs(in[i + 4], in[i + 5]), mine = opposite(it->second.a, it->second.b);
        const Point a(key[0], key[1]), b(key[2], key[3]);
        const Point& low = n < rank_ ? theirs : mine;
        const Point& high = n < rank_ ? mine : theirs;
        if(CGAL::side_of_bounded_circle(a, b, low, high) == CGAL::ON_BOUNDED_SIDE)
          to_split.emplace_back(it->second.a, it->second.b);
      }
      for(const auto& ab : to_split) {
        const Point a(ab.first->point()), b(ab.second->point());
        const Edge_key key = undirected_key(a, b);
        // the midpoint from the key's order, so both sides compute it alike
        split_shared(ab.first, ab.second, Point((key[0] + key[2]) / 2, (key[1] + key[3]) / 2));
        if(n == upper_) ++upper_delaunay_splits_;
      }
    }
  }

  Cdt& cdt_;
  Share_tags<K>& tags_;
  int rank_, lower_, upper_;
  std::map<Edge_key, Shared_edge> shared_;
  std::unordered_set<const void*> known_;
  std::vector<Vertex_handle> inserted_; // by the rounds
  AFM::Minimum_angle_statistics stats_;
  bool changed_ = true; // since the share was last refined
  std::size_t rounds_ = 0, upper_vertices_before_ = 0, upper_delaunay_splits_ = 0;
  std::size_t counted_segment_splits_ = 0, registered_segment_splits_ = 0;
};

// The rounds of the refinement could go on only on inputs beyond those
// measured (each round ends when no rank inserted a point; the runs of the
// manual took 2 to 4): a safeguard, as the insertion limit of
// refine_to_minimum_angle_2().
constexpr std::size_t most_refinement_rounds = 64;

// The share `m` (its triangles, `input_constraints` per triangle as
// Triangle_soup_2 has them) in `cdt`, empty before: the share's faces in the
// domain, the input constraints and the edges of one triangle (the share's
// boundary) held as constraints. Returns those edges of one triangle and
// whether each is an input constraint. As insert_band() makes a band, but
// with sorted arrays for its maps and the points in spatial order (a share
// is large: with insert_band() the refinement of the MESH2D lake's million
// triangles on 2 ranks took 1.6 s, so 1.0 s): the points are
// inserted in spatial order, every edge of the triangles is inserted as a
// constraint (so that each triangle is a face, cocircular points or not)
// and those inside the share that are no input constraint are released.
// Throws std::logic_error when a triangle is not a face then. The vertex
// of each point goes to `vertices`, when given.
template <class K>
std::vector<std::pair<std::pair<typename CDT<K>::Vertex_handle, typename CDT<K>::Vertex_handle>, bool> >
share_triangulation(const Rank_mesh& m, const std::vector<unsigned char>& input_constraints, CDT<K>& cdt,
                    std::vector<typename CDT<K>::Vertex_handle>* vertices = nullptr)
{
  typedef typename K::Point_2 Point;
  typedef typename CDT<K>::Vertex_handle Vertex_handle;
  typedef typename CDT<K>::Face_handle Face_handle;
  std::vector<std::pair<std::pair<Vertex_handle, Vertex_handle>, bool> > once;
  if(m.triangles.empty()) return once;
  std::vector<Point> points;
  points.reserve(m.points.size());
  for(const auto& p : m.points) points.push_back(Point(p[0], p[1]));
  std::vector<std::size_t> order(points.size());
  for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  typedef CGAL::Spatial_sort_traits_adapter_2<K, typename CGAL::Pointer_property_map<Point>::const_type> Sort_traits;
  CGAL::spatial_sort(order.begin(), order.end(), Sort_traits(CGAL::make_property_map(static_cast<const std::vector<Point>&>(points))));
  std::vector<Vertex_handle> vertex(points.size());
  Face_handle hint;
  for(std::size_t i : order) {
    vertex[i] = cdt.insert(points[i], hint);
    hint = vertex[i]->face();
  }
  // the edges by their local indices, each with how many triangles have it
  // and whether it is an input constraint
  std::vector<std::array<std::uint64_t, 3> > edges; // a < b, input constraint
  edges.reserve(3 * m.triangles.size());
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
    for(std::size_t k = 0; k < 3; ++k) {
      const std::uint64_t a = m.triangles[t][(k + 1) % 3], b = m.triangles[t][(k + 2) % 3];
      edges.push_back({{(std::min)(a, b), (std::max)(a, b), std::uint64_t((input_constraints[t] >> k) & 1)}});
    }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<std::array<std::uint64_t, 2>, bool> > released;
  for(std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    bool input = false;
    for(; j < edges.size() && edges[j][0] == edges[i][0] && edges[j][1] == edges[i][1]; ++j)
      input = input || edges[j][2] != 0;
    if(j - i > 2) throw std::logic_error("an edge of the share is in more than two of its triangles");
    const Vertex_handle a = vertex[edges[i][0]], b = vertex[edges[i][1]];
    cdt.insert_constraint(a, b);
    if(j - i == 1) once.push_back({{a, b}, input});
    else if(!input) released.push_back({{{edges[i][0], edges[i][1]}}, true});
    i = j;
  }
  for(const auto& e : released) {
    Face_handle f;
    int k = 0;
    if(!cdt.is_edge(vertex[e.first[0]], vertex[e.first[1]], f, k))
      throw std::logic_error("an edge of the share is not an edge of its triangulation");
    const Face_handle g = f->neighbor(k);
    f->set_constraint(k, false);
    g->set_constraint(g->index(f), false);
  }
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(false);
  for(const auto& t : m.triangles) {
    Face_handle f;
    if(!cdt.is_face(vertex[t[0]], vertex[t[1]], vertex[t[2]], f) || f->is_in_domain())
      throw std::logic_error("a triangle of the share is not a face of its triangulation");
    f->set_in_domain(true);
  }
  if(vertices != nullptr) *vertices = std::move(vertex);
  return once;
}

// This rank's share, refined: its triangles with every vertex's number.
// A vertex the rank below holds too is owned there (the vertices of the
// edges shared with it, and any other vertex of both shares' boundaries,
// such as one where the domain touches itself): each rank sends the rank
// above the points of its share's boundary, then, once numbered, their
// numbers.
template <class K>
Rank_mesh refined_rank_mesh(const CDT<K>& cdt, const Share_refinement<K>& r, int rank)
{
  Rank_mesh m;
  Vertex_numbering number(m);
  std::vector<std::uint64_t> boundary; // local indices
  if(cdt.dimension() == 2) {
    number.reserve(cdt.number_of_vertices());
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      m.triangles.push_back({{number(f->vertex(0)), number(f->vertex(1)), number(f->vertex(2))}});
      for(int k = 0; k < 3; ++k) {
        const auto g = f->neighbor(k);
        if(cdt.is_infinite(g) || !g->is_in_domain())
          for(int j : {CDT<K>::ccw(k), CDT<K>::cw(k)}) boundary.push_back(m.triangles.back()[std::size_t(j)]);
      }
    }
  }
  std::sort(boundary.begin(), boundary.end());
  boundary.erase(std::unique(boundary.begin(), boundary.end()), boundary.end());
  std::vector<double> boundary_points;
  for(std::uint64_t i : boundary) boundary_points.insert(boundary_points.end(), m.points[i].begin(), m.points[i].end());
  std::map<std::pair<double, double>, std::uint64_t> at;
  for(std::uint64_t i : boundary) at.emplace(std::make_pair(m.points[i][0], m.points[i][1]), i);
  m.owned.assign(m.points.size(), 1);
  if(r.upper() >= 0) send_vector(boundary_points, r.upper(), MIN_ANGLE_IDS);
  std::vector<std::uint64_t> from_below; // local indices of the vertices the rank below owns
  if(r.lower() >= 0) {
    const std::vector<double> points = receive_vector<double>(r.lower(), MIN_ANGLE_IDS);
    for(std::size_t k = 0; 2 * k + 1 < points.size(); ++k) {
      const auto it = at.find(std::make_pair(points[2 * k], points[2 * k + 1]));
      from_below.push_back(it == at.end() ? no_number : it->second);
      if(it != at.end()) m.owned[it->second] = 0;
    }
  }
  for(const auto& v : r.vertices_shared_with(r.lower()))
    if(m.owned[*number.find(v)] != 0) throw std::logic_error("the rank below does not hold a vertex of a shared edge");
  number_owned(m, rank);
  if(r.lower() >= 0) {
    const std::vector<std::uint64_t> ids = receive_vector<std::uint64_t>(r.lower(), MIN_ANGLE_IDS);
    if(ids.size() != from_below.size()) throw std::logic_error("the rank below numbered other points");
    for(std::size_t k = 0; k < ids.size(); ++k)
      if(from_below[k] != no_number) m.global_id[from_below[k]] = ids[k];
  }
  if(r.upper() >= 0) {
    std::vector<std::uint64_t> ids;
    for(std::uint64_t i : boundary) ids.push_back(m.global_id[i]);
    send_vector(ids, r.upper(), MIN_ANGLE_IDS);
  }
  for(std::uint64_t id : m.global_id)
    if(id == no_number) throw std::logic_error("a vertex of the rank's share has no number");
  return m;
}

// The angle figures of a share not refined: its triangles, how many are
// below `degrees`, its smallest angle.
inline AFM::Minimum_angle_statistics share_angles(const Rank_mesh& m, double degrees)
{
  typedef CGAL::Epick::Point_2 Point;
  AFM::Minimum_angle_statistics st;
  st.angle = degrees;
  st.smallest_angle = 180;
  for(const auto& t : m.triangles) {
    auto p = [&](int k) { return Point(m.points[t[std::size_t(k)]][0], m.points[t[std::size_t(k)]][1]); };
    const double angle = AFM::internal::smallest_angle_degrees(p(0), p(1), p(2));
    st.below_before += angle < degrees * (1 - 1e-9) ? 1 : 0;
    st.smallest_angle = (std::min)(st.smallest_angle, angle);
  }
  st.triangles_before = st.triangles_after = m.triangles.size();
  st.below_after = st.below_before;
  if(m.triangles.empty()) st.smallest_angle = 0;
  return st;
}

// The refinement's figures over all ranks (collective): `s` this rank's,
// the rounds (the same on every rank), the points put on the edges shared
// with the rank above and those of them step 3 put there.
inline Min_angle_figures min_angle_figures(const AFM::Minimum_angle_statistics& s, std::size_t rounds,
                                           std::size_t upper_points, std::size_t upper_delaunay_splits,
                                           double seconds)
{
  Min_angle_figures f;
  f.total.angle = s.angle;
  f.total.triangles_before = sum_over_ranks(s.triangles_before);
  f.total.triangles_after = sum_over_ranks(s.triangles_after);
  f.total.below_before = sum_over_ranks(s.below_before);
  f.total.below_after = sum_over_ranks(s.below_after);
  f.total.points_inserted = sum_over_ranks(s.points_inserted);
  f.total.triangles_changed = sum_over_ranks(s.triangles_changed);
  f.total.completed = all_ranks(s.completed);
  double smallest = s.triangles_after > 0 ? s.smallest_angle : 180, slowest = 0;
  MPI_Allreduce(&smallest, &f.total.smallest_angle, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(&seconds, &slowest, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  f.time = slowest;
  f.rounds = rounds;
  f.shared_points = sum_over_ranks(upper_points);
  f.delaunay_splits = sum_over_ranks(upper_delaunay_splits);
  return f;
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_MIN_ANGLE_H
