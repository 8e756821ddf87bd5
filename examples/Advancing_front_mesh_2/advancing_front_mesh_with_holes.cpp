// Meshes a square with a circular hole at a uniform target edge length,
// exactly as one would call CGAL::refine_Delaunay_mesh_2.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Advancing_front_mesher_2.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <list>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_2<K>                Vb;
typedef CGAL::Delaunay_mesh_face_base_2<K>                  Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb>        Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds>  CDT;
typedef K::Point_2                                          Point;

int main(int argc, char* argv[])
{
  const double h = (argc > 1) ? std::atof(argv[1]) : 0.02;
  CDT cdt;
  // outer square, one constraint per side: the mesher keeps input segments
  // unsplit, so boundary points are where the user puts them
  const int n = int(1 / h);
  std::vector<Point> square;
  for(int i = 0; i < n; ++i) square.push_back(Point(double(i) / n, 0));
  for(int i = 0; i < n; ++i) square.push_back(Point(1, double(i) / n));
  for(int i = 0; i < n; ++i) square.push_back(Point(1 - double(i) / n, 1));
  for(int i = 0; i < n; ++i) square.push_back(Point(0, 1 - double(i) / n));
  cdt.insert_constraint(square.begin(), square.end(), true);
  std::vector<Point> circle;
  const int m = int(2 * M_PI * 0.25 / h);
  for(int i = 0; i < m; ++i)
    circle.push_back(Point(0.5 + 0.25 * std::cos(2 * M_PI * i / m), 0.5 + 0.25 * std::sin(2 * M_PI * i / m)));
  cdt.insert_constraint(circle.begin(), circle.end(), true);

  std::list<Point> seeds{Point(0.5, 0.5)}; // the hole
  CGAL::advancing_front_mesh_2(cdt, seeds.begin(), seeds.end(), h);

  std::size_t faces = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->is_in_domain()) ++faces;
  std::cout << "vertices: " << cdt.number_of_vertices() << "\ntriangles in domain: " << faces << "\n";
  return EXIT_SUCCESS;
}
