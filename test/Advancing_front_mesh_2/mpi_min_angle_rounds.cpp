// Step 3 of afmesh_2_mpi's --min-angle rounds (examples/Advancing_front_mesh_2/
// afmesh_2_mpi/min_angle.h), which no run of the tool has reached: an edge
// two ranks share that is not locally Delaunay across them is split at the
// same midpoint by both, until every shared edge is.
//
// Run on 2 ranks (mpi_checks.py does). The domain is the quadrilateral
// d a c b; rank 0's share is the triangle (a, b, d), rank 1's (b, a, c),
// sharing the edge a-b (the interface). The angles at d (90 degrees) and c
// (118 degrees) add up to more than 180: c is in the circle of a, b, d, as
// a point inserted by rank 1 near the edge would be. No triangle is below
// the bound (20 degrees), so Mesh_2 inserts nothing and only step 3 acts:
// both ranks must split a-b at (0, 0.5), and then the two halves are
// locally Delaunay (45 + 59 degrees). Rank 0 then checks the whole mesh:
// the shares put together by their global numbers, five vertices numbered
// 0 to 4, four triangles, every edge held by two triangles locally
// Delaunay (exact predicates; the four at the midpoint), and the figures.
#include "afmesh_2_mpi/min_angle.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afmesh_2_mpi::CDT<K> Cdt;
typedef K::Point_2 Point;

namespace {

int failures = 0;

void check(bool ok, const std::string& what)
{
  if(!ok) {
    std::cerr << "mpi_min_angle_rounds: FAILED: " << what << "\n";
    ++failures;
  }
}

// A triangulation of the polygon `corners` (counter-clockwise), its edges
// constraints and its inside the domain.
void polygon(const std::vector<Point>& corners, Cdt& cdt)
{
  for(std::size_t i = 0; i < corners.size(); ++i) cdt.insert_constraint(corners[i], corners[(i + 1) % corners.size()]);
  for(auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->set_in_domain(!cdt.is_infinite(f));
}

} // namespace

int main(int argc, char** argv)
{
  afmesh_2_mpi::Mpi_session mpi(argc, argv);
  if(mpi.ranks != 2) {
    if(mpi.rank == 0) std::cerr << "mpi_min_angle_rounds: run on 2 ranks\n";
    return 2;
  }
  const Point a(0, 0), b(0, 1), c(0.3, 0.5), d(-0.5, 0.5);
  // the input: the quadrilateral, for the tags (its four sides are segments)
  Cdt input;
  polygon({d, a, c, b}, input);
  const CGAL::Advancing_front_mesh_2::Markers_and_regions_2<Cdt> no_tags;
  afmesh_2_mpi::Share_tags<K> tags(input, no_tags);
  // this rank's share, and its edges of one triangle
  Cdt share;
  const bool left = mpi.rank == 0;
  polygon(left ? std::vector<Point>{a, b, d} : std::vector<Point>{b, a, c}, share);
  std::vector<std::pair<std::pair<Cdt::Vertex_handle, Cdt::Vertex_handle>, bool> > once;
  for(auto e = share.finite_edges_begin(); e != share.finite_edges_end(); ++e) {
    const auto u = e->first->vertex(Cdt::cw(e->second)), v = e->first->vertex(Cdt::ccw(e->second));
    const bool interface = u->point().x() == 0 && v->point().x() == 0;
    once.push_back({{u, v}, !interface});
  }
  afmesh_2_mpi::Share_refinement<K> refinement(share, tags, mpi.rank, left ? -1 : 0, left ? 1 : -1);
  refinement.find_shared_edges(once);
  refinement.refine(20, afmesh_2_mpi::most_refinement_rounds);
  const afmesh_2_mpi::Rank_mesh mesh = afmesh_2_mpi::refined_rank_mesh<K>(share, refinement, mpi.rank);
  const afmesh_2_mpi::Min_angle_figures figures = afmesh_2_mpi::min_angle_figures(
    refinement.statistics(), refinement.rounds(), refinement.upper_points(), refinement.upper_delaunay_splits(), 0);

  // the shares to rank 0: points by global number, triangles by them
  std::vector<double> points;
  std::vector<std::uint64_t> triangles;
  for(std::size_t i = 0; i < mesh.points.size(); ++i) {
    points.push_back(double(mesh.global_id[i]));
    points.push_back(mesh.points[i][0]);
    points.push_back(mesh.points[i][1]);
  }
  for(const auto& t : mesh.triangles)
    for(std::uint64_t i : t) triangles.push_back(mesh.global_id[i]);
  if(!left) {
    afmesh_2_mpi::send_vector(points, 0, afmesh_2_mpi::MERGED_POINTS);
    afmesh_2_mpi::send_vector(triangles, 0, afmesh_2_mpi::MERGED_TRIANGLES);
    return 0;
  }
  const std::vector<double> other_points = afmesh_2_mpi::receive_vector<double>(1, afmesh_2_mpi::MERGED_POINTS);
  const std::vector<std::uint64_t> other_triangles =
    afmesh_2_mpi::receive_vector<std::uint64_t>(1, afmesh_2_mpi::MERGED_TRIANGLES);
  points.insert(points.end(), other_points.begin(), other_points.end());
  triangles.insert(triangles.end(), other_triangles.begin(), other_triangles.end());
  std::map<std::uint64_t, Point> at;
  bool one_position = true;
  for(std::size_t k = 0; k + 2 < points.size(); k += 3) {
    const Point p(points[k + 1], points[k + 2]);
    const auto it = at.emplace(std::uint64_t(points[k]), p).first;
    one_position = one_position && it->second == p;
  }
  check(one_position, "a global number has two positions");
  check(at.size() == 5 && at.begin()->first == 0 && at.rbegin()->first == 4,
        "the vertices are not numbered 0 to 4: " + std::to_string(at.size()) + " numbers");
  bool has_midpoint = false;
  for(const auto& v : at) has_midpoint = has_midpoint || v.second == Point(0, 0.5);
  check(has_midpoint, "the shared edge was not split at its midpoint");
  check(triangles.size() == 12, "not 4 triangles: " + std::to_string(triangles.size() / 3));
  // every edge of two triangles locally Delaunay, every triangle
  // counter-clockwise
  std::map<std::pair<std::uint64_t, std::uint64_t>, std::vector<Point> > opposite;
  for(std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    check(CGAL::orientation(at[triangles[t]], at[triangles[t + 1]], at[triangles[t + 2]]) == CGAL::LEFT_TURN,
          "a triangle is not counter-clockwise");
    for(std::size_t k = 0; k < 3; ++k) {
      std::uint64_t u = triangles[t + (k + 1) % 3], v = triangles[t + (k + 2) % 3];
      if(v < u) std::swap(u, v);
      opposite[{u, v}].push_back(at[triangles[t + k]]);
    }
  }
  std::size_t inner = 0;
  for(const auto& e : opposite) {
    if(e.second.size() != 2) continue;
    ++inner;
    check(CGAL::side_of_bounded_circle(at[e.first.first], at[e.first.second], e.second[0], e.second[1]) !=
            CGAL::ON_BOUNDED_SIDE,
          "an edge is not locally Delaunay");
  }
  check(inner == 4, "not 4 inner edges: " + std::to_string(inner));
  check(figures.delaunay_splits == 1 && figures.shared_points == 1 && figures.total.points_inserted == 1 &&
          figures.total.below_before == 0 && figures.total.triangles_after == 4 && figures.rounds == 2,
        "the figures: " + std::to_string(figures.delaunay_splits) + " splits, " +
          std::to_string(figures.shared_points) + " shared points, " +
          std::to_string(figures.total.points_inserted) + " inserted, " + std::to_string(figures.rounds) +
          " rounds");
  if(failures == 0) std::cout << "mpi_min_angle_rounds: all checks passed\n";
  return failures == 0 ? 0 : 1;
}
