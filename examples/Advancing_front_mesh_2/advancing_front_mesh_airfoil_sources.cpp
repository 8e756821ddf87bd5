// The run of Mavriplis (1992), Fig. 12: a four-element airfoil (slat, main
// element, two flap elements, from NACA formulas) in a circular far field,
// with a background size field from 4 point sources at the outer boundary,
// 6 near the surfaces and the spacing of the boundary discretization,
// diffused by a Poisson solve on a quadtree (Poisson_sizing_field_2).
// Writes the global view and a close-up as SVG and prints the statistics,
// then smooths the mesh and swaps edges as in the paper's Fig. 13 and writes
// close-ups coloured by quality before and after.
// With the shared data directory, the same is done for the real 30P-30N
// three-element airfoil.
//
//   advancing_front_mesh_airfoil_sources [OUT_DIR [SHARED_DATA_DIR]]
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>
#include <CGAL/Advancing_front_mesh_2/laplacian_smooth_mesh_2.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>

#include "afm_geometries.h"
#include "afm_paper_sources.h"
#include "afm_shared_data.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_2<K> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;
typedef K::Point_2 Point;
namespace AFM = CGAL::Advancing_front_mesh_2;
typedef AFM::Size_source_2<K> Source;
typedef AFM::Poisson_sizing_field_2<K> Field;

struct Run
{
  std::string name, out_prefix;
  AFM::IO::Poly_data boundary;
  std::vector<Source> sources;
  CGAL::Bbox_2 close_up;
};

// The background quadtree about the boundary points (the paper's Fig. 10),
// leaves shaded by the field's size at their centre, within `window`.
void write_quadtree_svg(const std::string& file, const Field& field, const AFM::IO::Poly_data& boundary,
                        const CGAL::Bbox_2& window)
{
  std::vector<CGAL::Bbox_2> leaves;
  field.leaf_boxes(std::back_inserter(leaves));
  const double width = 1200, scale = width / (window.xmax() - window.xmin());
  const double height = scale * (window.ymax() - window.ymin());
  auto X = [&](double x) { return (x - window.xmin()) * scale; };
  auto Y = [&](double y) { return (window.ymax() - y) * scale; };
  const double lo = std::log(field.statistics().smallest_size), hi = std::log(field.statistics().largest_size);
  std::ofstream os(file);
  os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
     << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for(const CGAL::Bbox_2& b : leaves) {
    if(!CGAL::do_overlap(b, window)) continue;
    const double h = CGAL::to_double(field(Point(0.5 * (b.xmin() + b.xmax()), 0.5 * (b.ymin() + b.ymax()))));
    const int shade = int(255 - 120 * (hi > lo ? (hi - std::log(h)) / (hi - lo) : 0));
    os << "<rect x=\"" << X(b.xmin()) << "\" y=\"" << Y(b.ymax()) << "\" width=\"" << (b.xmax() - b.xmin()) * scale
       << "\" height=\"" << (b.ymax() - b.ymin()) * scale << "\" fill=\"rgb(" << shade << "," << shade
       << ",255)\" stroke=\"#446\" stroke-width=\"0.4\"/>\n";
  }
  for(const auto& s : boundary.segments) {
    const auto& a = boundary.points[s[0]];
    const auto& b = boundary.points[s[1]];
    os << "<line x1=\"" << X(a[0]) << "\" y1=\"" << Y(a[1]) << "\" x2=\"" << X(b[0]) << "\" y2=\"" << Y(b[1])
       << "\" stroke=\"black\" stroke-width=\"1.5\"/>\n";
  }
  os << "</svg>\n";
}

int mesh_and_report(const Run& run)
{
  CDT cdt;
  std::vector<CDT::Vertex_handle> vh;
  for(const auto& p : run.boundary.points) vh.push_back(cdt.insert(Point(p[0], p[1])));
  for(const auto& s : run.boundary.segments) cdt.insert_constraint(vh[s[0]], vh[s[1]]);
  std::vector<Point> seeds;
  for(const auto& h : run.boundary.holes) seeds.push_back(Point(h[0], h[1]));

  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::pair<Point, K::FT> > spacing;
  AFM::boundary_spacing_2(cdt, std::back_inserter(spacing));
  // The paper's field: the boundary spacing diffused with the sources
  // (the default grows it from the boundary instead); gradation limit 0.2.
  AFM::Poisson_sizing_field_options paper;
  paper.boundary_spacing = AFM::Poisson_sizing_field_options::DIFFUSE_WITH_SOURCES;
  const Field field(spacing, run.sources, paper);
  const auto t1 = std::chrono::steady_clock::now();
  const AFM::Mesh_return_code rc = CGAL::advancing_front_mesh_2(cdt, seeds.begin(), seeds.end(), field);
  const auto t2 = std::chrono::steady_clock::now();
  if(rc != AFM::MESH_COMPLETE) {
    std::cerr << run.name << ": meshing stopped early\n";
    return EXIT_FAILURE;
  }

  const auto& fs = field.statistics();
  const AFM::Mesh_quality q = AFM::mesh_quality(cdt);
  std::size_t vertices = 0, triangles = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) triangles += f->is_in_domain();
  vertices = cdt.number_of_vertices();
  auto seconds = [](auto a, auto b) { return std::chrono::duration<double>(b - a).count(); };
  std::cout << run.name << "\n"
            << "  size field: " << fs.number_of_sources << " sources, " << fs.number_of_boundary_points
            << " boundary points, quadtree of " << fs.number_of_leaves << " leaves and " << fs.number_of_corners
            << " corners, sizes " << fs.smallest_size << " to " << fs.largest_size << ", built in "
            << seconds(t0, t1) << " s\n"
            << "  mesh: " << vertices << " vertices, " << triangles << " triangles in " << seconds(t1, t2)
            << " s (" << triangles / seconds(t1, t2) << " triangles/s)\n"
            << "  radius ratio: mean " << q.mean_radius_ratio << ", min " << q.min_radius_ratio << ", "
            << 100 * q.share_above_0_9 << "% above 0.9; angles " << q.min_angle_degrees << " to "
            << q.max_angle_degrees << " degrees\n";

  AFM::IO::SVG_options global;
  global.title = run.name + ": global view";
  global.stroke_scale = 0.5;
  {
    std::ofstream os(run.out_prefix + "_global.svg");
    AFM::IO::write_SVG(os, cdt, global);
  }
  AFM::IO::SVG_options close = global;
  close.title = run.name + ": close-up";
  close.has_window = true;
  close.xmin = run.close_up.xmin();
  close.ymin = run.close_up.ymin();
  close.xmax = run.close_up.xmax();
  close.ymax = run.close_up.ymax();
  {
    std::ofstream os(run.out_prefix + "_closeup.svg");
    AFM::IO::write_SVG(os, cdt, close);
  }
  write_quadtree_svg(run.out_prefix + "_quadtree.svg", field, run.boundary, run.close_up);
  AFM::IO::SVG_options coloured = close;
  coloured.color_by_quality = true;
  coloured.title = run.name + ": close-up coloured by radius ratio";
  {
    std::ofstream os(run.out_prefix + "_closeup_quality.svg");
    AFM::IO::write_SVG(os, cdt, coloured);
  }
  AFM::IO::write_poly(run.out_prefix + ".poly", run.boundary);
  AFM::IO::write_mesh(run.out_prefix + ".off", cdt);
  // The paper's Fig. 13: Laplacian smoothing, then edge swapping to restore
  // the Delaunay property.
  const auto t3 = std::chrono::steady_clock::now();
  const auto smoothing = CGAL::laplacian_smooth_mesh_2(cdt, CGAL::parameters::number_of_iterations(5));
  const auto t4 = std::chrono::steady_clock::now();
  const AFM::Mesh_quality qs = AFM::mesh_quality(cdt);
  std::cout << "  after 5 smoothing passes (" << seconds(t3, t4) << " s, " << smoothing.moves << " moves, "
            << smoothing.flips << " edges swapped): radius ratio mean " << qs.mean_radius_ratio << ", min "
            << qs.min_radius_ratio << ", " << 100 * qs.share_above_0_9 << "% above 0.9; angles "
            << qs.min_angle_degrees << " to " << qs.max_angle_degrees << " degrees\n";
  coloured.title = run.name + ": smoothed, coloured by radius ratio";
  {
    std::ofstream os(run.out_prefix + "_smoothed_closeup_quality.svg");
    AFM::IO::write_SVG(os, cdt, coloured);
  }
  AFM::IO::write_mesh(run.out_prefix + "_smoothed.off", cdt);
  std::cout << "  wrote " << run.out_prefix << "{_global,_closeup,_quadtree,_closeup_quality,_smoothed_closeup_quality}.svg, "
            << run.out_prefix << ".poly and " << run.out_prefix << "{,_smoothed}.off\n";
  return EXIT_SUCCESS;
}

int main(int argc, char* argv[])
{
  const std::string out_dir = argc > 1 ? argv[1] : ".";
  const double far_radius = 15;
  const std::size_t far_points = 64;
  int status = EXIT_SUCCESS;

  Run four;
  four.name = "four-element airfoil (Mavriplis 1992, Fig. 12)";
  four.out_prefix = out_dir + "/four_element_airfoil";
  four.boundary = afm_geometry::multi_element_airfoil(far_radius, far_points);
  four.sources = afm_paper::figure_12_sources<K>(Point(0.5, 0), far_radius, 2 * CGAL_PI * far_radius / far_points);
  four.close_up = CGAL::Bbox_2(-0.35, -0.55, 1.65, 0.45);
  status |= mesh_and_report(four);

  if(argc > 2) {
    Run p30;
    p30.name = "30P-30N three-element airfoil (shared data)";
    p30.out_prefix = out_dir + "/thirty_p_thirty_n";
    p30.boundary = afm_shared_data::thirty_p_thirty_n(argv[2], far_radius, far_points);
    p30.sources = afm_paper::figure_12_sources<K>(Point(0.5, 0), far_radius, 2 * CGAL_PI * far_radius / far_points);
    p30.close_up = CGAL::Bbox_2(-0.3, -0.5, 1.5, 0.4);
    status |= mesh_and_report(p30);
  }
  return status;
}
