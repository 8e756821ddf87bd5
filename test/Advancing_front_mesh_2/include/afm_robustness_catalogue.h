// The robustness catalogue shared by the tests (test_robustness.cpp, the
// kernel matrix) and the inexact-kernel report (benchmark/): the issue
// geometries and the adversarial ones, each with its size, and a reader of
// the CDT library's text format used by ../shared/data/cdt_artem-ogre.
#ifndef AFM_ROBUSTNESS_CATALOGUE_H
#define AFM_ROBUSTNESS_CATALOGUE_H

#include "afm_geometries.h"
#include "afm_test_mesh.h"

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace afm_robustness {

typedef afm_test::Poly_data Poly_data;

// A geometry with its size: uniform h, or graded from the boundary spacing
// (grading > 0, at most h).
struct Case
{
  std::string name;
  Poly_data in;
  double h;
  double grading;
};

// 2^996, about 6.7e299: scaling by a power of two is exact
inline const double huge_scale = std::ldexp(1.0, 996);

inline std::vector<Case> catalogue()
{
  using namespace afm_geometry;
  std::vector<Case> c;
  c.push_back({"square with hole", square_with_circular_hole(1, 0.25, 0.05), 0.05, 0});
  c.push_back({"L-shape", l_shape(0.1), 0.1, 0});
  c.push_back({"two thin plates (Fig. 9)", two_thin_plates(), 1e300, 0.3});
  c.push_back({"NACA 0012 far field", naca0012_far_field(40, 10, 24), 1e300, 0.3});
  c.push_back({"four-element airfoil", multi_element_airfoil(10, 32), 1e300, 0.3});
  c.push_back({"many holes", many_holes(8, 2), 0.05, 0});
  c.push_back({"nearly collinear boundary (1e-12)", nearly_collinear_boundary(1e-12), 0.05, 0});
  c.push_back({"slit of width 1e-7", square_with_slit(1e-7, 0.05), 0.05, 0});
  c.push_back({"boundary spacing varying by 1e4 on one loop", graded_circle(1e4, 0.4), 0.4, 0.3});
  c.push_back({"boundary spacing varying by 1e4, uniform size 0.2", graded_circle(1e4, 0.4), 0.2, 0});
  c.push_back({"cocircular and one-ulp-off points", cocircular_points(), 0.5, 0});
  c.push_back({"huge hole among tiny ones", huge_and_tiny_holes(60), 0.5, 0.3});
  c.push_back({"offset by 1e9", offset(square_with_circular_hole(1, 0.25, 0.05), 1e9, 1e9), 0.05, 0});
  c.push_back({"scaled to 1e+300", scaled(square_with_circular_hole(1, 0.25, 0.05), huge_scale), 0.05 * huge_scale, 0});
  c.push_back({"scaled to 1e-300", scaled(square_with_circular_hole(1, 0.25, 0.05), 1 / huge_scale), 0.05 / huge_scale,
               0});
  return c;
}

template <class K>
struct Case_size
{
  afm_test::Boundary_graded_size<K> graded;
  double h;
  bool uniform;
  Case_size(const Case& c) : graded(c.in, c.grading > 0 ? c.grading : 1, c.h), h(c.h), uniform(c.grading <= 0) {}
  typename K::FT operator()(const typename K::Point_2& p) const
  {
    return uniform ? typename K::FT(h) : graded(p);
  }
};

// The CDT library's format: "nVertices nEdges", the vertices "x y", the
// edges "i j" (0-based). Holes are implied there by even-odd nesting, which
// the mesher does not do: every bounded region is meshed.
inline bool read_cdt_txt(const std::string& path, Poly_data& out, std::string& why)
{
  std::ifstream in(path);
  std::size_t nv = 0, ne = 0;
  if(!(in >> nv >> ne)) {
    why = "no header";
    return false;
  }
  for(std::size_t i = 0; i < nv; ++i) {
    double x, y;
    if(!(in >> x >> y)) {
      why = "truncated vertices";
      return false;
    }
    out.points.push_back({{x, y}});
  }
  for(std::size_t i = 0; i < ne; ++i) {
    std::size_t a, b;
    if(!(in >> a >> b) || a >= nv || b >= nv) {
      why = "bad edge " + std::to_string(i);
      return false;
    }
    out.segments.push_back({{a, b}});
  }
  return true;
}

} // namespace afm_robustness

#endif // AFM_ROBUSTNESS_CATALOGUE_H
