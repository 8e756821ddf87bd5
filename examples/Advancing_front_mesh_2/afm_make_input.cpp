// Writes one of the project's own test geometries as a Triangle .poly file.
// The default input of the main job (a four-element airfoil from NACA
// formulas in a circular far field) comes from here, so the repository ships
// the code that makes its inputs, not data.
//
//   afm_make_input [GEOMETRY] [OUT.poly] [SPACING]
//   GEOMETRY: multi-element-airfoil (default), square-with-hole, l-shape,
//             two-thin-plates, naca0012, many-holes, nearly-collinear,
//             tagged-regions (three regions, markers, area limits)
//   SPACING: boundary spacing of square-with-hole (default 0.01), so that
//            a uniform mesh of size SPACING fits its boundary
//   afm_make_input from-jigsaw OUT.poly IN.msh: a MESH2D / JIGSAW geometry
//            (closed loops, nested ones holes) as .poly
//
//   afm_make_input HARD-INPUT OUT.poly N
//   the inputs that once made the mesher slow or too fine (afm_hard_inputs.h):
//   collinear-strip (N points per long side), fine-bottom-zigzag and
//   fine-bottom-collinear (N bottom points at spacing 1 in a 100,000 box),
//   fine-bottom-graded-sides (the zigzag box, its sides graded up to 2500),
//   constraint-star (N spokes), offset-square-with-hole (offset 10^N,
//   spacing 2^-8), tiny-holes (N holes), box-with-fine-bottom (N points)
#include "afm_geometries.h"
#include "afm_hard_inputs.h"
#include "afm_shared_data.h"

#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

// The hard inputs by name, or false.
static bool make_hard_input(const std::string& name, double n, CGAL::Advancing_front_mesh_2::IO::Poly_data& pd)
{
  namespace H = afm_hard_inputs;
  const std::size_t count = std::size_t(n);
  if(name == "collinear-strip") pd = H::collinear_strip(count);
  else if(name == "fine-bottom-zigzag") pd = H::fine_bottom_box(count);
  else if(name == "fine-bottom-collinear") pd = H::fine_bottom_box(count, 100000, true);
  else if(name == "fine-bottom-graded-sides") pd = H::fine_bottom_box_graded_sides(count);
  else if(name == "constraint-star") pd = H::constraint_star(count);
  else if(name == "offset-square-with-hole") pd = H::offset_square_with_hole(std::pow(10., n), 1. / 256);
  else if(name == "tiny-holes") pd = H::square_with_tiny_holes(count);
  else if(name == "box-with-fine-bottom") pd = H::box_with_fine_bottom(count);
  else return false;
  return true;
}

int main(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "multi-element-airfoil";
  const std::string out = argc > 2 ? argv[2] : name + ".poly";
  if(name == "from-jigsaw") {
    // a MESH2D / JIGSAW .msh geometry (closed loops; nested ones are holes)
    // as .poly, for meshers that read only .poly (the benchmarks' Triangle)
    if(argc != 4) {
      std::cerr << "afm_make_input: from-jigsaw needs OUT.poly and the .msh file\n";
      return EXIT_FAILURE;
    }
    try {
      const CGAL::Advancing_front_mesh_2::IO::Poly_data pd = afm_shared_data::mesh2d_jigsaw(argv[3]);
      CGAL::Advancing_front_mesh_2::IO::write_poly(out, pd);
      std::cout << "wrote " << out << ": " << pd.points.size() << " points, " << pd.segments.size()
                << " segments, " << pd.holes.size() << " holes\n";
    } catch(const std::exception& e) {
      std::cerr << "afm_make_input: " << e.what() << "\n";
      return EXIT_FAILURE;
    }
    return EXIT_SUCCESS;
  }
  CGAL::Advancing_front_mesh_2::IO::Poly_data hard;
  const double n = argc > 3 ? std::atof(argv[3]) : 1000;
  if(!(n >= 0 && n <= 1e7)) {
    std::cerr << "afm_make_input: N must be a number in [0, 1e7]\n";
    return EXIT_FAILURE;
  }
  if(make_hard_input(name, n, hard)) {
    CGAL::Advancing_front_mesh_2::IO::write_poly(out, hard);
    std::cout << "wrote " << out << ": " << hard.points.size() << " points, " << hard.segments.size()
              << " segments, " << hard.holes.size() << " holes\n";
    return EXIT_SUCCESS;
  }
  const double spacing = argc > 3 ? std::atof(argv[3]) : 0.01;
  if(!(spacing > 0) || !(spacing <= 0.1)) {
    std::cerr << "afm_make_input: the spacing must be a number in (0, 0.1]\n";
    return EXIT_FAILURE;
  }
  CGAL::Advancing_front_mesh_2::IO::Poly_data pd;
  if(name == "multi-element-airfoil") pd = afm_geometry::multi_element_airfoil(4, 256);
  else if(name == "square-with-hole") pd = afm_geometry::square_with_circular_hole(1.0, 0.25, spacing);
  else if(name == "l-shape") pd = afm_geometry::l_shape(0.02);
  else if(name == "two-thin-plates") pd = afm_geometry::two_thin_plates();
  else if(name == "naca0012") pd = afm_geometry::naca0012_far_field(100, 20, 64);
  else if(name == "many-holes") pd = afm_geometry::many_holes(40, 1);
  else if(name == "nearly-collinear") pd = afm_geometry::nearly_collinear_boundary(1e-9);
  else if(name == "tagged-regions") pd = afm_geometry::tagged_regions();
  else {
    std::cerr << "afm_make_input: unknown geometry '" << name << "'\n";
    return EXIT_FAILURE;
  }
  CGAL::Advancing_front_mesh_2::IO::write_poly(out, pd);
  std::cout << "wrote " << out << ": " << pd.points.size() << " points, " << pd.segments.size()
            << " segments, " << pd.holes.size() << " holes\n";
  return EXIT_SUCCESS;
}
