// The minimum angle bound side by side (scripts/benchmark_min_angle.sh):
//
//   min_angle_comparison IN.poly H A [--triangle PATH]
//     ours (the frontal pass at uniform size H, then
//     refine_to_minimum_angle_2 at A degrees), CGAL Mesh_2 (shape bound A,
//     size bound scaled until its triangle count is within 3% of ours) and,
//     with --triangle, Triangle 1.6 (-pq<A>Q with an area bound scaled the
//     same way; the whole process, reading and writing files included, as a
//     user runs it): triangles, mean radius ratio, share above 0.9,
//     smallest angle, triangles below A, time; every mesh checked by the
//     independent checker. One Markdown row per mesher.
//
//   min_angle_comparison --shared DIR A
//     the real geometries of ../shared/data that the tests mesh, with the
//     tests' sizes, refined at A degrees: the same figures per geometry.
//
//   min_angle_comparison --random N A
//     N random domains of the tests' generator meshed and refined at A
//     degrees: that every run ends, what is left below A, and whether each
//     such triangle has a vertex within one local size of an input vertex
//     where two input segments meet at under 60 degrees (the documented
//     exception).
#include "afm_random_pslg.h"
#include "afm_shared_data.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>
#include <CGAL/Advancing_front_mesh_2/refine_to_minimum_angle_2.h>
#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afm_test::Types<K>::CDT CDT;
namespace AFM = CGAL::Advancing_front_mesh_2;
typedef std::array<double, 2> Xy;

double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double angle_at(const Xy& o, const Xy& u, const Xy& w)
{
  const double ux = u[0] - o[0], uy = u[1] - o[1], wx = w[0] - o[0], wy = w[1] - o[1];
  return std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180 / CGAL_PI;
}

double smallest_angle(const afm_check::Mesh& m, const std::array<std::size_t, 3>& t)
{
  double a = 180;
  for(int i = 0; i < 3; ++i)
    a = (std::min)(a, angle_at(m.vertices[t[i]], m.vertices[t[(i + 1) % 3]], m.vertices[t[(i + 2) % 3]]));
  return a;
}

struct Row
{
  std::string mesher;
  std::size_t triangles = 0, below = 0;
  double mean = 0, share_above_0_9 = 0, smallest = 180, seconds = 0;
  std::string check;
};

Row measure(const std::string& mesher, const afm_check::Mesh& m, const afm_test::Poly_data& in, double bound,
            double seconds)
{
  Row r;
  r.mesher = mesher;
  r.seconds = seconds;
  r.triangles = m.triangles.size();
  double sum = 0;
  std::size_t above = 0;
  for(const auto& t : m.triangles) {
    const Xy& a = m.vertices[t[0]];
    const Xy& b = m.vertices[t[1]];
    const Xy& c = m.vertices[t[2]];
    const double la = std::hypot(b[0] - c[0], b[1] - c[1]), lb = std::hypot(a[0] - c[0], a[1] - c[1]),
                 lc = std::hypot(a[0] - b[0], a[1] - b[1]);
    const double area = std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
    const double ratio = area > 0 ? 16 * area * area / (la * lb * lc * (la + lb + lc)) : 0; // 2r/R
    sum += ratio;
    above += ratio > 0.9 ? 1 : 0;
    const double s = smallest_angle(m, t);
    r.smallest = (std::min)(r.smallest, s);
    r.below += s < bound * (1 - 1e-9) ? 1 : 0;
  }
  r.mean = r.triangles ? sum / double(r.triangles) : 0;
  r.share_above_0_9 = r.triangles ? double(above) / double(r.triangles) : 0;
  const afm_check::Report report = afm_test::check_split_mesh(in, m);
  r.check = report.ok ? "valid" : "INVALID: " + report.summary();
  return r;
}

void print(const Row& r)
{
  std::cout << "| " << r.mesher << " | " << r.triangles << " | " << std::setprecision(4) << r.mean << " | "
            << std::setprecision(3) << 100 * r.share_above_0_9 << "% | " << std::setprecision(4) << r.smallest
            << " | " << r.below << " | " << std::setprecision(3) << r.seconds << " | " << r.check << " |\n";
}

// Triangle's .node and .ele (first index as the files give it).
bool read_triangle_output(const std::string& base, afm_check::Mesh& m)
{
  std::ifstream node(base + ".node"), ele(base + ".ele");
  std::size_t n = 0, dim = 0, attributes = 0, markers = 0;
  if(!(node >> n >> dim >> attributes >> markers)) return false;
  m.vertices.assign(n, Xy{{0, 0}});
  long first = -1;
  for(std::size_t i = 0; i < n; ++i) {
    long id;
    double skip;
    node >> id >> m.vertices[i][0] >> m.vertices[i][1];
    for(std::size_t k = 0; k < attributes + markers; ++k) node >> skip;
    if(first < 0) first = id;
  }
  std::size_t nt = 0, corners = 0;
  if(!(ele >> nt >> corners >> attributes)) return false;
  m.triangles.assign(nt, {{0, 0, 0}});
  for(auto& t : m.triangles) {
    long id, a, b, c;
    double skip;
    ele >> id >> a >> b >> c;
    for(std::size_t k = 0; k < attributes; ++k) ele >> skip;
    t = {{std::size_t(a - first), std::size_t(b - first), std::size_t(c - first)}};
  }
  return bool(node) && bool(ele);
}

int compare(const std::string& path, double h, double bound, const std::string& triangle)
{
  const afm_test::Poly_data in = AFM::IO::read_poly(path);
  std::cout << "### " << path << ", h = " << h << ", minimum angle " << bound << " degrees\n\n"
            << "| mesher | triangles | mean radius ratio | share above 0.9 | smallest angle | below the bound | "
               "seconds | checker |\n|---|---|---|---|---|---|---|---|\n";
  // ours
  CDT ours;
  auto inserted = AFM::IO::insert_poly(ours, in);
  auto start = std::chrono::steady_clock::now();
  CGAL::Advancing_front_mesher_2<CDT, AFM::Uniform_sizing_field_2<K> > mesher(ours, AFM::Uniform_sizing_field_2<K>(h));
  mesher.set_seeds(inserted.hole_seeds.begin(), inserted.hole_seeds.end());
  mesher.refine_mesh();
  const double frontal = seconds_since(start);
  print(measure("ours, frontal pass only", afm_test::extract_mesh(ours), in, bound, frontal));
  const AFM::Minimum_angle_statistics st = AFM::refine_to_minimum_angle_2(ours, bound);
  const Row our_row = measure("ours, then refine_to_minimum_angle_2", afm_test::extract_mesh(ours), in, bound,
                              seconds_since(start));
  print(our_row);
  // Mesh_2 at a matched count
  const double sine = std::sin(bound * CGAL_PI / 180);
  double size_bound = h / 0.7;
  for(int round = 0; round < 6; ++round) {
    CDT m2;
    auto ins = AFM::IO::insert_poly(m2, in);
    start = std::chrono::steady_clock::now();
    CGAL::refine_Delaunay_mesh_2(m2, ins.hole_seeds.begin(), ins.hole_seeds.end(),
                                 CGAL::Delaunay_mesh_size_criteria_2<CDT>(sine * sine, size_bound), false);
    const double t = seconds_since(start);
    const afm_check::Mesh m = afm_test::extract_mesh(m2);
    const double ratio = double(m.triangles.size()) / double(our_row.triangles);
    if(std::abs(ratio - 1) < 0.03 || round == 5) {
      print(measure("CGAL Mesh_2 (size bound " + std::to_string(size_bound) + ")", m, in, bound, t));
      break;
    }
    size_bound *= std::sqrt(ratio);
  }
  // Triangle at a matched count
  if(!triangle.empty()) {
    // Triangle's -a bounds the area; its mean triangle is about 0.6 of it
    double area = 0;
    const afm_check::Mesh om = afm_test::extract_mesh(ours);
    for(const auto& t : om.triangles) {
      const Xy& a = om.vertices[t[0]];
      const Xy& b = om.vertices[t[1]];
      const Xy& c = om.vertices[t[2]];
      area += std::abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) / 2;
    }
    double max_area = 1.6 * area / double(our_row.triangles);
    for(int round = 0; round < 6; ++round) {
      std::ostringstream command;
      // areas as plain decimals: Triangle reads the e of 1e-6 as a switch
      command << triangle << " -pq" << bound << "Qa" << std::fixed << std::setprecision(12) << max_area << " "
              << path;
      start = std::chrono::steady_clock::now();
      if(std::system(command.str().c_str()) != 0) {
        std::cout << "| Triangle | failed: " << command.str() << " |\n";
        break;
      }
      const double t = seconds_since(start);
      afm_check::Mesh m;
      const std::string base = path.substr(0, path.size() - 5) + ".1";
      if(!read_triangle_output(base, m)) {
        std::cout << "| Triangle | unreadable output " << base << " |\n";
        break;
      }
      const double ratio = double(m.triangles.size()) / double(our_row.triangles);
      if(std::abs(ratio - 1) < 0.03 || round == 5) {
        std::ostringstream label;
        label << "Triangle 1.6 -pq" << bound << "Qa" << max_area << " (whole process)";
        print(measure(label.str(), m, in, bound, t));
        break;
      }
      max_area *= ratio;
    }
  }
  std::cout << "\nours: " << st.below_before << " triangles below " << bound << " after the frontal pass, "
            << st.points_inserted << " points inserted, " << st.triangles_changed << " triangles changed ("
            << std::setprecision(3) << 100.0 * double(st.triangles_changed) / double(st.triangles_after)
            << "%), " << st.below_after << " left\n\n";
  return our_row.check == "valid" ? 0 : 1;
}

// The triangles below the bound that are farther than one local size from
// every input vertex where two input segments meet at under 60 degrees.
template <class Size>
std::size_t unexplained_below(const afm_check::Mesh& m, const afm_test::Poly_data& in, const Size& size, double bound)
{
  std::map<Xy, std::vector<Xy> > neighbours;
  for(const auto& s : in.segments) {
    neighbours[in.points[s[0]]].push_back(in.points[s[1]]);
    neighbours[in.points[s[1]]].push_back(in.points[s[0]]);
  }
  std::vector<std::pair<Xy, double> > apexes; // with the local size there
  for(const auto& vn : neighbours)
    for(std::size_t i = 0; i < vn.second.size(); ++i)
      for(std::size_t j = i + 1; j < vn.second.size(); ++j)
        if(angle_at(vn.first, vn.second[i], vn.second[j]) < 60)
          apexes.emplace_back(vn.first, CGAL::to_double(size(K::Point_2(vn.first[0], vn.first[1]))));
  std::size_t unexplained = 0;
  for(const auto& t : m.triangles) {
    if(!(smallest_angle(m, t) < bound * (1 - 1e-9))) continue;
    bool near = false;
    for(const auto& a : apexes)
      for(int i = 0; i < 3; ++i)
        near = near || std::hypot(m.vertices[t[i]][0] - a.first[0], m.vertices[t[i]][1] - a.first[1]) <= a.second;
    unexplained += near ? 0 : 1;
  }
  return unexplained;
}

template <class Size>
bool shared_case(const std::string& name, const afm_test::Poly_data& in, const Size& size, double bound)
{
  CDT cdt;
  auto ins = AFM::IO::insert_poly(cdt, in);
  const auto start = std::chrono::steady_clock::now();
  CGAL::Advancing_front_mesher_2<CDT, Size> mesher(cdt, size);
  mesher.set_seeds(ins.hole_seeds.begin(), ins.hole_seeds.end());
  mesher.refine_mesh();
  const AFM::Minimum_angle_statistics st = AFM::refine_to_minimum_angle_2(cdt, bound);
  const double t = seconds_since(start);
  const afm_check::Mesh m = afm_test::extract_mesh(cdt);
  const afm_check::Report report = afm_test::check_split_mesh(in, m);
  const std::size_t unexplained = unexplained_below(m, in, size, bound);
  std::cout << "| " << name << " | " << st.triangles_after << " | " << st.below_before << " | " << st.points_inserted
            << " | " << st.triangles_changed << " (" << std::setprecision(3)
            << 100.0 * double(st.triangles_changed) / double(st.triangles_after) << "%) | " << st.below_after << " ("
            << unexplained << " far from small input angles) | " << std::setprecision(4) << st.smallest_angle
            << " | " << (st.completed ? "yes" : "NO") << " | " << std::setprecision(3) << t << " | "
            << (report.ok ? "valid" : "INVALID") << " |\n";
  return report.ok && st.completed && unexplained == 0;
}

int shared_geometries(const std::string& dir, double bound)
{
  namespace SD = afm_shared_data;
  std::cout << "| geometry | triangles | below " << bound << " after the frontal pass | points inserted | "
            << "triangles changed | left below | smallest angle | ended | seconds | checker |\n"
            << "|---|---|---|---|---|---|---|---|---|---|\n";
  bool ok = true;
  const auto p30 = SD::thirty_p_thirty_n(dir, 20, 96);
  ok = shared_case("30P-30N (graded 0.2)", p30, afm_test::Boundary_graded_size<K>(p30, 0.2), bound) && ok;
  const auto nlr = SD::nlr7301_with_flap(dir);
  ok = shared_case("NLR 7301 with flap (graded 0.2)", nlr, afm_test::Boundary_graded_size<K>(nlr, 0.2), bound) && ok;
  const auto lake = SD::mesh2d_jigsaw(dir + "/mesh2d/lake.msh");
  ok = shared_case("MESH2D lake (h = 0.1)", lake, AFM::Uniform_sizing_field_2<K>(0.1), bound) && ok;
  const auto islands = SD::mesh2d_jigsaw(dir + "/mesh2d/islands.msh");
  ok = shared_case("MESH2D islands (graded)", islands, afm_test::Boundary_graded_size<K>(islands, 0.2, 0.25), bound) &&
       ok;
  const auto a = SD::triangle_poly(dir + "/triangle_drufat/A.poly");
  ok = shared_case("Triangle's A.poly (h = 0.02)", a, AFM::Uniform_sizing_field_2<K>(0.02), bound) && ok;
  const auto hex = SD::triangle_poly(dir + "/triangle_drufat/double_hex.poly");
  ok = shared_case("Triangle's double_hex.poly (h = 0.02)", hex, AFM::Uniform_sizing_field_2<K>(0.02), bound) && ok;
  std::cout << "\n";
  return ok ? 0 : 1;
}

int random_domains(std::size_t n, double bound)
{
  std::size_t triangles = 0, below_before = 0, inserted = 0, left = 0, unexplained = 0, unfinished = 0;
  const auto start = std::chrono::steady_clock::now();
  for(std::uint64_t seed = 0; seed < n; ++seed) {
    afm_random::Generator g(seed);
    const afm_random::Domain d = g.domain();
    const double h = g.uniform(0.05, 0.15) * d.scale;
    CDT cdt;
    auto ins = AFM::IO::insert_poly(cdt, d.pslg);
    CGAL::Advancing_front_mesher_2<CDT, AFM::Uniform_sizing_field_2<K> > mesher(cdt, AFM::Uniform_sizing_field_2<K>(h));
    mesher.set_seeds(ins.hole_seeds.begin(), ins.hole_seeds.end());
    mesher.refine_mesh();
    const AFM::Minimum_angle_statistics st = AFM::refine_to_minimum_angle_2(cdt, bound);
    triangles += st.triangles_after;
    below_before += st.below_before;
    inserted += st.points_inserted;
    left += st.below_after;
    unfinished += st.completed ? 0 : 1;
    if(st.below_after == 0) continue;
    const std::size_t far = unexplained_below(afm_test::extract_mesh(cdt), d.pslg, AFM::Uniform_sizing_field_2<K>(h), bound);
    if(far != 0) std::cout << "seed " << seed << ": " << far << " triangles below " << bound << " degrees far from small input angles\n";
    unexplained += far;
  }
  std::cout << n << " random domains at " << bound << " degrees in " << seconds_since(start) << " s: " << triangles
            << " triangles, " << below_before << " below the bound after the frontal pass, " << inserted
            << " points inserted, " << left << " left below, " << unexplained
            << " of them farther than one local size from an input angle under 60 degrees, " << unfinished
            << " runs stopped at the insertion limit\n";
  return unexplained == 0 && unfinished == 0 ? 0 : 1;
}

} // namespace

std::string afm_test::shared_data_dir() { return ""; }

int main(int argc, char* argv[])
{
  const std::vector<std::string> args(argv + 1, argv + argc);
  if(args.size() == 3 && args[0] == "--random") return random_domains(std::stoul(args[1]), std::stod(args[2]));
  if(args.size() == 3 && args[0] == "--shared") return shared_geometries(args[1], std::stod(args[2]));
  if(args.size() == 3 || (args.size() == 5 && args[3] == "--triangle"))
    return compare(args[0], std::stod(args[1]), std::stod(args[2]), args.size() == 5 ? args[4] : "");
  std::cerr << "usage: min_angle_comparison IN.poly H A [--triangle PATH] | --shared DIR A | --random N A\n";
  return 2;
}
