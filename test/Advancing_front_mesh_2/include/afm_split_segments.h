// The input of the validity checker for meshers that split input segments
// (the boundary discretisation, Mesh_2): every input segment cut at the
// points that lie on it, found from the coordinates alone. check_mesh() on
// the result then checks that each input segment is covered by a chain of
// mesh edges (and everything else against the split segments).
//
// A segment is cut
// - at every input point exactly on it, strictly between its ends (exact
//   predicates; insert_poly() and CGAL's triangulations split segments
//   there), whether the point is a mesh vertex or not (it must be one where
//   the segment borders the domain, and check_mesh() says so), and
// - at the mesh vertices that are not input points and belong to it: a
//   vertex exactly on a segment belongs to that one (input segments meet
//   only at their ends, so it is on no other); any other vertex belongs to
//   the segment it projects strictly inside of and lies within `ulps` units
//   in the last place of that segment's largest coordinate from, the
//   nearest one in those units when there are several: a split point that
//   a kernel with inexact constructions (Epick) rounded. The mesher's cuts
//   lie within a few such units, and it keeps them clear of other
//   constraints by more than that, so each has one segment.
// Input points just off a segment are not taken for split points, so the
// adversarial inputs (points one unit off a line) keep their meaning.
#ifndef AFM_SPLIT_SEGMENTS_H
#define AFM_SPLIT_SEGMENTS_H

#include "afm_validity_checker.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace afm_check {

inline Pslg split_at_mesh_vertices(const Pslg& in, const Mesh& mesh, double ulps = 16)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel::Point_2 P;
  std::map<std::pair<double, double>, std::size_t> input_points; // the first index of each position
  for(std::size_t i = 0; i < in.points.size(); ++i) input_points.emplace(std::make_pair(in.points[i][0], in.points[i][1]), i);
  // input points and mesh vertices by x, for the range of each segment
  auto sorted_by_x = [](const std::vector<detail::Point2>& points) {
    std::vector<std::size_t> order(points.size());
    for(std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return points[a][0] < points[b][0]; });
    return order;
  };
  const std::vector<std::size_t> inputs_by_x = sorted_by_x(in.points);
  const std::vector<std::size_t> vertices_by_x = sorted_by_x(mesh.vertices);
  auto x_range = [](const std::vector<std::size_t>& order, const std::vector<detail::Point2>& points, double x0) {
    return std::lower_bound(order.begin(), order.end(), x0,
                            [&](std::size_t v, double x) { return points[v][0] < x; });
  };

  // the points on each segment: (parameter along it, input point) and,
  // for the mesh vertices that are not input points, the segment each
  // belongs to with its score (-1 exactly on it, else distance / tolerance)
  const std::size_t none = std::size_t(-1);
  std::vector<std::vector<std::pair<double, std::size_t> > > inputs_on(in.segments.size());
  std::vector<std::pair<double, std::size_t> > owner(mesh.vertices.size(), std::make_pair(2.0, none));
  std::vector<double> parameter_of(mesh.vertices.size(), 0);
  std::vector<bool> usable(in.segments.size(), false);
  // a segment given twice (either way round, or by duplicate points) is cut
  // once, at the first copy, and every copy gets that chain
  std::vector<std::size_t> first_copy(in.segments.size(), none);
  std::map<std::pair<std::pair<double, double>, std::pair<double, double> >, std::size_t> copies;
  for(std::size_t k = 0; k < in.segments.size(); ++k) {
    const auto& s = in.segments[k];
    if(s[0] >= in.points.size() || s[1] >= in.points.size()) continue; // check_mesh() reports it
    auto ends = std::make_pair(std::make_pair(in.points[s[0]][0], in.points[s[0]][1]),
                               std::make_pair(in.points[s[1]][0], in.points[s[1]][1]));
    if(ends.second < ends.first) std::swap(ends.first, ends.second);
    first_copy[k] = copies.emplace(ends, k).first->second;
    if(first_copy[k] != k) continue;
    const auto& a = in.points[s[0]];
    const auto& b = in.points[s[1]];
    const double largest = (std::max)((std::max)(std::abs(a[0]), std::abs(a[1])),
                                      (std::max)(std::abs(b[0]), std::abs(b[1])));
    const double tol = (std::max)(ulps * largest * std::numeric_limits<double>::epsilon(),
                                  std::numeric_limits<double>::denorm_min());
    const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    if(!(len2 > 0) || !std::isfinite(len2)) continue;
    usable[k] = true;
    const double x0 = (std::min)(a[0], b[0]) - tol, x1 = (std::max)(a[0], b[0]) + tol;
    const double y0 = (std::min)(a[1], b[1]) - tol, y1 = (std::max)(a[1], b[1]) + tol;
    const P pa(a[0], a[1]), pb(b[0], b[1]);
    auto exactly_inside = [&](const detail::Point2& v) {
      const P pv(v[0], v[1]);
      return CGAL::collinear(pa, pv, pb) && CGAL::collinear_are_strictly_ordered_along_line(pa, pv, pb);
    };
    auto parameter = [&](const detail::Point2& v) { return ((v[0] - a[0]) * dx + (v[1] - a[1]) * dy) / len2; };
    for(auto it = x_range(inputs_by_x, in.points, x0); it != inputs_by_x.end() && in.points[*it][0] <= x1; ++it) {
      const auto& v = in.points[*it];
      if(v[1] < y0 || v[1] > y1 || input_points[std::make_pair(v[0], v[1])] != *it) continue;
      if(exactly_inside(v)) inputs_on[k].emplace_back(parameter(v), *it);
    }
    for(auto it = x_range(vertices_by_x, mesh.vertices, x0); it != vertices_by_x.end() && mesh.vertices[*it][0] <= x1;
        ++it) {
      const auto& v = mesh.vertices[*it];
      if(v[1] < y0 || v[1] > y1 || input_points.count(std::make_pair(v[0], v[1])) != 0) continue;
      const double t = parameter(v);
      double score;
      if(exactly_inside(v)) {
        score = -1;
      } else {
        if(!(t > 0 && t < 1)) continue;
        score = std::abs(dx * (v[1] - a[1]) - dy * (v[0] - a[0])) / std::sqrt(len2) / tol;
        if(!(score <= 1)) continue;
      }
      if(score < owner[*it].first) {
        owner[*it] = std::make_pair(score, k);
        parameter_of[*it] = t;
      }
    }
  }

  std::vector<std::vector<std::pair<double, std::size_t> > > added_on(in.segments.size()); // mesh vertices
  for(std::size_t v = 0; v < owner.size(); ++v)
    if(owner[v].second != none) added_on[owner[v].second].emplace_back(parameter_of[v], v);

  Pslg out;
  out.points = in.points;
  out.holes = in.holes;
  // the chain of each first copy: its cuts, as points of out, from its
  // first end to its second
  std::vector<std::vector<std::size_t> > chain(in.segments.size());
  for(std::size_t k = 0; k < in.segments.size(); ++k) {
    if(!usable[k]) continue;
    std::vector<std::pair<double, std::size_t> > cuts = inputs_on[k]; // (parameter, point of out)
    for(const auto& tv : added_on[k]) {
      cuts.emplace_back(tv.first, out.points.size());
      out.points.push_back(mesh.vertices[tv.second]);
    }
    std::sort(cuts.begin(), cuts.end());
    for(const auto& tp : cuts) chain[k].push_back(tp.second);
  }
  for(std::size_t k = 0; k < in.segments.size(); ++k) {
    const auto& s = in.segments[k];
    const std::size_t first = first_copy[k];
    if(first == none || !usable[first]) {
      out.segments.push_back(s);
      continue;
    }
    std::vector<std::size_t> cuts = chain[first];
    if(in.points[s[0]] != in.points[in.segments[first][0]]) std::reverse(cuts.begin(), cuts.end());
    std::size_t prev = s[0];
    for(std::size_t c : cuts) {
      out.segments.push_back({{prev, c}});
      prev = c;
    }
    out.segments.push_back({{prev, s[1]}});
  }
  return out;
}

} // namespace afm_check

#endif // AFM_SPLIT_SEGMENTS_H
