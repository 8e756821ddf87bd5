// The point sources of Mavriplis (1992), Fig. 12, for the four-element
// airfoil of afm_geometry::multi_element_airfoil(): shared by the example
// that reproduces the figure and by the benchmarks.
#ifndef AFM_PAPER_SOURCES_H
#define AFM_PAPER_SOURCES_H

#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#include <CGAL/number_type_config.h>

#include <cmath>
#include <vector>

namespace afm_paper {

// 4 sources on the far field (at 0, 90, 180 and 270 degrees) and 6 near the
// surfaces: ahead of the slat, in the slat cove, over the main element, at
// the main trailing edge, and behind each flap.
template <class K>
std::vector<CGAL::Advancing_front_mesh_2::Size_source_2<K> >
figure_12_sources(const typename K::Point_2& far_centre, double far_radius, double far_size)
{
  typedef typename K::Point_2 Point;
  std::vector<CGAL::Advancing_front_mesh_2::Size_source_2<K> > s;
  for(int i = 0; i < 4; ++i) {
    const double a = i * CGAL_PI / 2;
    s.emplace_back(Point(CGAL::to_double(far_centre.x()) + far_radius * std::cos(a),
                         CGAL::to_double(far_centre.y()) + far_radius * std::sin(a)),
                   far_size);
  }
  s.emplace_back(Point(-0.25, -0.05), 0.012);
  s.emplace_back(Point(-0.03, -0.04), 0.008);
  s.emplace_back(Point(0.45, 0.15), 0.04);
  s.emplace_back(Point(1.0, 0.02), 0.01);
  s.emplace_back(Point(1.25, -0.12), 0.015);
  s.emplace_back(Point(1.45, -0.3), 0.03);
  return s;
}

} // namespace afm_paper

#endif // AFM_PAPER_SOURCES_H
