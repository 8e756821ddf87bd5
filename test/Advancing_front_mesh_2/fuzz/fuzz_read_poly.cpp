// libFuzzer target: the .poly reader and insert_poly() on arbitrary bytes.
//
// Whatever the bytes, read_poly() returns or throws Poly_read_error; what it
// accepts must survive write_poly() and read back identically; and a small
// accepted graph goes through insert_poly(), which accepts it or throws
// Poly_read_error. Anything else (a crash, another exception, a sanitizer
// report, a hang) is a finding.
#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdint>
#include <sstream>
#include <string>

namespace {
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_2<K> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_requiring_constructions_tag> CDT;
namespace IO = CGAL::Advancing_front_mesh_2::IO;
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  IO::Poly_data d;
  try {
    d = IO::read_poly(in, "fuzz.poly");
  } catch(const IO::Poly_read_error&) {
    return 0;
  }
  std::ostringstream os;
  IO::write_poly(os, d);
  std::istringstream back(os.str());
  const IO::Poly_data again = IO::read_poly(back, "round-trip.poly");
  if(again.points != d.points || again.segments != d.segments || again.holes != d.holes) __builtin_trap();
  if(d.points.size() <= 256 && d.segments.size() <= 512 && d.holes.size() <= 64) {
    CDT cdt;
    try {
      IO::insert_poly(cdt, d);
    } catch(const IO::Poly_read_error&) {
    }
  }
  return 0;
}
