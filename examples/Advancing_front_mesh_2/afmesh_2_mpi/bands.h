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

#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <string>
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

// The band of `part_cdt` near cut `c`: its in-domain triangles with a vertex
// within `width` of the cut's line. The part's constrained edges are input
// constraints unless both ends are points of that cut's interface.
template <class K>
Band<K> band_near_cut(const CDT<K>& part_cdt, const Decomposition<K>& d, std::size_t c, double width)
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
  band.soup = AFM::internal::triangles_of(
    part_cdt,
    [&](Face_handle f) {
      return f->is_in_domain() && (near(f->vertex(0)) || near(f->vertex(1)) || near(f->vertex(2)));
    },
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

// The band of the cut starts at 8 sizes of its interface (the seam is
// within 6: as mesh_in_parallel_2(), 3 local sizes and twice 3 interface
// sizes) and is doubled when a merge reaches its edge, at most 4 times (2
// when the part is streamed: it holds back the triangles within 32 sizes).
constexpr double initial_band_sizes = 8;
constexpr std::size_t seam_passes = 3;
constexpr double seam_width = 3;
constexpr std::size_t most_widenings = 4;
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

// The interfaces of a part meshed in memory, in `part_cdt`.
template <class K>
void merge_interfaces(const afmesh_2::Input<K>& in, const Decomposition<K>& d, int rank, const CDT<K>& part_cdt,
                      Interface_work<K>& w)
{
  merge_interfaces<K>(
    in, d, rank, [&](std::size_t c, double width) { return band_near_cut<K>(part_cdt, d, c, width); },
    most_widenings, w);
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_BANDS_H
