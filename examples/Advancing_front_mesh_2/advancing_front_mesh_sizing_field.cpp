// Meshes a NACA 0012 in a circular far field with a sizing field that grows
// with the distance from the airfoil, using the class API step by step and
// printing the mesher's statistics.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Advancing_front_mesher_2.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <list>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_2<K>                Vb;
typedef CGAL::Delaunay_mesh_face_base_2<K>                  Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb>        Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds>  CDT;
typedef K::Point_2                                          Point;
typedef std::function<K::FT(const Point&)>                  Sizing;

int main()
{
  CDT cdt;
  // NACA 0012 (closed trailing edge), 80 points per side, cosine spacing
  std::vector<Point> foil;
  const int n = 80;
  auto thickness = [](double x) {
    return 0.6 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
  };
  for(int i = 0; i < n; ++i) { const double x = 0.5 * (1 + std::cos(M_PI * i / n)); foil.push_back(Point(x, thickness(x))); }
  for(int i = 0; i < n; ++i) { const double x = 0.5 * (1 - std::cos(M_PI * i / n)); foil.push_back(Point(x, -thickness(x))); }
  cdt.insert_constraint(foil.begin(), foil.end(), true);
  std::vector<Point> far;
  for(int i = 0; i < 48; ++i) far.push_back(Point(0.5 + 10 * std::cos(2 * M_PI * i / 48), 10 * std::sin(2 * M_PI * i / 48)));
  cdt.insert_constraint(far.begin(), far.end(), true);

  // the target edge length: the surface spacing near the airfoil, growing
  // by a fifth of the distance away from it
  Sizing h = [](const Point& p) { return K::FT(0.01 + 0.2 * std::hypot(p.x() - 0.5, p.y())); };
  CGAL::Advancing_front_mesher_2<CDT, Sizing> mesher(cdt, h);
  std::list<Point> seeds{Point(0.3, 0)};
  mesher.set_seeds(seeds.begin(), seeds.end());
  std::size_t steps = 0;
  while(mesher.step_by_step_refine_mesh()) ++steps;

  const auto& s = mesher.statistics();
  std::cout << "front edges processed: " << steps << "\n"
            << "vertices: " << s.number_of_vertices << ", triangles: " << s.number_of_faces << "\n"
            << "points inserted: " << s.points_inserted
            << ", triangles closed on existing points: " << s.triangles_closed_on_existing_points << "\n"
            << "largest front: " << s.largest_front << ", largest live triangle set: " << s.largest_live_triangles << "\n";
  return EXIT_SUCCESS;
}
