// afmesh_2_mpi: the interfaces between the ranks' parts released, and the
// mesh made constrained Delaunay across them.
//
// Part r and part r + 1 share the interface of cut r. Rank r + 1 sends rank
// r the band of its triangles near the cut; rank r merges it with its own
// band (internal/Interface_band_2.h: Lawson's flips across the released
// interface, then the seam's vertices smoothed) and says whether the merge
// stayed inside the bands. When it did not, both widen the band and try
// again. Rank r then owns the merged band, and rank r + 1 drops the
// triangles it sent.
#ifndef AFMESH_2_MPI_BANDS_H
#define AFMESH_2_MPI_BANDS_H

#include "channel.h"
#include "parts.h"

#include <CGAL/Advancing_front_mesh_2/internal/Interface_band_2.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

namespace afmesh_2_mpi {

// A band, the triangles of a part near a cut, with the part's triangles it
// holds (so that the part can leave them out of its own output): faces of
// the part's triangulation in memory, or indices of the triangles a
// streamed part held back (streamed.h).
template <class K, class Triangle = typename CDT<K>::Face_handle>
struct Band
{
  AFM::internal::Triangle_soup_2<typename K::Point_2> soup;
  std::vector<Triangle> faces;
};

// The band of the cut starts at 8 sizes of its interface (the seam is
// within 6: as mesh_in_parallel_2(), 3 local sizes and twice 3 interface
// sizes) and is doubled when a merge reaches its edge, at most 4 times (2
// when the part is streamed: it holds back the triangles within 32 sizes).
constexpr double initial_band_sizes = 8;
constexpr std::size_t seam_passes = 3;
constexpr double seam_width = 3;
constexpr std::size_t most_widenings = 4;

// The angle of face f at its vertex k, in degrees.
template <class Face_handle>
double angle_at(Face_handle f, int k)
{
  auto xy = [&](int i) {
    const auto& p = f->vertex((k + i) % 3)->point();
    return std::array<double, 2>{{CGAL::to_double(p.x()), CGAL::to_double(p.y())}};
  };
  const std::array<double, 2> o = xy(0), a = xy(1), b = xy(2);
  const double ux = a[0] - o[0], uy = a[1] - o[1], vx = b[0] - o[0], vy = b[1] - o[1];
  return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180 / 3.14159265358979323846;
}

// --min-angle: the band grown until its outer edges make no corner sharper
// than `degrees` on either side. The outer edges of the band a rank sends
// down are the edges it shares with that rank once the interface is merged,
// constraints of both shares' refinement (min_angle.h): in a corner of them
// (or of one and a segment) narrower than the bound, no point either share
// inserts can make the triangles there good. At a vertex of the band's
// outer edges, the faces around it are cut into sectors by the band's outer
// edges, the constrained edges and the domain's boundary; where a sector
// next to an outer edge is narrower than the bound, every in-domain face at
// the vertex joins the band (the corner is then inside the band, or its
// outer edges go around it). The band only grows, and little: over the 50
// runs of scripts/benchmark_mpi_min_angle.sh about 20 faces joined, in at
// most 2 passes (counted before the limits below, with the same table).
// `most_passes` bounds it all the same, and only the faces
// for which `may_join(f)` holds join: those clear of the part's other band,
// which the grown band must not meet.
template <class K, class May_join>
void round_sharp_corners(const CDT<K>& cdt, std::unordered_set<const void*>& in_band, double degrees,
                         const May_join& may_join, std::size_t most_passes = 3)
{
  typedef typename CDT<K>::Face_handle Face_handle;
  typedef typename CDT<K>::Vertex_handle Vertex_handle;
  auto inside = [&](Face_handle f) { return !cdt.is_infinite(f) && f->is_in_domain(); };
  auto banded = [&](Face_handle f) { return in_band.count(&*f) > 0; };
  for(std::size_t pass = 0; pass < most_passes; ++pass) {
    // the vertices of the outer edges, each once, in the faces' order
    std::vector<Vertex_handle> corners;
    std::unordered_set<const void*> seen;
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if(!banded(f)) continue;
      for(int k = 0; k < 3; ++k) {
        const Face_handle g = f->neighbor(k);
        if(!inside(g) || banded(g)) continue;
        for(const Vertex_handle v : {f->vertex(CDT<K>::ccw(k)), f->vertex(CDT<K>::cw(k))})
          if(seen.insert(&*v).second) corners.push_back(v);
      }
    }
    std::vector<Face_handle> joining;
    for(const Vertex_handle v : corners) {
      // the faces around v in counter-clockwise order, starting after a wall
      std::vector<Face_handle> around;
      auto fc = cdt.incident_faces(v), done = fc;
      do around.push_back(fc); while(++fc != done);
      const std::size_t n = around.size();
      // the edge between around[i] and around[i + 1]: a wall (an outer edge
      // of the band, a constraint, the domain's boundary), and whether it is
      // an outer edge
      auto wall = [&](std::size_t i, bool& outer) {
        const Face_handle f = around[i], g = around[(i + 1) % n];
        outer = inside(f) && inside(g) && banded(f) != banded(g);
        return outer || inside(f) != inside(g) || f->is_constrained(f->index(g));
      };
      std::size_t start = n;
      bool outer = false;
      for(std::size_t i = 0; i < n && start == n; ++i)
        if(wall(i, outer)) start = (i + 1) % n;
      if(start == n) continue; // no wall: v is inside the band or the rest
      bool sharp = false;
      double sector = 0;
      bool sector_at_outer = outer; // the wall before the first sector
      for(std::size_t j = 0; j < n && !sharp; ++j) {
        const std::size_t i = (start + j) % n;
        const Face_handle f = around[i];
        if(inside(f)) sector += angle_at(f, f->index(v));
        bool after_outer = false;
        if(wall(i, after_outer)) {
          sharp = inside(f) && (sector_at_outer || after_outer) && sector < degrees;
          sector = 0;
          sector_at_outer = after_outer;
        }
      }
      if(!sharp) continue;
      for(const Face_handle f : around)
        if(inside(f) && !banded(f) && may_join(f)) joining.push_back(f);
    }
    if(joining.empty()) return;
    for(const Face_handle f : joining) in_band.insert(&*f);
  }
}

// The band of `part_cdt` near cut `c`: its in-domain triangles with a vertex
// within `width` of the cut's line, grown by round_sharp_corners() when
// `corner_degrees` is above 0. The part's constrained edges are input
// constraints unless both ends are points of that cut's interface.
template <class K>
Band<K> band_near_cut(const CDT<K>& part_cdt, const Decomposition<K>& d, std::size_t c, double width,
                      double corner_degrees = 0)
{
  typedef typename CDT<K>::Vertex_handle Vertex_handle;
  Band<K> band;
  const double position = d.plan.cuts[c].position;
  auto near = [&](Vertex_handle v) {
    const double a = AFM::internal::coordinate(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y()),
                                               d.plan.axis);
    return std::abs(a - position) <= width;
  };
  auto on_interface = [&](Vertex_handle v) { return d.interface_points[c].count(key_of(v->point())) > 0; };
  typedef typename CDT<K>::Face_handle Face_handle;
  std::unordered_set<const void*> in_band;
  for(auto f = part_cdt.finite_faces_begin(); f != part_cdt.finite_faces_end(); ++f)
    if(f->is_in_domain() && (near(f->vertex(0)) || near(f->vertex(1)) || near(f->vertex(2)))) in_band.insert(&*f);
  // the faces joining the band for its corners keep clear of the band the
  // part keeps at its other cut (c + 1, above the part whose band is sent
  // down at c): its triangles have a vertex within its first width of 8
  // interface sizes, and reach a size or so beyond
  const bool other_cut = c + 1 < d.plan.cuts.size();
  const double other = other_cut ? d.plan.cuts[c + 1].position : 0;
  const double clear = other_cut ? (initial_band_sizes + 2) * d.interface_size[c + 1] : 0;
  auto clear_of_other_band = [&](Face_handle f) {
    for(int k = 0; other_cut && k < 3; ++k) {
      const auto& p = f->vertex(k)->point();
      if(std::abs(AFM::internal::coordinate(CGAL::to_double(p.x()), CGAL::to_double(p.y()), d.plan.axis) - other) <=
         clear)
        return false;
    }
    return true;
  };
  if(corner_degrees > 0) round_sharp_corners<K>(part_cdt, in_band, corner_degrees, clear_of_other_band);
  band.soup = AFM::internal::triangles_of(
    part_cdt,
    [&](Face_handle f) { return in_band.count(&*f) > 0; },
    [&](Face_handle f, int k) {
      return f->is_constrained(k) &&
             !(on_interface(f->vertex(CDT<K>::ccw(k))) && on_interface(f->vertex(CDT<K>::cw(k))));
    },
    &band.faces);
  AFM::internal::sort_soup(band.soup, &band.faces);
  return band;
}

// A soup as one message: the points as doubles, the triangles (and the
// flags, sent as they are).
struct Soup_message
{
  std::vector<double> xy;
  std::vector<std::uint64_t> triangles;
};

// Sends `soup` to rank `to`; returns the bytes sent.
template <class Point>
std::size_t send_soup(const AFM::internal::Triangle_soup_2<Point>& soup, int to)
{
  Soup_message m;
  for(const Point& p : soup.points) {
    m.xy.push_back(CGAL::to_double(p.x()));
    m.xy.push_back(CGAL::to_double(p.y()));
  }
  for(const auto& t : soup.triangles) m.triangles.insert(m.triangles.end(), t.begin(), t.end());
  send_vector(m.xy, to, BAND);
  send_vector(m.triangles, to, BAND);
  send_vector(soup.constrained, to, BAND);
  return 8 * m.xy.size() + 8 * m.triangles.size() + soup.constrained.size();
}

template <class Point>
AFM::internal::Triangle_soup_2<Point> receive_soup(int from)
{
  AFM::internal::Triangle_soup_2<Point> soup;
  const std::vector<double> xy = receive_vector<double>(from, BAND);
  const std::vector<std::uint64_t> t = receive_vector<std::uint64_t>(from, BAND);
  soup.constrained = receive_vector<unsigned char>(from, BAND);
  for(std::size_t i = 0; i + 1 < xy.size(); i += 2) soup.points.push_back(Point(xy[i], xy[i + 1]));
  for(std::size_t i = 0; i + 2 < t.size(); i += 3) soup.triangles.push_back({{t[i], t[i + 1], t[i + 2]}});
  return soup;
}

// What this rank did at its two interfaces.
template <class K, class Band_type = Band<K> >
struct Interface_work
{
  // cut r - 1 (below): the band sent to rank r - 1 once it settled
  bool has_lower = false;
  Band_type sent;
  // cut r (above): this rank's band, the merged band it now owns, and the
  // vertices of its band and of rank r + 1's in it, by the bands' point
  // orders
  bool has_upper = false;
  Band_type kept_band;
  CDT<K> merged;
  std::vector<typename CDT<K>::Vertex_handle> own_vertices, upper_vertices;
  AFM::internal::Band_merge_statistics merge;
  std::size_t widenings = 0;
  double lower_width = 0, upper_width = 0;
  std::size_t bytes_sent = 0; // the bands sent down (every try)
};

constexpr std::size_t most_streamed_widenings = 2;

// Merges every interface between the ranks' parts, the band of this rank's
// part near cut c of width w being band_of(c, w), widened at most
// `widenings` times; throws std::runtime_error when a band cannot settle
// within its part.
template <class K, class Band_type, class Band_of>
void merge_interfaces(const afmesh_2::Input<K>& in, const Decomposition<K>& d, int rank, const Band_of& band_of,
                      std::size_t widenings, Interface_work<K, Band_type>& w)
{
  typedef typename K::Point_2 Point;
  const std::size_t r = std::size_t(rank);
  const bool meshes = r < d.parts;
  w.has_lower = meshes && r >= 1;
  w.has_upper = meshes && r + 1 < d.parts;
  bool lower_pending = w.has_lower, upper_pending = w.has_upper;
  if(w.has_lower) w.lower_width = initial_band_sizes * d.interface_size[r - 1];
  if(w.has_upper) w.upper_width = initial_band_sizes * d.interface_size[r];
  // the input's free points near the cut are mesh vertices that must not
  // move (as in mesh_in_parallel_2(); the input's other vertices are on
  // constrained edges, which the smoothing leaves)
  std::set<std::pair<double, double> > input_points;
  if(w.has_upper)
    for(std::size_t p : {r, r + 1})
      for(const Point& q : d.free_points[p]) input_points.insert(key_of(q));
  std::string failure;
  while(any_rank(lower_pending || upper_pending)) {
    if(lower_pending) {
      w.sent = band_of(r - 1, w.lower_width);
      w.bytes_sent += send_soup(w.sent.soup, rank - 1);
    }
    if(upper_pending) {
      const AFM::internal::Triangle_soup_2<Point> above = receive_soup<Point>(rank + 1);
      w.kept_band = band_of(r, w.upper_width);
      const double position = d.plan.cuts[r].position, interface_size = d.interface_size[r];
      // the seam, as mesh_in_parallel_2()'s seam_vertices()
      auto in_seam = [&](const Point& p) {
        const double a = AFM::internal::coordinate(CGAL::to_double(p.x()), CGAL::to_double(p.y()), d.plan.axis);
        const double dist = std::abs(a - position);
        return dist <= 2 * seam_width * interface_size && dist <= seam_width * CGAL::to_double(in.sizing(p)) &&
               input_points.count(key_of(p)) == 0;
      };
      w.merged.clear();
      const std::vector<const AFM::internal::Triangle_soup_2<Point>*> soups{&w.kept_band.soup, &above};
      std::vector<std::vector<typename CDT<K>::Vertex_handle> > soup_vertices;
      bool settled = false;
      std::string error;
      try {
        settled = AFM::internal::merge_interface_band(soups, in_seam, seam_passes, w.merged, w.merge, &soup_vertices);
      } catch(const std::exception& e) {
        error = e.what(); // rank r + 1 must hear the verdict all the same
      }
      unsigned char verdict = settled ? 1 : 0;
      if(!error.empty() || (!settled && w.widenings == widenings)) verdict = 2; // give up
      MPI_Send(&verdict, 1, MPI_UNSIGNED_CHAR, rank + 1, BAND_VERDICT, MPI_COMM_WORLD);
      if(settled) {
        upper_pending = false;
        w.own_vertices = soup_vertices[0];
        w.upper_vertices = soup_vertices[1];
      } else if(verdict == 2) {
        upper_pending = false;
        failure = "the merge across cut " + std::to_string(r) + " " +
                  (error.empty() ? "did not settle within " + std::to_string(w.upper_width) + " of the cut" : error);
      } else {
        ++w.widenings;
        w.upper_width *= 2;
      }
    }
    if(lower_pending) {
      unsigned char verdict = 0;
      MPI_Recv(&verdict, 1, MPI_UNSIGNED_CHAR, rank - 1, BAND_VERDICT, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if(verdict == 1) lower_pending = false;
      else if(verdict == 2) {
        lower_pending = false;
        failure = "the merge across cut " + std::to_string(r - 1) + " did not settle";
      } else {
        w.lower_width *= 2;
      }
    }
  }
  // the two bands of a part must not share a vertex: the triangles between
  // them stay with the part, and each shared point has one owner
  if(failure.empty() && w.has_lower && w.has_upper) {
    std::set<std::pair<double, double> > lower;
    for(const Point& p : w.sent.soup.points) lower.insert(key_of(p));
    for(const Point& p : w.kept_band.soup.points)
      if(lower.count(key_of(p)) > 0) {
        failure = "part " + std::to_string(r) + " is too narrow for the bands of its two interfaces";
        break;
      }
  }
  if(any_rank(!failure.empty()))
    throw std::runtime_error(failure.empty() ? "another rank could not merge an interface" : failure);
}

// The interfaces of a part meshed in memory, in `part_cdt`; with
// --min-angle (`corner_degrees`, the bound), the band sent down without
// corners sharper than the bound (round_sharp_corners()).
template <class K>
void merge_interfaces(const afmesh_2::Input<K>& in, const Decomposition<K>& d, int rank, const CDT<K>& part_cdt,
                      Interface_work<K>& w, double corner_degrees = 0)
{
  merge_interfaces<K>(
    in, d, rank,
    [&](std::size_t c, double width) {
      return band_near_cut<K>(part_cdt, d, c, width, c + 1 == std::size_t(rank) ? corner_degrees : 0);
    },
    most_widenings, w);
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_BANDS_H
