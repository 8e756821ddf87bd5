// afmesh_2: the command-line front end of Advancing_front_mesh_2.
//
//   afmesh_2 INPUT.poly [--size H] [--sources FILE] [--grading G|off]
//            [--boundary-spacing grow|diffuse]
//            [-o OUT.off] [-o OUT.vtu] [-o OUT.svg] [-o OUT.poly] [--no-output]
//            [--smooth N] [--svg-color plain|quality] [--histogram OUT.svg]
//            [--kernel epick|epeck|exact-rational] [--stats] [--report]
//   afmesh_2 --resume FILE [--checkpoint-every K FILE] [--stats] [--report]
//   afmesh_2 --help | --version
//
// --size alone meshes with the uniform target edge length H. Otherwise the
// size field is a Poisson_sizing_field_2: the sources of FILE (one "x y h"
// per line) diffused by its Poisson solve, the boundary spacing grown from
// each boundary point at the gradation rate G (default 0.2; or diffused
// with the sources, --boundary-spacing diffuse) and, with --size, bounded
// above by H.
//
// Streaming (meshes larger than memory): --stream hands finished triangles
// to the output files while meshing, so that memory holds only the part
// near the front; --checkpoint-every K FILE also writes the mesher's state
// to FILE after every K more triangles, and --resume FILE continues such a
// run later (with the options stored in FILE), giving the same files as an
// uninterrupted run.
//
// The pieces, in afmesh_2/: options.h (the command line), resume.h
// (checkpoints and --resume), input.h (reading, the boundary, the size
// field), meshing.h (the mesher, streaming, smoothing), output.h (the mesh
// files), report.h (--report and the JSON of --stats), run.h (one run).
//
// INPUT is a .poly file, or polygons with holes in WKT (.wkt) or GeoJSON
// (.geojson, .json).
//
// Without -o, the mesh goes to INPUT.1.node/.ele/.edge beside the input, as
// Triangle writes it; --no-output writes nothing.
//
// Exit codes: 0 success; 1 invalid input (one line "afmesh_2: error:
// FILE[:LINE]: what is wrong" on stderr); 2 bad usage; 3 an output or
// checkpoint that could not be written, or an internal error.
#include "afmesh_2/options.h"
#include "afmesh_2/resume.h"
#include "afmesh_2/run.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

int main(int argc, char* argv[])
{
  using namespace afmesh_2;
  Options opt;
  try {
    opt = parse(std::vector<std::string>(argv + 1, argv + argc));
  } catch(const Usage_error& e) {
    std::cerr << program << ": " << e.what() << "\n" << "Try 'afmesh_2 --help'.\n";
    return 2;
  } catch(const Input_error& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 1;
  }
  try {
    if(opt.kernel == "epeck") return run<CGAL::Exact_predicates_exact_constructions_kernel>(opt);
    if(opt.kernel == "exact-rational") return run<CGAL::Simple_cartesian<CGAL::Exact_rational> >(opt);
    return run<CGAL::Exact_predicates_inexact_constructions_kernel>(opt);
  } catch(const Input_error& e) {
    std::cerr << program << ": error: " << e.what() << "\n";
    return 1;
  } catch(const std::invalid_argument& e) {
    std::cerr << program << ": error: " << opt.input << ": " << e.what() << "\n";
    return 1;
  } catch(const std::exception& e) {
    std::cerr << program << ": internal error: " << e.what() << "\n";
    return 3;
  }
}
