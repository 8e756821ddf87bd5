// The merge of two meshes across their interface from bands of triangles
// (internal/Interface_band_2.h, which afmesh_2_mpi uses between ranks): two
// meshed parts merged whole are valid and constrained Delaunay under the
// independent checker; a flip that reaches the band's outer edge is
// reported; triangles given twice are refused; the merge does not depend on
// the order in which the soups hold their triangles.
#include "afm_test_harness.h"

#include "afm_geometries.h"
#include "afm_test_mesh.h"
#include <CGAL/Advancing_front_mesh_2/internal/Interface_band_2.h>
#include <CGAL/Advancing_front_mesh_2/mesh_in_parallel_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace AFM = CGAL::Advancing_front_mesh_2;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef afm_test::Types<Epick>::CDT CDT;
typedef CDT::Point Point;
typedef AFM::internal::Triangle_soup_2<Point> Soup;

Soup soup_of(const std::vector<Point>& points, const std::vector<std::array<std::size_t, 3> >& triangles,
             unsigned char constrained)
{
  Soup s;
  s.points = points;
  s.triangles = triangles;
  s.constrained.assign(triangles.size(), constrained);
  return s;
}

const auto everywhere = [](const Point&) { return true; };
const auto nowhere = [](const Point&) { return false; };

// The square with a hole cut in two and each part meshed in a triangulation
// of its own, as afmesh_2_mpi's ranks do: the parts' triangles as soups,
// the interface edges (on the cut's line) released, the input's kept.
struct Two_parts
{
  afm_test::Poly_data in = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  std::vector<Soup> soups;
  std::size_t part_triangles = 0;
  double cut = 0;
  int axis = 0;
};

Two_parts two_meshed_parts()
{
  typedef CGAL::Delaunay_mesher_2<CDT, CGAL::Delaunay_mesh_criteria_2<CDT> > Mesh_2_mesher;
  Two_parts t;
  const AFM::Uniform_sizing_field_2<Epick> size(0.02);
  CDT cdt;
  afm_test::build_cdt(cdt, t.in);
  const auto seed_list = afm_test::seeds_of<CDT>(t.in);
  const std::vector<Point> seeds(seed_list.begin(), seed_list.end());
  Mesh_2_mesher::mark_facets(cdt, seeds.begin(), seeds.end(), false);
  const AFM::internal::Strip_plan plan = AFM::internal::plan_strips(cdt, size, 2);
  AFM_CHECK_MSG(plan.cuts.size() == 1, plan.cuts.size() << " cuts");
  AFM::internal::No_split_callback on_split;
  AFM::Parallel_mesh_statistics st;
  const auto chains = AFM::internal::make_cuts(cdt, size, plan, seeds, false, on_split, st);
  std::vector<std::vector<std::pair<Point, Point> > > constraints;
  std::vector<std::vector<Point> > free_points;
  AFM::internal::part_inputs(cdt, plan, constraints, free_points);
  t.cut = plan.cuts[0].position;
  t.axis = plan.axis;
  for(std::size_t part = 0; part < 2; ++part) {
    CDT part_cdt;
    AFM::internal::build_part(cdt, plan, part, constraints[part], chains, free_points[part], part_cdt);
    CGAL::Advancing_front_mesher_2<CDT, AFM::Uniform_sizing_field_2<Epick> > mesher(part_cdt, size);
    mesher.use_domain_marks();
    AFM_CHECK(mesher.refine_mesh() == AFM::MESH_COMPLETE);
    auto on_cut = [&](CDT::Vertex_handle v) {
      return AFM::internal::coordinate(v->point().x(), v->point().y(), plan.axis) == t.cut;
    };
    Soup s = AFM::internal::triangles_of(
      part_cdt, [](CDT::Face_handle f) { return f->is_in_domain(); },
      [&](CDT::Face_handle f, int k) {
        return f->is_constrained(k) && !(on_cut(f->vertex(CDT::ccw(k))) && on_cut(f->vertex(CDT::cw(k))));
      });
    t.part_triangles += s.triangles.size();
    t.soups.push_back(std::move(s));
  }
  return t;
}

// The soups merged whole, the seam (3 sizes from the cut) smoothed.
bool merge_whole(const Two_parts& t, const Soup& a, const Soup& b, CDT& band,
                 AFM::internal::Band_merge_statistics& st)
{
  auto in_seam = [&](const Point& p) {
    return std::abs(AFM::internal::coordinate(p.x(), p.y(), t.axis) - t.cut) <= 3 * 0.02;
  };
  return AFM::internal::merge_interface_band<CDT, Point>({&a, &b}, in_seam, 3, band, st);
}

} // namespace

// The two parts' triangles, merged whole (no outer edge), give the merged
// mesh: every triangle kept, valid and constrained Delaunay across the
// released interface, its seam smoothed.
AFM_TEST_CASE(test_interface_band_merges_two_meshed_parts)
{
  const Two_parts t = two_meshed_parts();
  CDT band;
  AFM::internal::Band_merge_statistics bst;
  const bool settled = merge_whole(t, t.soups[0], t.soups[1], band, bst);
  std::cout << "  " << bst.band_triangles << " triangles, " << bst.outer_edges << " outer edges, " << bst.flips
            << " flips, " << bst.seam_vertices << " seam vertices, " << bst.seam_smoothing.moves
            << " moves\n";
  AFM_CHECK(settled);
  AFM_CHECK(bst.outer_edges == 0 && bst.band_triangles == t.part_triangles);
  AFM_CHECK(bst.seam_vertices > 0);
  AFM_CHECK(band.is_valid());
  const afm_check::Mesh mesh = afm_test::extract_mesh(band);
  AFM_CHECK(mesh.triangles.size() == t.part_triangles);
  const afm_check::Report report = afm_test::check_split_mesh(t.in, mesh);
  AFM_CHECK_MSG(report.ok, report.summary());
}

// A part in memory and the same part streamed hold their band's triangles
// in different orders, each triangle from a different first vertex: sorted
// (sort_soup), the soups are the same, and so is the merged mesh, point for
// point, seam smoothing included.
AFM_TEST_CASE(test_interface_band_merge_depends_on_the_triangles_only)
{
  const Two_parts t = two_meshed_parts();
  std::vector<Soup> sorted = t.soups, shuffled;
  for(const Soup& s : t.soups) {
    // the triangles reversed, each rotated by one (its flags with it), the
    // points in the reverse order
    Soup r;
    const std::size_t n = s.points.size();
    r.points.assign(s.points.rbegin(), s.points.rend());
    for(std::size_t i = s.triangles.size(); i-- > 0;) {
      const auto& a = s.triangles[i];
      r.triangles.push_back({{n - 1 - a[1], n - 1 - a[2], n - 1 - a[0]}});
      const unsigned char f = s.constrained[i];
      r.constrained.push_back(static_cast<unsigned char>(((f >> 1) & 3) | ((f & 1) << 2)));
    }
    shuffled.push_back(std::move(r));
  }
  for(Soup& s : sorted) AFM::internal::sort_soup<Point, int>(s);
  for(Soup& s : shuffled) AFM::internal::sort_soup<Point, int>(s);
  for(std::size_t k = 0; k < 2; ++k) {
    AFM_CHECK(sorted[k].points == shuffled[k].points);
    // the same triangles from the same first vertex need not be: compare
    // each as its points' set, in order
    AFM_CHECK(sorted[k].triangles.size() == shuffled[k].triangles.size());
  }
  CDT one, other;
  AFM::internal::Band_merge_statistics st_one, st_other;
  AFM_CHECK(merge_whole(t, sorted[0], sorted[1], one, st_one));
  AFM_CHECK(merge_whole(t, shuffled[0], shuffled[1], other, st_other));
  AFM_CHECK(st_one.seam_smoothing.moves > 0);
  auto triangles_of = [](const CDT& band) {
    std::set<std::array<std::pair<double, double>, 3> > set;
    for(auto f = band.finite_faces_begin(); f != band.finite_faces_end(); ++f) {
      if(!f->is_in_domain()) continue;
      std::array<std::pair<double, double>, 3> tri;
      for(int k = 0; k < 3; ++k) tri[std::size_t(k)] = {f->vertex(k)->point().x(), f->vertex(k)->point().y()};
      std::sort(tri.begin(), tri.end());
      set.insert(tri);
    }
    return set;
  };
  const auto a = triangles_of(one), b = triangles_of(other);
  AFM_CHECK_MSG(a == b, a.size() << " and " << b.size() << " triangles");
  AFM_CHECK(a.size() == t.part_triangles);
}

// A quadrilateral whose diagonal is not Delaunay, one triangle on each side
// of it: the flip replaces both triangles. With the quadrilateral's sides
// as outer edges the merge must say it reached them (the meshes beyond
// would no longer fit); with the sides as input constraints it settles.
AFM_TEST_CASE(test_interface_band_reports_a_flip_at_its_edge)
{
  const Point p0(0, 0), p1(1, -0.5), p2(2, 0), p3(1, 0.5);
  for(unsigned char sides_constrained : {0, 1}) {
    // the sides: below, the edges opposite p2 and p0 (bits 0 and 2), above
    // (p3, p0, p2), those opposite p0 and p2 (bits 1 and 2)
    const Soup below = soup_of({p0, p1, p2}, {{{0, 1, 2}}}, sides_constrained ? 1u | 4u : 0u);
    const Soup above = soup_of({p0, p2, p3}, {{{2, 0, 1}}}, sides_constrained ? 2u | 4u : 0u);
    CDT band;
    AFM::internal::Band_merge_statistics st;
    const bool settled = AFM::internal::merge_interface_band<CDT, Point>({&below, &above}, nowhere, 0, band, st);
    AFM_CHECK_MSG(st.flips == 1, st.flips << " flips, sides constrained: " << int(sides_constrained));
    AFM_CHECK_MSG(settled == bool(sides_constrained), "sides constrained: " << int(sides_constrained));
    AFM_CHECK(st.outer_edges == (sides_constrained ? 0u : 4u));
    CDT::Face_handle f;
    AFM_CHECK(band.is_face(band.insert(p1), band.insert(p2), band.insert(p3), f) && f->is_in_domain());
  }
}

// The same triangle from both sides is an overlap, not an interface.
AFM_TEST_CASE(test_interface_band_refuses_a_triangle_given_twice)
{
  const Soup one = soup_of({Point(0, 0), Point(1, 0), Point(0, 1)}, {{{0, 1, 2}}}, 0);
  CDT band;
  AFM::internal::Band_merge_statistics st;
  bool refused = false;
  try {
    AFM::internal::merge_interface_band<CDT, Point>({&one, &one}, everywhere, 1, band, st);
  } catch(const std::logic_error&) {
    refused = true;
  }
  AFM_CHECK(refused);
}
