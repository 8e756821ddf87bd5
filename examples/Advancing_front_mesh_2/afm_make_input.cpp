// Writes one of the project's own test geometries as a Triangle .poly file.
// The default input of the main job (a four-element airfoil from NACA
// formulas in a circular far field) comes from here, so the repository ships
// the code that makes its inputs, not data.
//
//   afm_make_input [GEOMETRY] [OUT.poly] [SPACING]
//   GEOMETRY: multi-element-airfoil (default), square-with-hole, l-shape,
//             two-thin-plates, naca0012, many-holes, nearly-collinear
//   SPACING: boundary spacing of square-with-hole (default 0.01), so that
//            a uniform mesh of size SPACING fits its boundary
#include "afm_geometries.h"

#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  const std::string name = argc > 1 ? argv[1] : "multi-element-airfoil";
  const std::string out = argc > 2 ? argv[2] : name + ".poly";
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
  else {
    std::cerr << "afm_make_input: unknown geometry '" << name << "'\n";
    return EXIT_FAILURE;
  }
  CGAL::Advancing_front_mesh_2::IO::write_poly(out, pd);
  std::cout << "wrote " << out << ": " << pd.points.size() << " points, " << pd.segments.size()
            << " segments, " << pd.holes.size() << " holes\n";
  return EXIT_SUCCESS;
}
