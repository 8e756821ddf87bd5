// Meshes a square with a hole twice, at a uniform size and with the
// Poisson background field (with AFM_CONSUMER_POISSON; without it, the core
// package alone, which needs no Eigen: at a second uniform size): what a
// user of the installed package compiles.
// Writes the input (square.poly) and the meshes (uniform.off, graded.off)
// to the directory given, for the validity checker.
#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>
#ifdef AFM_CONSUMER_POISSON
#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#endif
#include <CGAL/Advancing_front_mesh_2/version.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <iostream>
#include <iterator>
#include <list>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_2<K> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;
typedef K::Point_2 Point;

// the boundary divided every 0.05 (input segments are never split)
static CGAL::Advancing_front_mesh_2::IO::Poly_data square_with_hole()
{
  CGAL::Advancing_front_mesh_2::IO::Poly_data pd;
  auto loop = [&pd](double x0, double y0, double side, int n) {
    const std::size_t first = pd.points.size();
    for(int i = 0; i < 4 * n; ++i) {
      const int s = i / n, k = i % n;
      const double t = side * k / n;
      const double x = s == 0 ? x0 + t : s == 1 ? x0 + side : s == 2 ? x0 + side - t : x0;
      const double y = s == 0 ? y0 : s == 1 ? y0 + t : s == 2 ? y0 + side : y0 + side - t;
      pd.points.push_back({{x, y}});
      pd.segments.push_back({{first + i, first + (i + 1) % (4 * n)}});
    }
  };
  loop(0, 0, 1, 20);
  loop(0.4, 0.4, 0.2, 4);
  pd.holes.push_back({{0.5, 0.5}});
  return pd;
}

static void insert(CDT& cdt, const CGAL::Advancing_front_mesh_2::IO::Poly_data& pd)
{
  for(const auto& s : pd.segments)
    cdt.insert_constraint(Point(pd.points[s[0]][0], pd.points[s[0]][1]), Point(pd.points[s[1]][0], pd.points[s[1]][1]));
}

int main(int argc, char* argv[])
{
  const std::string dir = argc > 1 ? argv[1] : ".";
  const auto pd = square_with_hole();
  CGAL::Advancing_front_mesh_2::IO::write_poly(dir + "/square.poly", pd);
  std::list<Point> holes{Point(0.5, 0.5)};
  CDT uniform;
  insert(uniform, pd);
  CGAL::advancing_front_mesh_2(uniform, holes.begin(), holes.end(), 0.05);

  CDT graded;
  insert(graded, pd);
#ifdef AFM_CONSUMER_POISSON
  std::vector<std::pair<Point, K::FT> > spacing;
  CGAL::Advancing_front_mesh_2::boundary_spacing_2(graded, std::back_inserter(spacing));
  const CGAL::Advancing_front_mesh_2::Poisson_sizing_field_2<K> field(
    spacing, std::vector<CGAL::Advancing_front_mesh_2::Size_source_2<K> >{{Point(0.1, 0.1), 0.01}});
  CGAL::advancing_front_mesh_2(graded, holes.begin(), holes.end(), field);
#else
  CGAL::advancing_front_mesh_2(graded, holes.begin(), holes.end(), 0.03);
#endif

  std::size_t a = 0, b = 0;
  for(auto f = uniform.finite_faces_begin(); f != uniform.finite_faces_end(); ++f) a += f->is_in_domain();
  for(auto f = graded.finite_faces_begin(); f != graded.finite_faces_end(); ++f) b += f->is_in_domain();
  std::cout << "Advancing_front_mesh_2 " << CGAL_ADVANCING_FRONT_MESH_2_VERSION_STR << ": " << a << " and " << b
            << " triangles\n";
  std::ofstream u(dir + "/uniform.off"), g(dir + "/graded.off");
  CGAL::Advancing_front_mesh_2::IO::write_OFF(u, uniform);
  CGAL::Advancing_front_mesh_2::IO::write_OFF(g, graded);
  return (a > 500 && b > 500 && u && g) ? EXIT_SUCCESS : EXIT_FAILURE;
}
