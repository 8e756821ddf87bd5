// The input of the validity checker for meshers that split input segments
// (the boundary discretisation, Mesh_2): every input segment cut at the mesh
// vertices that lie on it, found from the coordinates alone. check_mesh() on
// the result then checks that each input segment is covered by a chain of
// mesh edges (and everything else against the split segments).
//
// A mesh vertex lies on a segment when
// - it is an input point exactly on the segment, strictly between its ends
//   (exact predicates: insert_poly() splits segments there), or
// - it is not an input point, projects strictly inside the segment and lies
//   within `ulps` units in the last place of the segment's largest coordinate
//   from its line: a split point that a kernel with inexact constructions
//   (Epick) rounded. The mesher's cuts lie within a few such units.
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
  std::map<std::pair<double, double>, std::size_t> input_points;
  for(std::size_t i = 0; i < in.points.size(); ++i) input_points.emplace(std::make_pair(in.points[i][0], in.points[i][1]), i);
  // mesh vertices by x, for the range of each segment
  std::vector<std::size_t> by_x(mesh.vertices.size());
  for(std::size_t i = 0; i < by_x.size(); ++i) by_x[i] = i;
  std::sort(by_x.begin(), by_x.end(),
            [&](std::size_t a, std::size_t b) { return mesh.vertices[a][0] < mesh.vertices[b][0]; });
  Pslg out;
  out.points = in.points;
  out.holes = in.holes;
  std::map<std::size_t, std::size_t> added; // mesh vertex -> point of out
  for(const auto& s : in.segments) {
    if(s[0] >= in.points.size() || s[1] >= in.points.size()) {
      out.segments.push_back(s); // check_mesh() reports it
      continue;
    }
    const auto& a = in.points[s[0]];
    const auto& b = in.points[s[1]];
    const double largest = (std::max)((std::max)(std::abs(a[0]), std::abs(a[1])),
                                      (std::max)(std::abs(b[0]), std::abs(b[1])));
    const double tol = (std::max)(ulps * largest * std::numeric_limits<double>::epsilon(),
                                  std::numeric_limits<double>::denorm_min());
    const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
    if(!(len2 > 0) || !std::isfinite(len2)) {
      out.segments.push_back(s);
      continue;
    }
    const double x0 = (std::min)(a[0], b[0]) - tol, x1 = (std::max)(a[0], b[0]) + tol;
    const double y0 = (std::min)(a[1], b[1]) - tol, y1 = (std::max)(a[1], b[1]) + tol;
    auto first = std::lower_bound(by_x.begin(), by_x.end(), x0,
                                  [&](std::size_t v, double x) { return mesh.vertices[v][0] < x; });
    std::vector<std::pair<double, std::size_t> > on; // parameter along the segment, mesh vertex
    const P pa(a[0], a[1]), pb(b[0], b[1]);
    for(auto it = first; it != by_x.end() && mesh.vertices[*it][0] <= x1; ++it) {
      const auto& v = mesh.vertices[*it];
      if(v[1] < y0 || v[1] > y1) continue;
      const double t = ((v[0] - a[0]) * dx + (v[1] - a[1]) * dy) / len2;
      if(input_points.count(std::make_pair(v[0], v[1])) != 0) {
        const P pv(v[0], v[1]);
        if(CGAL::collinear(pa, pv, pb) && CGAL::collinear_are_strictly_ordered_along_line(pa, pv, pb))
          on.emplace_back(t, *it);
        continue;
      }
      if(!(t > 0 && t < 1)) continue;
      const double distance = std::abs(dx * (v[1] - a[1]) - dy * (v[0] - a[0])) / std::sqrt(len2);
      if(distance <= tol) on.emplace_back(t, *it);
    }
    std::sort(on.begin(), on.end());
    std::size_t prev = s[0];
    for(const auto& tv : on) {
      const auto found = added.find(tv.second);
      const auto& v = mesh.vertices[tv.second];
      const auto input = input_points.find(std::make_pair(v[0], v[1]));
      std::size_t id;
      if(input != input_points.end()) {
        id = input->second;
      } else if(found != added.end()) {
        id = found->second;
      } else {
        id = out.points.size();
        out.points.push_back(mesh.vertices[tv.second]);
        added.emplace(tv.second, id);
      }
      out.segments.push_back({{prev, id}});
      prev = id;
    }
    out.segments.push_back({{prev, s[1]}});
  }
  return out;
}

} // namespace afm_check

#endif // AFM_SPLIT_SEGMENTS_H
