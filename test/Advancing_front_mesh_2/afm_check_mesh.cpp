// afm_check_mesh INPUT.poly MESH.off: runs the independent validity checker
// on a mesh written by afmesh_2, whose input segments may be split (each
// must be covered by a chain of mesh edges). Exit 0 when valid, 1 otherwise.
#include "afm_split_segments.h"
#include "afm_validity_checker.h"

#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if(argc != 3) {
    std::cerr << "usage: afm_check_mesh INPUT.poly MESH.off\n";
    return 2;
  }
  const auto in = CGAL::Advancing_front_mesh_2::IO::read_poly(argv[1]);
  afm_check::Pslg pslg;
  pslg.points = in.points;
  pslg.segments = in.segments;
  pslg.holes = in.holes;
  std::ifstream off(argv[2]);
  std::string header;
  std::size_t nv = 0, nf = 0, ne = 0;
  if(!(off >> header >> nv >> nf >> ne) || header != "OFF") {
    std::cerr << argv[2] << ": not an OFF file\n";
    return 1;
  }
  afm_check::Mesh mesh;
  mesh.vertices.resize(nv);
  for(auto& v : mesh.vertices) {
    double z;
    off >> v[0] >> v[1] >> z;
  }
  mesh.triangles.resize(nf);
  for(auto& t : mesh.triangles) {
    int three;
    off >> three >> t[0] >> t[1] >> t[2];
    if(three != 3) { std::cerr << argv[2] << ": not a triangle\n"; return 1; }
  }
  if(!off) {
    std::cerr << argv[2] << ": truncated\n";
    return 1;
  }
  const auto report = afm_check::check_mesh(afm_check::split_at_mesh_vertices(pslg, mesh), mesh);
  std::cout << report.summary() << "\n";
  return report.ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
