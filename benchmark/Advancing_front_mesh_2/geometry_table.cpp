// Meshes every test geometry once (Release, Epick, no checks inside the
// loop), validates each result with the independent checker afterwards, and
// prints a Markdown table: vertices, triangles, meshing time, radius ratio.
// With a figure directory, also writes the user manual's figures as SVG
// (convert with `rsvg-convert -w 900 X.svg -o X.png`).
//   geometry_table [SHARED_DATA_DIR [FIGURE_DIR]]
#include "afm_geometries.h"
#include "afm_shared_data.h"
#include "afm_test_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>

#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afm_test::Types<K>::CDT CDT;
typedef std::function<K::FT(const K::Point_2&)> Sizing;

std::string afm_test::shared_data_dir() { return ""; }

namespace IO = CGAL::Advancing_front_mesh_2::IO;
static std::string figure_dir;

// A zoom window for a figure: xmin, ymin, xmax, ymax, or none.
struct Figure
{
  std::string name;
  std::array<double, 4> window;
  bool zoom = false;
};

static void row(const std::string& name, const std::string& size_text,
                const IO::Poly_data& in, const Sizing& size, const Figure& fig = Figure())
{
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  auto seeds = afm_test::seeds_of<CDT>(in);
  CGAL::Advancing_front_mesher_2<CDT, Sizing> mesher(cdt, size);
  // the paper's mode, in which the manual's figures were measured (these
  // inputs' boundaries are at the size)
  mesher.set_constraint_splitting(false);
  mesher.set_seeds(seeds.begin(), seeds.end());
  mesher.refine_mesh();
  const auto& st = mesher.statistics();
  const auto q = CGAL::Advancing_front_mesh_2::mesh_quality(cdt);
  const auto report = afm_check::check_mesh(afm_test::to_pslg(in), afm_test::extract_mesh(cdt));
  if(!figure_dir.empty() && !fig.name.empty()) {
    IO::SVG_options opt;
    opt.width_px = 900;
    opt.has_window = fig.zoom;
    opt.xmin = fig.window[0]; opt.ymin = fig.window[1]; opt.xmax = fig.window[2]; opt.ymax = fig.window[3];
    std::ofstream os(figure_dir + "/" + fig.name + ".svg");
    IO::write_SVG(os, cdt, opt);
  }
  std::cout << "| " << name << " | " << size_text << " | " << st.number_of_vertices << " | " << q.number_of_triangles
            << " | " << std::fixed << std::setprecision(3) << st.meshing_time << " | " << std::setprecision(4)
            << q.mean_radius_ratio << " | " << q.min_radius_ratio << " | " << st.largest_front << " | "
            << (report.ok && st.delaunay_repair_flips == 0 ? "valid" : "INVALID: " + report.summary()) << " |\n"
            << std::defaultfloat;
}

int main(int argc, char* argv[])
{
  const std::string data = argc > 1 ? argv[1] : "";
  if(argc > 2) figure_dir = argv[2];
  auto uniform = [](double h) { return Sizing([h](const K::Point_2&) { return K::FT(h); }); };
  auto graded = [](const CGAL::Advancing_front_mesh_2::IO::Poly_data& in, double g) {
    return Sizing(afm_test::Boundary_graded_size<K>(in, g));
  };
  std::cout << "| geometry | size | vertices | triangles | time (s) | mean radius ratio | min radius ratio | largest front | checker |\n"
            << "|---|---|---|---|---|---|---|---|---|\n";
  row("square with circular hole", "h = 0.025", afm_geometry::square_with_circular_hole(1, 0.25, 0.025), uniform(0.025),
      Figure{"square_with_hole", {{0, 0, 0, 0}}, false});
  row("square with circular hole", "h = 0.01", afm_geometry::square_with_circular_hole(1, 0.25, 0.01), uniform(0.01));
  row("square with circular hole", "h = 0.002", afm_geometry::square_with_circular_hole(1, 0.25, 0.002), uniform(0.002));
  row("L-shape", "h = 0.05", afm_geometry::l_shape(0.05), uniform(0.05));
  const auto plates = afm_geometry::two_thin_plates();
  row("two thin plates (Fig. 9)", "boundary-graded, g = 0.15", plates, graded(plates, 0.15),
      Figure{"two_thin_plates", {{-0.2, -0.35, 1.2, 0.45}}, true});
  row("two thin plates (Fig. 9)", "h = 0.04", plates, uniform(0.04));
  const auto naca = afm_geometry::naca0012_far_field(100, 20, 64);
  row("NACA 0012, far field r = 20", "boundary-graded, g = 0.2", naca, graded(naca, 0.2));
  const auto four = afm_geometry::multi_element_airfoil(15, 80);
  row("four-element airfoil, far field r = 15", "boundary-graded, g = 0.2", four, graded(four, 0.2),
      Figure{"multi_element_airfoil", {{-0.35, -0.55, 1.45, 0.35}}, true});
  row("many holes (40)", "h = 0.02", afm_geometry::many_holes(40, 1), uniform(0.02));
  {
    const auto outer = afm_geometry::subdivided_polygon({{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}}, 0.1);
    const auto hole = afm_geometry::circle({{0.3, 0.3}}, 0.002, 126, false);
    row("size jump x1000 (tiny hole)", "1e-4 / 0.1", afm_geometry::polygon_with_holes({outer, hole}),
        Sizing([](const K::Point_2& p) { return K::FT(std::hypot(p.x() - 0.3, p.y() - 0.3) < 0.004 ? 1e-4 : 0.1); }));
  }
  row("nearly collinear boundary (1e-9)", "h = 0.02", afm_geometry::nearly_collinear_boundary(1e-9), uniform(0.02));
  row("square with hole offset by 1e6", "h = 0.02",
      afm_geometry::offset(afm_geometry::square_with_circular_hole(1, 0.25, 0.02), 1e6, 1e6), uniform(0.02));
  if(!data.empty()) {
    const auto p30 = afm_shared_data::thirty_p_thirty_n(data, 20, 96);
    row("30P-30N (shared data)", "boundary-graded, g = 0.2", p30, graded(p30, 0.2));
    const auto nlr = afm_shared_data::nlr7301_with_flap(data);
    row("NLR 7301 with flap (shared data)", "boundary-graded, g = 0.2", nlr, graded(nlr, 0.2));
    row("MESH2D lake (shared data)", "h = 0.1", afm_shared_data::mesh2d_jigsaw(data + "/mesh2d/lake.msh"), uniform(0.1));
    const auto isl = afm_shared_data::mesh2d_jigsaw(data + "/mesh2d/islands.msh");
    row("MESH2D islands (shared data)", "boundary-graded, g = 0.2, max 0.25", isl,
        Sizing(afm_test::Boundary_graded_size<K>(isl, 0.2, 0.25)));
    row("Triangle A.poly (shared data)", "h = 0.02", afm_shared_data::triangle_poly(data + "/triangle_drufat/A.poly"), uniform(0.02));
    row("Triangle double_hex.poly (shared data)", "h = 0.02",
        afm_shared_data::triangle_poly(data + "/triangle_drufat/double_hex.poly"), uniform(0.02));
  }
  return 0;
}
