// afmesh_2_mpi: the markers and regions of afmesh_2's outputs, in the
// ranks' shares.
//
// No rank holds the whole mesh, and the parts are cut out of the input, so
// the tags are found on the input (before the cuts), as afmesh_2 --stream
// finds them (IO/internal/Input_tags_2.h): a vertex at an input vertex has
// its marker, every other vertex 0 (the mesher puts no vertex on a
// constraint, and the seam smoothing never moves an input point); a
// triangle has the attribute of the input region its interior starts in;
// a segment (an input constraint beside the domain, the domain on its
// left) is written by the rank whose share holds the triangle on its left,
// so by exactly one rank. The input vertices are found by their
// coordinates in a hash table (a vertex of the mesh at an input vertex has
// its very coordinates), the regions by point location in the input.
#ifndef AFMESH_2_MPI_TAGS_H
#define AFMESH_2_MPI_TAGS_H

#include "pieces.h"

#include <CGAL/Advancing_front_mesh_2/IO/internal/Input_tags_2.h>

#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace afmesh_2_mpi {

struct Pair_hash
{
  std::size_t operator()(const std::pair<double, double>& p) const
  {
    return std::hash<double>()(p.first) * 1000003u ^ std::hash<double>()(p.second);
  }
};

template <class K>
class Share_tags
{
public:
  typedef typename K::Point_2 Point;
  typedef AFM::IO::internal::Input_tags_2<CDT<K> > Input_tags;
  static constexpr std::size_t none = Input_tags::none;

  // `input` as load_input() left it, before the cuts
  Share_tags(const CDT<K>& input, const AFM::Markers_and_regions_2<CDT<K> >& tags) : input_(input, tags)
  {
    for(std::size_t o = 0; o < input_.number_of_input_vertices(); ++o)
      ordinal_.emplace(key_of(input_.input_point(o)), o);
    for(const auto& s : input_.segments()) segment_marker_.emplace(directed(s.a, s.b), s.marker);
  }

  // The cuts split the segment a-b (points of input vertices, or of
  // earlier splits) at v (decompose()'s callback): a-v and v-b are
  // segments with its marker, and v has that marker, as afmesh_2 gives a
  // vertex that splits a segment (Markers_and_regions_2's rules).
  void split_segment(const Point& a, const Point& b, const Point& v)
  {
    auto at = [this](const Point& p) { return input_vertex(CGAL::to_double(p.x()), CGAL::to_double(p.y())); };
    const std::size_t oa = at(a), ob = at(b), ov = input_.number_of_input_vertices() + split_markers_.size();
    int marker = 0;
    for(const auto& from_to : {std::make_pair(oa, ob), std::make_pair(ob, oa)}) {
      if(from_to.first == none || from_to.second == none) break;
      const auto it = segment_marker_.find(directed(from_to.first, from_to.second));
      if(it == segment_marker_.end()) continue;
      marker = it->second;
      segment_marker_.erase(it);
      segment_marker_.emplace(directed(from_to.first, ov), marker);
      segment_marker_.emplace(directed(ov, from_to.second), marker);
      ++split_segments_;
      break;
    }
    ordinal_.emplace(key_of(v), ov);
    split_markers_.push_back(marker);
  }

  bool has_regions() const { return input_.has_regions(); }
  // the region attributes of the input, 0 included; empty without regions
  const std::vector<double>& attributes() const { return input_.attributes(); }
  std::size_t number_of_segments() const { return input_.segments().size() + split_segments_; }

  // the input vertex at (x, y), or none
  std::size_t input_vertex(double x, double y) const
  {
    const auto it = ordinal_.find(key_of(x, y));
    return it == ordinal_.end() ? none : it->second;
  }
  int marker(std::size_t ordinal) const
  {
    const std::size_t n = input_.number_of_input_vertices();
    return ordinal == none ? 0 : ordinal < n ? input_.marker(ordinal) : split_markers_[ordinal - n];
  }
  int marker_at(double x, double y) const { return marker(input_vertex(x, y)); }

  // whether a -> b (input vertices) is a segment with the domain on its
  // left, and its marker
  bool segment(std::size_t a, std::size_t b, int& marker) const
  {
    if(a == none || b == none) return false;
    const auto it = segment_marker_.find(directed(a, b));
    if(it == segment_marker_.end()) return false;
    marker = it->second;
    return true;
  }

  // The attribute of the region of the triangle (a, b, c): of the input
  // face its interior starts in at a (Input_tags_2). A vertex the cuts
  // made is not a vertex of the input: the cut's crossing with a sloped
  // segment is rounded to a double, maybe to either side of the segment,
  // so the face found at it, or along an edge from it, may be the
  // neighbour's. Then the triangle's centroid, which is far from every
  // input edge (it is inside the triangle, by a third of its heights),
  // finds the face.
  double region_attribute(const Point& a, const Point& b, const Point& c)
  {
    if(!split_markers_.empty() && (made_by_cuts(a) || made_by_cuts(b) || made_by_cuts(c))) {
      const Point centroid((CGAL::to_double(a.x()) + CGAL::to_double(b.x()) + CGAL::to_double(c.x())) / 3,
                           (CGAL::to_double(a.y()) + CGAL::to_double(b.y()) + CGAL::to_double(c.y())) / 3);
      return input_.region_attribute(centroid, b, c);
    }
    return input_.region_attribute(a, b, c);
  }

private:
  bool made_by_cuts(const Point& p) const
  {
    const std::size_t o = input_vertex(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
    return o != none && o >= input_.number_of_input_vertices();
  }

  static std::uint64_t directed(std::size_t a, std::size_t b) { return (std::uint64_t(a) << 32) | std::uint64_t(b); }

  Input_tags input_;
  std::unordered_map<std::pair<double, double>, std::size_t, Pair_hash> ordinal_;
  std::unordered_map<std::uint64_t, int> segment_marker_;
  std::vector<int> split_markers_; // of the vertices the cuts added, by ordinal from the input's count
  std::size_t split_segments_ = 0;
};

// Finds the tags of the triangles `triangles` (indices into `points`).
template <class K>
Share_tagging tag_share(Share_tags<K>& tags, const std::vector<std::array<double, 2> >& points,
                        const std::vector<std::array<std::uint64_t, 3> >& triangles)
{
  typedef typename K::Point_2 Point;
  Share_tagging t;
  t.regions = tags.has_regions();
  std::vector<std::size_t> ordinal(points.size());
  t.markers.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    ordinal[i] = tags.input_vertex(points[i][0], points[i][1]);
    t.markers[i] = tags.marker(ordinal[i]);
  }
  for(const auto& tri : triangles) {
    if(tags.has_regions()) {
      auto p = [&](int k) { return Point(points[tri[std::size_t(k)]][0], points[tri[std::size_t(k)]][1]); };
      t.regions_of_triangles.push_back(tags.region_attribute(p(0), p(1), p(2)));
    }
    for(std::size_t k = 0; k < 3; ++k) {
      const std::uint64_t a = tri[k], b = tri[(k + 1) % 3];
      int marker = 0;
      if(tags.segment(ordinal[a], ordinal[b], marker)) {
        t.segments.push_back({{a, b}});
        t.segment_markers.push_back(marker);
      }
    }
  }
  return t;
}

// Every segment found by one rank exactly: a logic error otherwise. The
// refinement of --min-angle (min_angle.h) splits segments on each rank
// alone: `registered_here` of this rank's tags are its splits, of which
// `counted_here` are not counted by another rank (a segment both ranks of
// a shared edge hold is counted by the lower one).
template <class K>
void check_segments_found(const Share_tags<K>& tags, std::uint64_t found_here, std::uint64_t registered_here = 0,
                          std::uint64_t counted_here = 0)
{
  const std::uint64_t found = sum_over_ranks(found_here);
  const std::uint64_t expected = tags.number_of_segments() - registered_here + sum_over_ranks(counted_here);
  if(found != expected)
    throw std::logic_error("the ranks found " + std::to_string(found) + " boundary segments of the input's " +
                           std::to_string(expected));
}

} // namespace afmesh_2_mpi

#endif // AFMESH_2_MPI_TAGS_H
