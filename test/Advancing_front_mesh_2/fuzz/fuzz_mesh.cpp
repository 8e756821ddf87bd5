// libFuzzer target: the mesher on small fuzzed graphs.
//
// The bytes are read as a small graph on a grid (coarse grids make
// duplicates, collinear and cocircular points common; fine ones make
// near-degenerate ones), with segments, hole seeds and a uniform size.
// insert_poly() rejects the illegal ones; every legal one must mesh
// completely, without repair flips, into a mesh that CGAL's is_valid() and
// the test suite's independent validity checker accept.
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdint>
#include <cstdio>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef afm_test::Types<K>::CDT CDT;
namespace AFM = CGAL::Advancing_front_mesh_2;

struct Bytes
{
  const std::uint8_t* p;
  std::size_t n, at = 0;
  bool more() const { return at < n; }
  std::uint8_t next() { return at < n ? p[at++] : 0; }
};

void fail(const char* what)
{
  std::fprintf(stderr, "fuzz_mesh: %s\n", what);
  __builtin_trap();
}
} // namespace

std::string afm_test::shared_data_dir() { return ""; }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Bytes b{data, size};
  const std::uint8_t mode = b.next();
  const int grid = (mode & 3) == 0 ? 8 : (mode & 3) == 1 ? 64 : (mode & 3) == 2 ? 1024 : 65536;
  const double scale = (mode & 4) ? 1e-6 : (mode & 8) ? 1e6 : 1.0;
  const double offset = (mode & 16) ? 1e6 * scale : 0.0;
  auto coordinate = [&]() {
    const int v = (grid <= 256) ? int(b.next() % grid) : int((b.next() << 8 | b.next()) % grid);
    return offset + scale * (double(v) / grid);
  };
  AFM::IO::Poly_data d;
  const int n = 3 + b.next() % 22;
  for(int i = 0; i < n && b.more(); ++i) d.points.push_back({{coordinate(), coordinate()}});
  if(d.points.size() < 3) return 0;
  const int m = b.next() % 40;
  for(int i = 0; i < m && b.more(); ++i) {
    const std::size_t u = b.next() % d.points.size(), v = b.next() % d.points.size();
    if(u != v) d.segments.push_back({{u, v}});
  }
  const int holes = b.next() % 4;
  for(int i = 0; i < holes && b.more(); ++i) d.holes.push_back({{coordinate(), coordinate()}});
  // uniform size between 1/40 and 1/4 of the grid's extent: at most a few
  // thousand triangles
  const double h = scale * (0.025 + 0.225 * (b.next() / 255.0));

  CDT cdt;
  AFM::IO::Poly_insertion<CDT> inserted;
  try {
    inserted = AFM::IO::insert_poly(cdt, d);
  } catch(const AFM::IO::Poly_read_error&) {
    return 0;
  }
  CGAL::Advancing_front_mesher_2<CDT, AFM::Uniform_sizing_field_2<K> > mesher(cdt, AFM::Uniform_sizing_field_2<K>(h));
  mesher.set_seeds(inserted.hole_seeds.begin(), inserted.hole_seeds.end());
  mesher.set_pocket_priority((mode & 32) == 0);
  if(mesher.refine_mesh() != AFM::MESH_COMPLETE) fail("meshing stopped early");
  if(mesher.statistics().delaunay_repair_flips != 0) fail("repair flips");
  if(!cdt.is_valid()) fail("CGAL's is_valid() failed");
  const afm_check::Report report = afm_test::check_split_mesh(d, afm_test::extract_mesh(cdt));
  if(!report.ok) {
    std::fprintf(stderr, "%s\n", report.summary().c_str());
    fail("the validity checker rejected the mesh");
  }
  return 0;
}
