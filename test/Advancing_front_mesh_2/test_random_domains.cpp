// Randomised tests: random polygons with holes, interior segments and free
// points (afm_random_pslg.h), random size fields, each mesh checked by the
// independent validity checker. 5,000 domains per run in 8 cases of 625, so
// that ctest spreads them over the cores.
//
// A failure names its seed. To replay one:  AFM_RANDOM_SEED=<seed>
// test_advancing_front_mesh_2 test_random_domains_0  (runs that seed only);
// AFM_RANDOM_COUNT=<n> changes the number of domains per case.
#include "afm_random_pslg.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdlib>
#include <sstream>

namespace {

// A size field in the domain's unit coordinates: uniform, a smooth wave,
// or point sources growing linearly away from them.
template <class K>
struct Random_size
{
  int kind = 0;
  double h0 = 0.1, amplitude = 0, kx = 0, ky = 0, phase = 0, gradient = 0;
  std::vector<std::array<double, 3> > sources; // x, y, h
  double scale = 1, ox = 0, oy = 0;

  typename K::FT operator()(const typename K::Point_2& p) const
  {
    const double x = (CGAL::to_double(p.x()) - ox) / scale, y = (CGAL::to_double(p.y()) - oy) / scale;
    double h = h0;
    if(kind == 1) h = h0 * (1 + amplitude * std::sin(kx * x + phase) * std::cos(ky * y));
    if(kind == 2)
      for(const auto& s : sources) h = (std::min)(h, s[2] + gradient * std::hypot(x - s[0], y - s[1]));
    return typename K::FT(h * scale);
  }

  std::string describe() const
  {
    std::ostringstream os;
    os << (kind == 0 ? "uniform" : kind == 1 ? "wave" : "sources") << " h0 " << h0;
    if(kind == 2) os << ", " << sources.size() << " sources, gradient " << gradient;
    return os.str();
  }
};

template <class K>
Random_size<K> random_size(afm_random::Generator& g, const afm_random::Domain& d)
{
  Random_size<K> s;
  s.kind = g.integer(0, 2);
  s.h0 = g.uniform(0.05, 0.15);
  s.amplitude = g.uniform(0.2, 0.8);
  s.kx = g.uniform(1, 10);
  s.ky = g.uniform(1, 10);
  s.phase = g.uniform(0, 6.28);
  s.gradient = g.uniform(0.2, 1.0);
  const int n = g.integer(1, 4);
  for(int i = 0; i < n; ++i) s.sources.push_back({{g.uniform(-0.8, 0.8), g.uniform(-0.8, 0.8), g.uniform(0.008, 0.04)}});
  s.scale = d.scale;
  s.ox = d.offset_x;
  s.oy = d.offset_y;
  return s;
}

// returns the number of triangles
template <class K>
std::size_t mesh_random_domain(std::uint64_t seed)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  afm_random::Generator g(seed);
  const afm_random::Domain d = g.domain();
  const Random_size<K> size = random_size<K>(g, d);
  const bool pockets = g.integer(0, 3) != 0;
  const bool check_front = seed % 50 == 0;
  std::ostringstream label;
  label << "seed " << seed << " (" << d.description << "; " << size.describe() << (pockets ? "" : "; no pockets")
        << ")";

  CDT cdt;
  CGAL::Advancing_front_mesh_2::IO::Poly_insertion<CDT> inserted;
  try {
    inserted = CGAL::Advancing_front_mesh_2::IO::insert_poly(cdt, d.pslg);
  } catch(const std::exception& e) {
    AFM_CHECK_MSG(false, label.str() << ": the generated domain was rejected: " << e.what());
  }
  afm_test::Mesher<CDT, Random_size<K> > mesher(cdt, size);
  mesher.set_seeds(inserted.hole_seeds.begin(), inserted.hole_seeds.end());
  mesher.set_pocket_priority(pockets);
  CGAL::Advancing_front_mesh_2::Mesh_return_code rc = CGAL::Advancing_front_mesh_2::MESH_COMPLETE;
  try {
    if(check_front) {
      mesher.init();
      std::size_t steps = 0;
      while(mesher.step_by_step_refine_mesh())
        if(++steps % 7 == 0) AFM_CHECK_MSG(mesher.is_front_valid(), label.str() << ": front invalid after step " << steps);
    } else {
      rc = mesher.refine_mesh();
    }
  } catch(const afm_test::Failure&) {
    throw;
  } catch(const std::exception& e) {
    AFM_CHECK_MSG(false, label.str() << ": meshing threw: " << e.what());
  }
  AFM_CHECK_MSG(rc == CGAL::Advancing_front_mesh_2::MESH_COMPLETE, label.str() << ": return code " << int(rc));
  AFM_CHECK_MSG(mesher.statistics().delaunay_repair_flips == 0,
                label.str() << ": " << mesher.statistics().delaunay_repair_flips << " repair flips");
  AFM_CHECK_MSG(cdt.is_valid(), label.str() << ": CGAL's is_valid() failed");
  const auto report = afm_test::check_split_mesh(d.pslg, afm_test::extract_mesh(cdt));
  AFM_CHECK_MSG(report.ok, label.str() << ": " << report.summary());
  return mesher.statistics().number_of_faces;
}

void run_random_domains(int part)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
  typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
  if(const char* one = std::getenv("AFM_RANDOM_SEED")) {
    if(part == 0) {
      const std::uint64_t seed = std::strtoull(one, nullptr, 10);
      std::cout << "  replaying seed " << seed << "\n";
      mesh_random_domain<Epick>(seed);
      mesh_random_domain<Epeck>(seed);
    }
    return;
  }
  std::uint64_t count = 625;
  if(const char* c = std::getenv("AFM_RANDOM_COUNT")) count = std::strtoull(c, nullptr, 10);
  const std::uint64_t first = 1000003ull * std::uint64_t(part + 1);
  std::size_t triangles = 0;
  for(std::uint64_t s = first; s < first + count; ++s) {
    triangles += mesh_random_domain<Epick>(s);
    // the exact-constructions kernel on every 25th domain (it is slow in debug builds)
    if(s % 25 == 0) mesh_random_domain<Epeck>(s);
  }
  std::cout << "  " << count << " random domains meshed and checked (seeds " << first << ".." << first + count - 1
            << "), " << triangles << " triangles in all\n";
}

} // namespace

AFM_TEST_CASE(test_random_domains_0) { run_random_domains(0); }
AFM_TEST_CASE(test_random_domains_1) { run_random_domains(1); }
AFM_TEST_CASE(test_random_domains_2) { run_random_domains(2); }
AFM_TEST_CASE(test_random_domains_3) { run_random_domains(3); }
AFM_TEST_CASE(test_random_domains_4) { run_random_domains(4); }
AFM_TEST_CASE(test_random_domains_5) { run_random_domains(5); }
AFM_TEST_CASE(test_random_domains_6) { run_random_domains(6); }
AFM_TEST_CASE(test_random_domains_7) { run_random_domains(7); }
