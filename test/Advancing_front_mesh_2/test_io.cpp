// Tests of the .poly reader/writer and of the mesh writers.
//
// The reader is meant to reject every damaged file with the exact line of the
// damage, so each kind of damage is planted once and the reported position is
// checked, not only the fact that something was thrown. The writers are
// checked by parsing their output back: counts, exact coordinates and
// orientation, since a writer whose output no tool reads is worthless.

#include "afm_test_harness.h"

#include "afm_geometries.h"

#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/markers_and_regions.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_WKT_polygons.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_gmsh_boundary.h>
#include <CGAL/Advancing_front_mesh_2/IO/read_poly.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>
#include <CGAL/Advancing_front_mesher_2.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <locale>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_2<K> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;
typedef CGAL::Delaunay_mesh_size_criteria_2<CDT> Criteria;
typedef CGAL::Delaunay_mesher_2<CDT, Criteria> Mesher;

namespace AFM = CGAL::Advancing_front_mesh_2;
namespace afm_io = CGAL::Advancing_front_mesh_2::IO;

// Files are created in the working directory (the build tree under ctest),
// with a prefix that no other test uses.
std::string temp_path(const std::string& name) { return "afm_test_io_" + name; }

void write_text(const std::string& path, const std::string& content)
{
  std::ofstream os(path.c_str(), std::ios::binary);
  os << content;
  AFM_CHECK_MSG(os.good(), "cannot create " << path);
}

std::string read_text(const std::string& path)
{
  std::ifstream in(path.c_str(), std::ios::binary);
  AFM_CHECK_MSG(in.good(), "cannot open " << path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

bool file_exists(const std::string& path)
{
  std::ifstream in(path.c_str(), std::ios::binary);
  return in.good();
}

afm_io::Poly_data parse(const std::string& content, const std::string& name = "test.poly")
{
  std::istringstream in(content);
  return afm_io::read_poly(in, name);
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

// ---------------------------------------------------------------------------
// Reader: valid input

AFM_TEST_CASE(test_io_read_one_based_with_comments_attributes_markers)
{
  const std::string poly =
    "# A square with a square hole, as Triangle writes it.\r\n"
    "8 2 1 1   # vertices, dimension, attributes, markers\r\n"
    "\r\n"
    "1 0 0 10.5 1\r\n"
    "2 4 0 10.5 1\n"
    "   3\t4 4 10.5 1   # tabs and trailing comment\n"
    "4 0 4 10.5 1\n"
    "# a full-line comment between vertex lines\n"
    "5 1 1 0 2\n"
    "6 3 1 0 2\n"
    "7 3 3 0 2\n"
    "8 1e0 3.0 -0 2\n"
    "8 1\n"
    "1 1 2 1\n2 2 3 1\n3 3 4 1\n4 4 1 1\n"
    "5 5 6 2\n6 6 7 2\n7 7 8 2\n8 8 5 2\n"
    "1\n"
    "1 2 2\n"
    "\n# trailing comment\n";
  const afm_io::Poly_data d = parse(poly);
  AFM_CHECK(d.points.size() == 8);
  AFM_CHECK(d.points[2][0] == 4 && d.points[2][1] == 4);
  AFM_CHECK(d.points[7][0] == 1 && d.points[7][1] == 3);
  AFM_CHECK(d.segments.size() == 8);
  AFM_CHECK(d.segments[0][0] == 0 && d.segments[0][1] == 1);
  AFM_CHECK(d.segments[7][0] == 7 && d.segments[7][1] == 4);
  AFM_CHECK(d.holes.size() == 1);
  AFM_CHECK(d.holes[0][0] == 2 && d.holes[0][1] == 2);
  // the markers are kept, one per item, in file order
  AFM_CHECK(d.point_markers.size() == 8 && d.point_markers[0] == 1 && d.point_markers[7] == 2);
  AFM_CHECK(d.segment_markers.size() == 8 && d.segment_markers[3] == 1 && d.segment_markers[4] == 2);
  AFM_CHECK(d.regions.empty());
}

AFM_TEST_CASE(test_io_read_zero_based)
{
  const std::string poly =
    "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n"
    "3 0\n0 0 1\n1 1 2\n2 2 0\n"
    "0\n";
  const afm_io::Poly_data d = parse(poly);
  AFM_CHECK(d.points.size() == 3);
  AFM_CHECK(d.segments.size() == 3);
  AFM_CHECK(d.segments[0][0] == 0 && d.segments[0][1] == 1);
  AFM_CHECK(d.segments[2][0] == 2 && d.segments[2][1] == 0);
  AFM_CHECK(d.holes.empty());
}

AFM_TEST_CASE(test_io_read_regions)
{
  const std::string poly =
    "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n"
    "3 0\n1 1 2\n2 2 3\n3 3 1\n"
    "0\n"
    "3\n"
    "1 0.2 0.2 7 0.01\n"
    "2 0.1 0.1 8   # no area: as in Triangle, the attribute is the area too\n"
    "3 0.3 0.1 -2.5 -1\n";
  const afm_io::Poly_data d = parse(poly);
  AFM_CHECK(d.points.size() == 3);
  AFM_CHECK(d.segments.size() == 3);
  AFM_CHECK(d.holes.empty());
  AFM_CHECK(d.point_markers.empty() && d.segment_markers.empty());
  AFM_CHECK(d.regions.size() == 3);
  AFM_CHECK(d.regions[0].seed[0] == 0.2 && d.regions[0].seed[1] == 0.2);
  AFM_CHECK(d.regions[0].attribute == 7 && d.regions[0].max_area == 0.01);
  AFM_CHECK(d.regions[1].attribute == 8 && d.regions[1].max_area == 8);
  AFM_CHECK(d.regions[2].attribute == -2.5 && d.regions[2].max_area == -1);
  AFM_CHECK(d.origin.region_lines.size() == 3 && d.origin.region_lines[2] == 13);

  // An empty regions section is just as valid.
  const afm_io::Poly_data e = parse("1 2 0 0\n1 0 0\n0 0\n0\n0\n");
  AFM_CHECK(e.points.size() == 1 && e.segments.empty());
}

AFM_TEST_CASE(test_io_read_vertices_from_node_file)
{
  const std::string base = temp_path("nodes");
  write_text(base + ".node", "# vertices live here\n3 2 0 1\n0 0 0 1\n1 1 0 1\n2 0 1 1\n");
  write_text(base + ".poly", "0 2 0 1\n3 0\n1 0 1\n2 1 2\n3 2 0\n0\n");
  const afm_io::Poly_data d = afm_io::read_poly(base + ".poly");
  AFM_CHECK(d.points.size() == 3);
  AFM_CHECK(d.points[1][0] == 1 && d.points[1][1] == 0);
  // The .node file numbers from 0, so the segment endpoints do too.
  AFM_CHECK(d.segments.size() == 3 && d.segments[2][0] == 2 && d.segments[2][1] == 0);

  // An error in the .node file names that file and its own line.
  write_text(base + ".node", "3 2 0 1\n0 0 0 1\n1 1 zero 1\n2 0 1 1\n");
  bool thrown = false;
  try {
    afm_io::read_poly(base + ".poly");
  } catch(const afm_io::Poly_read_error& e) {
    thrown = true;
    AFM_CHECK_MSG(e.file() == base + ".node", e.what());
    AFM_CHECK_MSG(e.line() == 3, e.what());
    AFM_CHECK_MSG(std::string(e.what()).find(base + ".node:3: 'zero' is not a number") == 0,
                  e.what());
  }
  AFM_CHECK(thrown);

  // Trailing content after the vertices of a .node file is rejected too.
  write_text(base + ".node", "1 2 0 0\n1 0 0\n1 0 0\n");
  write_text(base + ".poly", "0 2 0 0\n0 0\n0\n");
  thrown = false;
  try {
    afm_io::read_poly(base + ".poly");
  } catch(const afm_io::Poly_read_error& e) {
    thrown = true;
    AFM_CHECK_MSG(e.file() == base + ".node" && e.line() == 3, e.what());
  }
  AFM_CHECK(thrown);

  std::remove((base + ".node").c_str());
  thrown = false;
  try {
    afm_io::read_poly(base + ".poly");
  } catch(const afm_io::Poly_read_error& e) {
    thrown = true;
    AFM_CHECK_MSG(e.file() == base + ".node" && e.line() == 0, e.what());
    AFM_CHECK_MSG(e.problem().find("cannot open file") == 0, e.what());
  }
  AFM_CHECK(thrown);
  std::remove((base + ".poly").c_str());
}

AFM_TEST_CASE(test_io_read_missing_file)
{
  bool thrown = false;
  try {
    afm_io::read_poly(temp_path("does_not_exist.poly"));
  } catch(const afm_io::Poly_read_error& e) {
    thrown = true;
    AFM_CHECK(e.line() == 0);
    AFM_CHECK_MSG(std::string(e.what()) ==
                  temp_path("does_not_exist.poly") + ": cannot open file", e.what());
  }
  AFM_CHECK(thrown);
}

// ---------------------------------------------------------------------------
// Reader: every kind of damage, with its line

struct Bad_case
{
  const char* name;
  std::string content;
  std::size_t line;
  const char* problem; // expected part of the message
};

// A valid triangle; cases below damage one part of it.
const std::string tri_vertices = "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n";
const std::string tri_segments = "3 0\n1 1 2\n2 2 3\n3 3 1\n";

AFM_TEST_CASE(test_io_read_rejects_malformed_input)
{
  const std::vector<Bad_case> cases = {
    {"empty", "", 0, "holds no data"},
    {"only comments", "# nothing\n\n#\n", 3, "holds no data"},
    {"truncated vertices",
     "12 2 0 0\n1 0 0\n2 1 0\n3 0 1\n4 1 1\n5 2 2\n6 3 3\n7 4 4\n",
     8, "expected 12 vertices, file ends after 7"},
    {"not a number", "3 2 0 0\n1 0 0\n2 1.0x 0\n3 0 1\n", 3, "'1.0x' is not a number"},
    {"nan coordinate", "3 2 0 0\n1 0 0\n2 nan 0\n3 0 1\n", 3, "'nan' is not finite"},
    {"inf coordinate", "3 2 0 0\n1 0 0\n2 1 -inf\n3 0 1\n", 3, "'-inf' is not finite"},
    {"overflowing coordinate", "3 2 0 0\n1 0 0\n2 1 0\n3 1e999 1\n", 4, "not finite"},
    {"nan attribute", "1 2 1 0\n1 0 0 nan\n0 0\n0\n", 2, "attribute 'nan' is not finite"},
    {"negative count", "-3 2 0 0\n", 1, "vertex count -3 is negative"},
    {"absurd count", "99999999999 2 0 0\n", 1, "is too large"},
    {"count overflowing long long", "99999999999999999999999 2 0 0\n", 1,
     "vertex count '99999999999999999999999' is out of range"},
    {"fractional count", "3.0 2 0 0\n", 1, "'3.0' is not an integer"},
    {"dimension 3", "3 3 0 0\n", 1, "dimension must be 2, got 3"},
    {"marker count 2", "3 2 0 2\n", 1, "must be 0 or 1, got 2"},
    {"negative attributes", "3 2 -1 0\n", 1, "attribute count -1 is negative"},
    {"short header", "3 2 0\n", 1, "has 3 values, expected 4"},
    {"vertex line too long", "3 2 0 0\n1 0 0\n2 1 0 5\n3 0 1\n", 3, "has 4 values, expected 3"},
    {"vertex line too short", "3 2 1 1\n1 0 0 0 0\n2 1 0 0\n", 3, "has 4 values, expected 5"},
    {"first id not 0 or 1", "3 2 0 0\n2 0 0\n3 1 0\n4 0 1\n", 2, "first vertex id must be 0 or 1, got 2"},
    {"ids out of order", "3 2 0 0\n1 0 0\n3 1 0\n2 0 1\n", 3, "vertex id 3 is out of order, expected 2"},
    {"fractional id", "3 2 0 0\n1 0 0\n2.5 1 0\n3 0 1\n", 3, "'2.5' is not an integer"},
    {"non-integer marker", "1 2 0 1\n1 0 0 b\n", 2, "'b' is not a number"},
    {"missing segment header", tri_vertices, 4, "expected the segment header"},
    {"truncated segments", tri_vertices + "3 0\n1 1 2\n", 6, "expected 3 segments, file ends after 1"},
    {"segment endpoint out of range", tri_vertices + "3 0\n1 1 2\n2 2 4\n3 3 1\n", 7,
     "segment endpoint 4 is out of range (vertex ids are 1..3)"},
    {"segment endpoint 0 in 1-based file", tri_vertices + "3 0\n1 1 2\n2 2 3\n3 3 0\n", 8,
     "segment endpoint 0 is out of range"},
    {"segment to itself", tri_vertices + "3 0\n1 1 2\n2 2 2\n3 3 1\n", 7,
     "segment joins vertex 2 to itself"},
    {"segment marker missing", tri_vertices + "3 1\n1 1 2 5\n2 2 3\n", 7, "has 3 values, expected 4"},
    {"segment ids out of order", tri_vertices + "3 0\n1 1 2\n1 2 3\n3 3 1\n", 7,
     "segment id 1 is out of order, expected 2"},
    {"missing hole header", tri_vertices + tri_segments, 8, "expected the hole header"},
    {"truncated holes", tri_vertices + tri_segments + "2\n1 0.1 0.1\n", 10,
     "expected 2 holes, file ends after 1"},
    {"hole not finite", tri_vertices + tri_segments + "1\n1 0.1 inf\n", 10, "'inf' is not finite"},
    {"extra hole", tri_vertices + tri_segments + "1\n1 0.1 0.1\n2 0.2 0.2\n", 11,
     "expected the optional region header"},
    {"truncated regions", tri_vertices + tri_segments + "0\n2\n1 0.1 0.1 1\n", 11,
     "expected 2 regions, file ends after 1"},
    {"region without attribute", tri_vertices + tri_segments + "0\n1\n1 0.1 0.1\n", 11,
     "has 3 values, expected 4 or 5"},
    {"garbage after regions", tri_vertices + tri_segments + "0\n0\nend\n", 11,
     "unexpected content after the last section"},
    {"binary garbage", std::string("\x7f" "ELF\x01\x02\x00\xff\xfe", 9), 1, "has 1 value, expected 4"},
    {"control bytes as a number", "\x01\x02 2 0 0\n", 1, "'\\x01\\x02' is not a number"},
    {"NUL inside a number", std::string("3 2 0 0\n1 0 0\n2 1\0" "5 0\n", 22), 3, "'1\\x005' is not a number"},
  };

  for(const Bad_case& c : cases) {
    bool thrown = false;
    try {
      parse(c.content, "file.poly");
    } catch(const afm_io::Poly_read_error& e) {
      thrown = true;
      const std::string what = e.what();
      const std::string where = c.line == 0 ? std::string("file.poly: ")
                                            : "file.poly:" + std::to_string(c.line) + ": ";
      AFM_CHECK_MSG(what.compare(0, where.size(), where) == 0,
                    c.name << ": got \"" << what << "\", expected it to start with " << where);
      AFM_CHECK_MSG(e.line() == c.line, c.name << ": " << what);
      AFM_CHECK_MSG(e.file() == "file.poly", c.name << ": " << what);
      AFM_CHECK_MSG(what.find(c.problem) != std::string::npos,
                    c.name << ": got \"" << what << "\", expected \"" << c.problem << "\"");
      AFM_CHECK_MSG(what == where + e.problem(), c.name << ": " << what);
    }
    AFM_CHECK_MSG(thrown, c.name << ": accepted");
  }
}

AFM_TEST_CASE(test_io_read_rejects_overlong_line)
{
  // A newline-free blob must be refused without being buffered whole.
  const std::string blob = "3 2 0 0\n" + std::string(3u << 20, '7');
  bool thrown = false;
  try {
    parse(blob, "file.poly");
  } catch(const afm_io::Poly_read_error& e) {
    thrown = true;
    AFM_CHECK_MSG(e.line() == 2 && e.problem().find("longer than") != std::string::npos,
                  e.what());
  }
  AFM_CHECK(thrown);

  // A long comment, however, is harmless.
  const afm_io::Poly_data d =
    parse("#" + std::string(3u << 20, 'x') + "\n1 2 0 0\n1 0 0\n0 0\n0\n");
  AFM_CHECK(d.points.size() == 1);
}

// ---------------------------------------------------------------------------
// Writer: round trip

// Digit grouping a writer must not apply to its numbers.
struct Grouping_numpunct : std::numpunct<char>
{
  char do_decimal_point() const override { return ','; }
  char do_thousands_sep() const override { return '.'; }
  std::string do_grouping() const override { return "\3"; }
};

AFM_TEST_CASE(test_io_poly_round_trip_is_exact)
{
  afm_io::Poly_data d;
  const double values[] = {0.1, 1.0 / 3.0, -2.5e-300, 123456789.123456789, -0.0,
                           std::nextafter(1.0, 2.0), 4.9406564584124654e-324,
                           1.7976931348623157e308, 1e22, -7};
  const std::size_t nv = sizeof(values) / sizeof(values[0]);
  for(std::size_t i = 0; i < nv; ++i)
    d.points.push_back({{values[i], values[(i + 3) % nv]}});
  for(std::size_t i = 0; i < nv; ++i)
    d.segments.push_back({{i, (i + 1) % nv}});
  d.holes.push_back({{0.7, -1.0 / 7.0}});

  std::ostringstream os;
  os.imbue(std::locale(std::locale::classic(), new Grouping_numpunct));
  os.precision(3);
  afm_io::write_poly(os, d);
  AFM_CHECK_MSG(os.precision() == 3, "stream state not restored");
  const std::string text = os.str();
  AFM_CHECK_MSG(text.compare(0, 9, "10 2 0 0\n") == 0, text.substr(0, 40));

  const afm_io::Poly_data r = parse(text);
  AFM_CHECK(r.points.size() == d.points.size());
  for(std::size_t i = 0; i < nv; ++i)
    AFM_CHECK_MSG(same_bits(r.points[i][0], d.points[i][0]) &&
                  same_bits(r.points[i][1], d.points[i][1]), "point " << i);
  AFM_CHECK(r.segments == d.segments);
  AFM_CHECK(r.holes.size() == 1 && same_bits(r.holes[0][0], 0.7) &&
            same_bits(r.holes[0][1], -1.0 / 7.0));

  // Through a file as well.
  const std::string path = temp_path("round_trip.poly");
  afm_io::write_poly(path, d);
  const afm_io::Poly_data f = afm_io::read_poly(path);
  AFM_CHECK(f.segments == d.segments && f.points.size() == nv);
  for(std::size_t i = 0; i < nv; ++i)
    AFM_CHECK(same_bits(f.points[i][0], d.points[i][0]));
  std::remove(path.c_str());
}

AFM_TEST_CASE(test_io_write_poly_rejects_invalid_data)
{
  afm_io::Poly_data d;
  d.points = {{{0, 0}}, {{1, 0}}};
  d.segments = {{{0, 2}}};
  std::ostringstream os;
  bool thrown = false;
  try { afm_io::write_poly(os, d); } catch(const std::invalid_argument&) { thrown = true; }
  AFM_CHECK(thrown && os.str().empty());

  d.segments = {{{1, 1}}};
  thrown = false;
  try { afm_io::write_poly(os, d); } catch(const std::invalid_argument&) { thrown = true; }
  AFM_CHECK(thrown);

  d.segments = {{{0, 1}}};
  d.points[1][1] = std::numeric_limits<double>::quiet_NaN();
  thrown = false;
  try { afm_io::write_poly(os, d); } catch(const std::invalid_argument&) { thrown = true; }
  AFM_CHECK(thrown);

  thrown = false;
  d.points[1][1] = 0;
  try { afm_io::write_poly("/nonexistent-dir-afm/x.poly", d); }
  catch(const std::runtime_error& e) {
    thrown = std::string(e.what()) == "cannot write /nonexistent-dir-afm/x.poly";
  }
  AFM_CHECK(thrown);
}

// ---------------------------------------------------------------------------
// Mesh writers

// Square [0,4]^2 around the hole [1,3]^2; without refinement the annulus has
// exactly 8 vertices and 8 triangles.
void build_square_with_hole(CDT& cdt, bool refine)
{
  const CDT::Point outer[4] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};
  const CDT::Point inner[4] = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
  for(int i = 0; i < 4; ++i) {
    cdt.insert_constraint(outer[i], outer[(i + 1) % 4]);
    cdt.insert_constraint(inner[i], inner[(i + 1) % 4]);
  }
  std::vector<CDT::Point> seeds = {CDT::Point(2, 2)};
  if(refine)
    CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), Criteria(0.125, 0.3));
  else
    Mesher::mark_facets(cdt, seeds.begin(), seeds.end());
}

std::size_t in_domain_faces(const CDT& cdt)
{
  std::size_t n = 0;
  for(CDT::Finite_faces_iterator f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->is_in_domain()) ++n;
  return n;
}

std::set<std::pair<double, double> > cdt_points(const CDT& cdt)
{
  std::set<std::pair<double, double> > s;
  for(CDT::Finite_vertices_iterator v = cdt.finite_vertices_begin();
      v != cdt.finite_vertices_end(); ++v)
    s.insert(std::make_pair(v->point().x(), v->point().y()));
  return s;
}

AFM_TEST_CASE(test_io_write_off)
{
  CDT cdt;
  build_square_with_hole(cdt, false);
  AFM_CHECK(in_domain_faces(cdt) == 8);

  std::ostringstream os;
  afm_io::write_OFF(os, cdt);
  std::istringstream in(os.str());
  std::string magic;
  std::size_t nv = 0, nf = 0, ne = 1;
  in >> magic >> nv >> nf >> ne;
  AFM_CHECK(magic == "OFF" && nv == 8 && nf == 8 && ne == 0);
  std::vector<std::array<double, 2> > p(nv);
  for(std::size_t i = 0; i < nv; ++i) {
    double z = 1;
    in >> p[i][0] >> p[i][1] >> z;
    AFM_CHECK(z == 0);
  }
  for(std::size_t i = 0; i < nf; ++i) {
    std::size_t three = 0, a = nv, b = nv, c = nv;
    in >> three >> a >> b >> c;
    AFM_CHECK(three == 3 && a < nv && b < nv && c < nv);
    const double orient = (p[b][0] - p[a][0]) * (p[c][1] - p[a][1]) -
                          (p[b][1] - p[a][1]) * (p[c][0] - p[a][0]);
    AFM_CHECK_MSG(orient > 0, "face " << i << " is not counter-clockwise");
  }
  AFM_CHECK(in.good());
  std::string rest;
  in >> rest;
  AFM_CHECK(rest.empty());

  // Exact coordinates on a refined mesh whose points are not short decimals.
  CDT fine;
  build_square_with_hole(fine, true);
  std::ostringstream fos;
  afm_io::write_OFF(fos, fine);
  std::istringstream fin(fos.str());
  fin >> magic >> nv >> nf >> ne;
  AFM_CHECK(nf == in_domain_faces(fine) && nf > 8);
  const std::set<std::pair<double, double> > all = cdt_points(fine);
  for(std::size_t i = 0; i < nv; ++i) {
    std::string xs, ys, zs;
    fin >> xs >> ys >> zs;
    const double x = std::strtod(xs.c_str(), nullptr), y = std::strtod(ys.c_str(), nullptr);
    AFM_CHECK_MSG(all.count(std::make_pair(x, y)) == 1, xs << " " << ys);
  }

  // Two writes are identical: the numbering does not depend on addresses.
  std::ostringstream again;
  afm_io::write_OFF(again, fine);
  AFM_CHECK(again.str() == fos.str());

  // write_OFF() numbers the vertices in 32 bits below 2^32 vertices and in
  // 64 above: the wide writer gives the same file.
  std::ostringstream wide;
  afm_io::internal::mesh_write_OFF_lean<std::uint64_t>(wide, fine);
  AFM_CHECK(wide.str() == fos.str());

  // It walks the faces twice instead of copying them into the writers'
  // shared view: its file is the one the view gives (the numbering .node/.ele,
  // .msh and .vtu use), byte for byte.
  afm_io::internal::Mesh_domain_view<CDT> view;
  afm_io::internal::mesh_collect_domain(fine, view);
  std::ostringstream from_view;
  {
    afm_io::internal::Text_output out(from_view);
    out.put("OFF\n").put_uint(view.points.size()).put(' ').put_uint(view.triangles.size()).put(" 0\n");
    for(const auto& q : view.points) out.put_double(q[0]).put(' ').put_double(q[1]).put(" 0\n");
    for(const auto& t : view.triangles)
      out.put("3 ").put_uint(t[0]).put(' ').put_uint(t[1]).put(' ').put_uint(t[2]).put('\n');
    out.flush();
  }
  AFM_CHECK(view.triangles.size() == nf && from_view.str() == fos.str());
}

AFM_TEST_CASE(test_io_write_node_ele)
{
  CDT cdt;
  build_square_with_hole(cdt, true);
  const std::size_t nf = in_domain_faces(cdt);

  const std::string base = temp_path("mesh");
  afm_io::write_triangle_node_ele(base, cdt);
  std::istringstream node(read_text(base + ".node"));
  std::istringstream ele(read_text(base + ".ele"));
  std::size_t nv = 0, dim = 0, na = 1, nm = 1;
  node >> nv >> dim >> na >> nm;
  AFM_CHECK(dim == 2 && na == 0 && nm == 0 && nv == cdt.number_of_vertices());
  const std::set<std::pair<double, double> > all = cdt_points(cdt);
  for(std::size_t i = 1; i <= nv; ++i) {
    std::size_t id = 0;
    std::string xs, ys;
    node >> id >> xs >> ys;
    AFM_CHECK(id == i);
    AFM_CHECK(all.count(std::make_pair(std::strtod(xs.c_str(), nullptr),
                                       std::strtod(ys.c_str(), nullptr))) == 1);
  }
  std::size_t ne = 0, corners = 0, attributes = 1;
  ele >> ne >> corners >> attributes;
  AFM_CHECK(ne == nf && corners == 3 && attributes == 0);
  for(std::size_t i = 1; i <= ne; ++i) {
    std::size_t id = 0, a = 0, b = 0, c = 0;
    ele >> id >> a >> b >> c;
    AFM_CHECK(id == i && a >= 1 && a <= nv && b >= 1 && b <= nv && c >= 1 && c <= nv);
  }
  AFM_CHECK(!ele.fail());

  // The stream version writes the same content.
  std::ostringstream node_os, ele_os;
  afm_io::write_triangle_node_ele(node_os, ele_os, cdt);
  AFM_CHECK(node_os.str() == read_text(base + ".node"));
  AFM_CHECK(ele_os.str() == read_text(base + ".ele"));
  std::remove((base + ".node").c_str());
  std::remove((base + ".ele").c_str());
}

AFM_TEST_CASE(test_io_write_gmsh_msh)
{
  CDT cdt;
  build_square_with_hole(cdt, false);
  std::ostringstream os;
  afm_io::write_gmsh_msh(os, cdt);
  std::istringstream in(os.str());
  std::string line;
  std::vector<std::string> lines;
  while(std::getline(in, line))
    lines.push_back(line);
  // 3 format lines, 4 entity lines, 4 + 8 + 8 node lines, 4 + 8 element lines.
  AFM_CHECK_MSG(lines.size() == 39, lines.size());
  AFM_CHECK(lines[0] == "$MeshFormat" && lines[1] == "4.1 0 8" && lines[2] == "$EndMeshFormat");
  AFM_CHECK(lines[3] == "$Entities" && lines[4] == "0 0 1 0");
  AFM_CHECK_MSG(lines[5] == "1 0 0 0 4 4 0 0 0", lines[5]);
  AFM_CHECK(lines[6] == "$EndEntities" && lines[7] == "$Nodes");
  AFM_CHECK(lines[8] == "1 8 1 8" && lines[9] == "2 1 0 8");
  for(int i = 0; i < 8; ++i)
    AFM_CHECK(lines[10 + i] == std::to_string(i + 1));
  AFM_CHECK(lines[26] == "$EndNodes" && lines[27] == "$Elements");
  AFM_CHECK(lines[28] == "1 8 1 8" && lines[29] == "2 1 2 8");
  for(int i = 0; i < 8; ++i) {
    std::istringstream el(lines[30 + i]);
    int tag = 0, a = 0, b = 0, c = 0;
    el >> tag >> a >> b >> c;
    AFM_CHECK(tag == i + 1 && a >= 1 && a <= 8 && b >= 1 && b <= 8 && c >= 1 && c <= 8 && el);
  }
  AFM_CHECK(lines[38] == "$EndElements");
}

// Markers and regions through every writer, on the tagged input inserted
// (its in-domain faces stand for a mesh): what each file holds is parsed
// back and compared with the geometry, not with the tags object.
AFM_TEST_CASE(test_io_write_markers_and_regions)
{
  typedef AFM::Markers_and_regions_2<CDT> Tags;
  const afm_io::Poly_data in = afm_geometry::tagged_regions(0.05);
  CDT cdt;
  const auto inserted = afm_io::insert_poly(cdt, in);
  Tags tags = afm_io::markers_and_regions(in, inserted);
  AFM_CHECK(tags.has_markers() && tags.has_regions() && tags.has_area_limits());
  bool thrown = false;
  try {
    tags.region(cdt.finite_faces_begin());
  } catch(const std::logic_error&) {
    thrown = true;
  }
  AFM_CHECK_MSG(thrown, "region() before mark_regions() did not throw");
  tags.mark_regions(cdt);

  std::ostringstream node_os, ele_os, edge_os;
  afm_io::write_triangle_node_ele(node_os, ele_os, edge_os, cdt, tags);
  std::istringstream node(node_os.str()), ele(ele_os.str()), edge(edge_os.str());
  std::size_t nv = 0, dim = 0, na = 0, nm = 0;
  node >> nv >> dim >> na >> nm;
  AFM_CHECK(nv == in.points.size() && dim == 2 && na == 0 && nm == 1);
  std::vector<std::array<double, 2> > pts(nv);
  std::vector<int> pmark(nv);
  for(std::size_t i = 0; i < nv; ++i) {
    std::size_t id = 0;
    node >> id >> pts[i][0] >> pts[i][1] >> pmark[i];
    AFM_CHECK(id == i + 1);
  }
  std::size_t ns = 0, em = 0;
  edge >> ns >> em;
  AFM_CHECK(ns == in.segments.size() && em == 1);
  auto on_circle = [](const std::array<double, 2>& p) { return std::abs(std::hypot(p[0] - 1.5, p[1] - 0.5) - 0.2) < 1e-9; };
  std::vector<int> smallest_marker(nv, 0);
  for(std::size_t i = 0; i < ns; ++i) {
    std::size_t id = 0, a = 0, b = 0;
    int k = 0;
    edge >> id >> a >> b >> k;
    const auto& p = pts[a - 1];
    const auto& q = pts[b - 1];
    const int expected = (p[1] == 0 && q[1] == 0)   ? 1
                         : (p[0] == 2 && q[0] == 2) ? 2
                         : (p[1] == 1 && q[1] == 1) ? 3
                         : (p[0] == 0 && q[0] == 0) ? 4
                         : (p[0] == 1 && q[0] == 1) ? 5
                         : on_circle(p) && on_circle(q) ? 6 : 7;
    AFM_CHECK_MSG(k == expected, "segment " << id << ": marker " << k << ", expected " << expected);
    for(std::size_t v : {a - 1, b - 1})
      if(smallest_marker[v] == 0 || k < smallest_marker[v]) smallest_marker[v] = k;
  }
  // vertices: the corners' own marker 9, else that of the first segment (in
  // file order, here the smallest marker) at them
  for(std::size_t i = 0; i < nv; ++i) {
    const bool corner = (pts[i][0] == 0 || pts[i][0] == 2) && (pts[i][1] == 0 || pts[i][1] == 1);
    AFM_CHECK_MSG(pmark[i] == (corner ? 9 : smallest_marker[i]), "vertex " << i + 1 << ": marker " << pmark[i]);
  }
  std::size_t nt = 0, per = 0, ea = 0;
  ele >> nt >> per >> ea;
  AFM_CHECK(per == 3 && ea == 1 && nt > 100);
  std::map<double, std::size_t> per_attribute;
  for(std::size_t t = 0; t < nt; ++t) {
    std::size_t id = 0, a = 0, b = 0, c = 0;
    double attribute = 0;
    ele >> id >> a >> b >> c >> attribute;
    // the inclusion is convex: its triangles have their corners on its circle
    const double cx = (pts[a - 1][0] + pts[b - 1][0] + pts[c - 1][0]) / 3;
    const double expected = cx < 1 ? 1 : (on_circle(pts[a - 1]) && on_circle(pts[b - 1]) && on_circle(pts[c - 1]) ? 3 : 2);
    AFM_CHECK_MSG(attribute == expected, "triangle " << id << ": attribute " << attribute << ", expected " << expected);
    ++per_attribute[attribute];
  }
  AFM_CHECK(per_attribute.size() == 3 && ele.good() && node.good() && edge.good());

  // Gmsh: a physical group per marker and per region, lines then triangles
  std::ostringstream msh;
  afm_io::write_gmsh_msh(msh, cdt, tags);
  const std::string m = msh.str();
  AFM_CHECK(m.find("$PhysicalNames\n10\n1 1 \"marker_1\"\n") != std::string::npos);
  AFM_CHECK(m.find("1 7 \"marker_7\"\n2 1 \"region_1\"\n2 2 \"region_2\"\n2 3 \"region_3\"\n") != std::string::npos);
  AFM_CHECK(m.find("$Entities\n0 7 3 0\n") != std::string::npos);
  const std::string elements = "$Elements\n10 " + std::to_string(ns + nt) + " 1 " + std::to_string(ns + nt) + "\n";
  AFM_CHECK_MSG(m.find(elements) != std::string::npos, elements);
  AFM_CHECK(m.find("2 3 2 " + std::to_string(per_attribute[3]) + "\n") != std::string::npos);

  // VTU: the segments as lines after the triangles, the tags as data
  std::ostringstream vtu;
  afm_io::write_mesh_VTU(vtu, cdt, tags);
  const std::string v = vtu.str();
  AFM_CHECK(v.find("NumberOfPoints=\"" + std::to_string(nv) + "\" NumberOfCells=\"" + std::to_string(nt + ns) + "\"") !=
            std::string::npos);
  AFM_CHECK(v.find("<PointData Scalars=\"marker\">") != std::string::npos);
  AFM_CHECK(v.find("<DataArray type=\"Float64\" Name=\"region\"") != std::string::npos);

  // the boundary .poly reads back with the same markers and regions, and
  // bounds the same domain
  std::ostringstream poly;
  afm_io::write_boundary_poly(poly, cdt, tags);
  const afm_io::Poly_data back = parse(poly.str());
  AFM_CHECK(back.points.size() == nv && back.segments.size() == ns);
  AFM_CHECK(back.point_markers.size() == nv && back.segment_markers.size() == ns);
  AFM_CHECK(back.regions.size() == 3 && back.regions[0].attribute == 1 && back.regions[0].max_area == 2e-4);
  AFM_CHECK(back.holes.size() == 1 && back.holes[0][0] > 0.4 && back.holes[0][0] < 0.6 && back.holes[0][1] > 0.4 &&
            back.holes[0][1] < 0.6);
  CDT again;
  afm_io::insert_poly(again, back);
  std::size_t faces = 0;
  for(auto f = again.finite_faces_begin(); f != again.finite_faces_end(); ++f) faces += f->is_in_domain() ? 1 : 0;
  AFM_CHECK_MSG(faces == nt, faces << " faces in the domain of the boundary .poly, " << nt << " before");

  // through write_mesh: .node also writes .edge; without tags, no markers
  const std::string base = temp_path("tagged");
  afm_io::write_mesh(base + ".node", cdt, tags);
  AFM_CHECK(read_text(base + ".edge") == edge_os.str() && read_text(base + ".node") == node_os.str());
  afm_io::write_mesh(base + ".node", cdt);
  const std::string untagged_header = std::to_string(nv) + " 2 0 0\n";
  AFM_CHECK(read_text(base + ".node").compare(0, untagged_header.size(), untagged_header) == 0);
  for(const char* ext : {".node", ".ele", ".edge"}) std::remove((base + ext).c_str());
}

// Triangle's rules for markers that were not given: 1 on the boundary of
// the domain, 0 inside; given markers win; a later region seed in the same
// region wins; seeds outside the domain mark nothing.
AFM_TEST_CASE(test_io_markers_and_regions_rules)
{
  typedef AFM::Markers_and_regions_2<CDT> Tags;
  // a square cut in two by an interior segment, no markers in the file
  const afm_io::Poly_data in = parse("6 2 0 0\n1 0 0\n2 1 0\n3 2 0\n4 2 1\n5 1 1\n6 0 1\n"
                                     "7 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n7 2 5\n0\n");
  CDT cdt;
  const auto inserted = afm_io::insert_poly(cdt, in);
  Tags tags = afm_io::markers_and_regions(in, inserted);
  AFM_CHECK(!tags.has_markers() && !tags.has_regions());
  auto marker_of_edge = [&](std::size_t a, std::size_t b) {
    CDT::Face_handle f;
    int i = 0;
    AFM_CHECK(cdt.is_edge(inserted.vertices[a], inserted.vertices[b], f, i));
    return tags.edge_marker(cdt, f, i);
  };
  AFM_CHECK(marker_of_edge(0, 1) == 1 && marker_of_edge(1, 4) == 0);
  AFM_CHECK(tags.vertex_marker(cdt, inserted.vertices[1]) == 1);
  tags.set_constraint_marker(inserted.vertices[4], inserted.vertices[1], 5); // the interior one, reversed
  tags.set_constraint_marker(inserted.vertices[0], inserted.vertices[1], 3);
  AFM_CHECK(marker_of_edge(1, 4) == 5 && marker_of_edge(0, 1) == 3);
  // vertex 2 (index 1): the bottom's marker, given later, loses to the interior one given first
  AFM_CHECK(tags.vertex_marker(cdt, inserted.vertices[1]) == 5);
  tags.set_vertex_marker(inserted.vertices[1], 8);
  AFM_CHECK(tags.vertex_marker(cdt, inserted.vertices[1]) == 8);
  AFM_CHECK(tags.vertex_marker(cdt, inserted.vertices[0]) == 3 && tags.vertex_marker(cdt, inserted.vertices[2]) == 1);

  tags.add_region(K::Point_2(0.5, 0.5), 1, -1);
  tags.add_region(K::Point_2(0.2, 0.7), 4, 0.5); // the same region: wins
  tags.add_region(K::Point_2(5, 5), 9, 1);       // outside: marks nothing
  tags.mark_regions(cdt);
  std::size_t left = 0, right = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const double cx = CGAL::to_double((f->vertex(0)->point().x() + f->vertex(1)->point().x() +
                                       f->vertex(2)->point().x()) / 3);
    if(cx < 1) {
      AFM_CHECK(tags.region(f) == 1 && tags.region_attribute(f) == 4);
      ++left;
    } else {
      AFM_CHECK(tags.region(f) == Tags::no_region && tags.region_attribute(f) == 0);
      ++right;
    }
  }
  AFM_CHECK(left == 2 && right == 2);
}

// Polygons from WKT: the rings become closed chains, each hole gets a seed
// outside the islands it holds, and bad lines are named.
AFM_TEST_CASE(test_io_read_WKT_polygons)
{
  std::istringstream in("# a square with a hole holding an island\n\n"
                        "POLYGON((0 0,4 0,4 4,0 4,0 0),(1 1,1 3,3 3,3 1,1 1))\n"
                        "MULTIPOLYGON(((1.5 1.5,2.5 1.5,2.5 2.5,1.5 2.5,1.5 1.5)),((5 0,6 0,6 1,5 0)))\n");
  const afm_io::Poly_data d = afm_io::read_WKT_polygons(in, "w.wkt");
  AFM_CHECK(d.points.size() == 15 && d.segments.size() == 15);
  AFM_CHECK(d.origin.segment_lines.size() == 15 && d.origin.segment_lines[0] == 3 && d.origin.segment_lines[14] == 4);
  AFM_CHECK_MSG(d.holes.size() == 1, d.holes.size());
  const double hx = d.holes[0][0], hy = d.holes[0][1];
  AFM_CHECK_MSG(hx > 1 && hx < 3 && hy > 1 && hy < 3 && !(hx >= 1.5 && hx <= 2.5 && hy >= 1.5 && hy <= 2.5),
                hx << " " << hy);
  CDT cdt;
  afm_io::insert_poly(cdt, d);
  double area = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->is_in_domain()) area += CGAL::to_double(cdt.triangle(f).area());
  AFM_CHECK_MSG(area == 16 - 4 + 1 + 0.5, area);

  const std::vector<std::pair<std::string, std::string> > bad = {
    {"POINT(1 1)\n", "w.wkt:1: expected a WKT POLYGON or MULTIPOLYGON, found 'POINT'"},
    {"\nPOLYGON((0 0,1 0,1 1)\n", "w.wkt:2: not a valid WKT polygon"},
    {"POLYGON((0 0,1 0,1 0,0 0))\n", "w.wkt:1: polygon 1: ring 1 has fewer than 3 distinct points"},
    {"# nothing\n", "w.wkt: no POLYGON or MULTIPOLYGON in the file"}};
  for(const auto& b : bad) {
    std::istringstream bin(b.first);
    std::string message;
    try {
      afm_io::read_WKT_polygons(bin, "w.wkt");
    } catch(const afm_io::Poly_read_error& e) {
      message = e.what();
    }
    AFM_CHECK_MSG(message.compare(0, b.second.size(), b.second) == 0, b.first << ": " << message);
  }
}

AFM_TEST_CASE(test_io_write_svg)
{
  CDT cdt;
  build_square_with_hole(cdt, true);
  afm_io::SVG_options options;
  options.title = "square <with> \"hole\" & more";
  std::ostringstream os;
  afm_io::write_SVG(os, cdt, options);
  const std::string svg = os.str();
  AFM_CHECK(svg.compare(0, 4, "<svg") == 0);
  AFM_CHECK(svg.size() > 8 && svg.compare(svg.size() - 7, 7, "</svg>\n") == 0);
  AFM_CHECK(svg.find("<title>square &lt;with&gt; &quot;hole&quot; &amp; more</title>") !=
            std::string::npos);
  // One path per layer: fill, triangle edges, constrained edges.
  std::size_t paths = 0;
  for(std::size_t p = svg.find("<path"); p != std::string::npos; p = svg.find("<path", p + 1))
    ++paths;
  AFM_CHECK_MSG(paths == 3, paths);
  AFM_CHECK(svg.find("<polygon") == std::string::npos);
  AFM_CHECK(svg.find("width=\"1200\"") != std::string::npos);
  AFM_CHECK(svg.find("nan") == std::string::npos && svg.find("inf") == std::string::npos);

  // A window keeps the picture valid and drops what lies outside it.
  afm_io::SVG_options zoom;
  zoom.has_window = true;
  zoom.xmin = 0; zoom.ymin = 0; zoom.xmax = 0.5; zoom.ymax = 0.5;
  std::ostringstream zs;
  afm_io::write_SVG(zs, cdt, zoom);
  const std::string z = zs.str();
  AFM_CHECK(z.compare(0, 4, "<svg") == 0 && z.compare(z.size() - 7, 7, "</svg>\n") == 0);
  AFM_CHECK(z.size() < svg.size());

  // A tiny window far from the mesh: only the header and footer remain.
  zoom.xmin = 100; zoom.xmax = 100.001; zoom.ymin = -50; zoom.ymax = -49.999;
  std::ostringstream empty_os;
  afm_io::write_SVG(empty_os, cdt, zoom);
  AFM_CHECK(empty_os.str().find("<path") == std::string::npos);

  bool thrown = false;
  zoom.xmax = zoom.xmin;
  try { std::ostringstream s; afm_io::write_SVG(s, cdt, zoom); }
  catch(const std::invalid_argument&) { thrown = true; }
  AFM_CHECK(thrown);

  // An empty triangulation still gives a picture.
  CDT none;
  std::ostringstream ns;
  afm_io::write_SVG(ns, none);
  AFM_CHECK(ns.str().compare(0, 4, "<svg") == 0);
}

AFM_TEST_CASE(test_io_writers_accept_triangulation_plus)
{
  typedef CGAL::Constrained_triangulation_plus_2<CDT> CDT_plus;
  CDT_plus cdt;
  const CDT::Point square[4] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
  for(int i = 0; i < 4; ++i)
    cdt.insert_constraint(square[i], square[(i + 1) % 4]);
  std::vector<CDT::Point> no_seeds;
  CGAL::Delaunay_mesher_2<CDT_plus, CGAL::Delaunay_mesh_size_criteria_2<CDT_plus> >::mark_facets(
    cdt, no_seeds.begin(), no_seeds.end());

  std::ostringstream off;
  off.precision(2);
  afm_io::write_OFF(off, cdt);
  AFM_CHECK(off.str().compare(0, 10, "OFF\n4 2 0\n") == 0);
  AFM_CHECK_MSG(off.precision() == 2, "stream state not restored");
  std::ostringstream svg;
  afm_io::write_SVG(svg, cdt);
  // The four sides are constrained: the black layer is there.
  AFM_CHECK(svg.str().find("stroke=\"#000000\"") != std::string::npos);
}

AFM_TEST_CASE(test_io_write_mesh_by_extension)
{
  CDT cdt;
  build_square_with_hole(cdt, true);
  const std::size_t nf = in_domain_faces(cdt);

  afm_io::write_mesh(temp_path("out.off"), cdt);
  AFM_CHECK(read_text(temp_path("out.off")).compare(0, 4, "OFF\n") == 0);

  afm_io::write_mesh(temp_path("out.VTU"), cdt);
  const std::string vtu = read_text(temp_path("out.VTU"));
  AFM_CHECK(vtu.find("<VTKFile") != std::string::npos);
  // Well-formed XML to the end, the arrays binary by default (raw appended)
  AFM_CHECK(vtu.size() > 12 && vtu.compare(vtu.size() - 11, 11, "</VTKFile>\n") == 0);
  AFM_CHECK(vtu.find("<AppendedData encoding=\"raw\">\n_") != std::string::npos);
  AFM_CHECK(vtu.find("format=\"ascii\"") == std::string::npos);
  afm_io::write_mesh(temp_path("out_ascii.vtu"), cdt, CGAL::parameters::use_binary_mode(false));
  const std::string ascii = read_text(temp_path("out_ascii.vtu"));
  AFM_CHECK(ascii.find("AppendedData") == std::string::npos && ascii.find("format=\"ascii\"") != std::string::npos);
  AFM_CHECK(ascii.compare(ascii.size() - 11, 11, "</VTKFile>\n") == 0);
  // The triangles only, and only the vertices they use (the streamed VTU
  // holds the same); the segments come as line cells with the markers.
  AFM_CHECK(vtu.find("NumberOfPoints=\"" + std::to_string(cdt.number_of_vertices()) + "\" NumberOfCells=\"" +
                     std::to_string(nf) + "\"") != std::string::npos);

  afm_io::write_mesh(temp_path("out.ele"), cdt);
  AFM_CHECK(file_exists(temp_path("out.node")) && file_exists(temp_path("out.ele")));

  afm_io::write_mesh(temp_path("out.msh"), cdt);
  AFM_CHECK(read_text(temp_path("out.msh")).compare(0, 20, "$MeshFormat\n4.1 0 8\n") == 0);

  afm_io::write_mesh(temp_path("out.svg"), cdt);
  AFM_CHECK(read_text(temp_path("out.svg")).compare(0, 4, "<svg") == 0);

  bool thrown = false;
  try { afm_io::write_mesh(temp_path("out.stl"), cdt); }
  catch(const std::invalid_argument&) { thrown = true; }
  AFM_CHECK(thrown && !file_exists(temp_path("out.stl")));

  thrown = false;
  try { afm_io::write_mesh("/nonexistent-dir-afm/out.off", cdt); }
  catch(const std::runtime_error& e) {
    thrown = std::string(e.what()) == "cannot write /nonexistent-dir-afm/out.off";
  }
  AFM_CHECK(thrown);

  for(const char* ext : {"off", "VTU", "node", "ele", "msh", "svg"})
    std::remove(temp_path(std::string("out.") + ext).c_str());
}

} // namespace

// ---------------------------------------------------------------------------
// insert_poly(): geometric problems named by file, line and the file's ids

namespace {

struct Expected_problem
{
  const char* name;
  std::string content;
  std::size_t line;
  const char* problem; // the start of problem()
};

} // namespace

AFM_TEST_CASE(test_io_insert_poly_rejects_bad_geometry)
{
  const std::string square = "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n";
  const std::string sides = "1 1 2\n2 2 3\n3 3 4\n4 4 1\n";
  const std::vector<Expected_problem> cases = {
    {"zero length", "5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 0 0\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 1\n0\n", 12,
     "segment 5 has zero length: its end points vertex 5 (line 6) and vertex 1 (line 2) are at the same position"},
    {"crossing", square + "2 0\n1 1 3\n2 2 4\n0\n", 8, "segment 2 crosses segment 1 (line 7)"},
    {"crossing, 0-based", "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n6 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 0 2\n5 1 3\n0\n", 12,
     "segment 5 crosses segment 4 (line 11)"},
    {"overlap", "6 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 0.2 0\n6 0.8 0\n5 0\n" + sides + "5 5 6\n0\n", 13,
     "segment 5 overlaps segment 1 (line 9) along a piece of line"},
    {"overlap from a shared end", "5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 0.5 0\n5 0\n" + sides + "5 1 5\n0\n", 12,
     "segment 5 overlaps segment 1 (line 8)"},
    {"overlap, one inside the other", "6 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 -1 0\n6 2 0\n5 0\n" + sides +
     "5 5 6\n0\n", 13, "segment 5 overlaps segment 1 (line 9)"},
    {"hole on a segment", square + "4 0\n" + sides + "1\n1 0.5 0\n", 12, "hole 1 lies on segment 1 (line 7)"},
    {"hole on a vertex", square + "4 0\n" + sides + "1\n1 1 1\n", 12, "hole 1 lies on vertex 3 (line 4)"},
    {"hole outside", square + "4 0\n" + sides + "2\n1 0.5 0.5\n2 3 3\n", 13,
     "hole 2 lies outside every closed boundary"},
    {"region on a segment", square + "4 0\n" + sides + "0\n1\n1 0.5 0 1\n", 13,
     "region 1 lies on segment 1 (line 7): a region seed must lie inside its region"},
    {"region on a vertex", square + "4 0\n" + sides + "0\n2\n1 0.5 0.5 1\n2 0 1 2 0.1\n", 14,
     "region 2 lies on vertex 4 (line 5)"},
    {"region outside", square + "4 0\n" + sides + "0\n1\n1 2 2 1\n", 13,
     "region 1 lies outside the domain to mesh (in a hole or outside every closed boundary)"},
    {"region in a hole", "8 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1\n6 2 1\n7 2 2\n8 1 2\n8 0\n" + sides +
     "5 5 6\n6 6 7\n7 7 8\n8 8 5\n1\n1 1.5 1.5\n1\n0 1.2 1.5 3\n", 22,
     "region 0 lies outside the domain to mesh"},
    {"open boundary", square + "3 0\n1 1 2\n2 2 3\n3 3 4\n0\n", 2,
     "the boundary is open at vertex 1: 1 segment ends there (segment 1 (line 7))"},
    {"dangling segment outside", "6 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 2 2\n6 3 2\n5 0\n" + sides + "5 5 6\n0\n", 6,
     "the boundary is open at vertex 5: 1 segment ends there (segment 5 (line 13))"},
    {"three segments at a vertex outside", "8 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 2 2\n6 3 2\n7 2 3\n8 3 3\n7 0\n" +
     sides + "5 5 6\n6 5 7\n7 5 8\n0\n", 6, "the boundary is open at vertex 5: 3 segments end there"},
    {"nothing left", square + "4 0\n" + sides + "1\n1 0.5 0.5\n", 0, "nothing to mesh"},
    // an open polyline whose ends touch two closed triangles (its end points
    // have 3 segments, beside a region): the square it was meant to close
    // leaks away
    {"open polyline between two regions",
     "8 2 0 0\n1 0 0\n2 -1 0\n3 -1 0.3\n4 0 1\n5 -1 1\n6 -1 0.7\n7 1 0\n8 1 1\n9 0\n1 1 2\n2 2 3\n3 3 1\n"
     "4 4 5\n5 5 6\n6 6 4\n7 1 7\n8 7 8\n9 8 4\n0\n",
     17, "segment 7 borders no region to mesh"},
    {"no segments", square + "0 0\n0\n", 0, "nothing to mesh"},
    {"collinear points", "3 2 0 0\n1 0 0\n2 1 0\n3 2 0\n0 0\n0\n", 0, "nothing to mesh"},
  };
  for(const Expected_problem& c : cases) {
    const afm_io::Poly_data data = parse(c.content, "bad.poly");
    CDT cdt;
    bool thrown = false;
    try {
      afm_io::insert_poly(cdt, data);
    } catch(const afm_io::Poly_read_error& e) {
      thrown = true;
      AFM_CHECK_MSG(e.file() == "bad.poly", c.name << ": " << e.what());
      AFM_CHECK_MSG(e.line() == c.line, c.name << ": " << e.what());
      AFM_CHECK_MSG(e.problem().compare(0, std::strlen(c.problem), c.problem) == 0, c.name << ": " << e.what());
      AFM_CHECK_MSG(std::string(e.what()).find('\n') == std::string::npos, c.name << ": " << e.what());
    }
    AFM_CHECK_MSG(thrown, c.name << ": accepted");
  }

  // segments crossing exactly at an input point: split there, accepted
  {
    const afm_io::Poly_data x = parse("9 2 0 0\n1 -1 -1\n2 3 -1\n3 3 3\n4 -1 3\n5 0 0\n6 2 2\n7 0 2\n8 2 0\n9 1 1\n"
                                      "6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 7 8\n0\n", "x.poly");
    CDT cdt;
    const auto r = afm_io::insert_poly(cdt, x);
    AFM_CHECK_MSG(r.points_on_segments == 1, r.points_on_segments);
  }

  // data built in code: out-of-range indices are an error, not undefined
  {
    afm_io::Poly_data bad;
    bad.points = {{{0, 0}}, {{1, 0}}, {{1, 1}}};
    bad.segments = {{{0, 1}}, {{1, 5}}};
    CDT cdt;
    try {
      afm_io::insert_poly(cdt, bad);
      AFM_CHECK_MSG(false, "an out-of-range index was accepted");
    } catch(const afm_io::Poly_read_error& e) {
      AFM_CHECK_MSG(std::string(e.what()) == "PSLG: segment 1 refers to point index 5, out of range (there are 3 points)",
                    e.what());
    }
  }

  // data built in code: named by 0-based index, without lines
  afm_io::Poly_data code;
  code.points = {{{0, 0}}, {{1, 0}}, {{1, 1}}, {{0, 1}}};
  code.segments = {{{0, 2}}, {{1, 3}}};
  CDT cdt;
  try {
    afm_io::insert_poly(cdt, code);
    AFM_CHECK_MSG(false, "crossing segments built in code were accepted");
  } catch(const afm_io::Poly_read_error& e) {
    AFM_CHECK_MSG(std::string(e.what()) == "PSLG: segment 1 crosses segment 0", e.what());
  }
}

AFM_TEST_CASE(test_io_insert_poly_repairs)
{
  // vertex 5 repeats vertex 2 and is used by a segment, segment 5 repeats
  // segment 1 reversed, vertex 6 lies inside segment 1, and the dangling
  // segment 6 inside the square is an interior constraint (legal)
  const std::string content = "8 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 1 0\n6 0.5 0\n7 0.3 0.3\n8 0.6 0.4\n"
                              "6 0\n1 1 2\n2 5 3\n3 3 4\n4 4 1\n5 2 1\n6 7 8\n0\n";
  const afm_io::Poly_data data = parse(content, "repaired.poly");
  CDT cdt;
  const auto r = afm_io::insert_poly(cdt, data);
  AFM_CHECK_MSG(r.merged_points == 1, r.merged_points);
  AFM_CHECK_MSG(r.duplicate_segments == 1, r.duplicate_segments);
  AFM_CHECK_MSG(r.points_on_segments == 1, r.points_on_segments);
  AFM_CHECK(r.vertices.size() == 8 && r.vertices[4] == r.vertices[1]);
  AFM_CHECK(cdt.number_of_vertices() == 7);
  // the bottom side is split at vertex 6: two constrained edges
  std::size_t constrained = 0;
  for(const auto& e : cdt.constrained_edges()) {
    (void)e;
    ++constrained;
  }
  AFM_CHECK_MSG(constrained == 6, constrained);
  std::size_t in_domain = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) in_domain += f->is_in_domain();
  AFM_CHECK(in_domain == cdt.number_of_faces());
}

// ---------------------------------------------------------------------------
// Gmsh .msh boundaries: the layouts Gmsh 4.x writes for a 1D mesh (checked
// against files written by its Python API, gmsh.model.mesh.generate(1), in
// MSH 4.1 and 2.2), typed here anew; every damage named by file and line.

namespace {

afm_io::Poly_data parse_msh(const std::string& content, const std::string& name = "b.msh")
{
  std::istringstream in(content);
  return afm_io::read_gmsh_boundary(in, name);
}

// A square [0,1]^2 around the hole [0.4,0.6]^2 as Gmsh 4.1 writes its 1D
// mesh: a point entity per corner, a curve per side (outer sides in the
// physical group 3 "outer", hole sides in 7 "hole"), the surface; nodes and
// elements in one block per entity, the corners as point elements, the
// outer sides split at their middle nodes 9 to 12.
const std::string msh41_square_with_hole =
  "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
  "$PhysicalNames\n2\n1 3 \"outer\"\n1 7 \"hole\"\n$EndPhysicalNames\n"
  "$Entities\n8 8 1 0\n"
  "1 0 0 0 0 \n2 1 0 0 0 \n3 1 1 0 0 \n4 0 1 0 0 \n"
  "5 0.4 0.4 0 0 \n6 0.6 0.4 0 0 \n7 0.6 0.6 0 0 \n8 0.4 0.6 0 0 \n"
  "1 0 0 0 1 0 0 1 3 2 1 -2 \n2 1 0 0 1 1 0 1 3 2 2 -3 \n"
  "3 0 1 0 1 1 0 1 3 2 3 -4 \n4 0 0 0 0 1 0 1 3 2 4 -1 \n"
  "5 0.4 0.4 0 0.6 0.4 0 1 7 2 5 -6 \n6 0.6 0.4 0 0.6 0.6 0 1 7 2 6 -7 \n"
  "7 0.4 0.6 0 0.6 0.6 0 1 7 2 7 -8 \n8 0.4 0.4 0 0.4 0.6 0 1 7 2 8 -5 \n"
  "1 0 0 0 1 1 0 0 8 1 2 3 4 -8 -7 -6 -5 \n"
  "$EndEntities\n"
  "$Nodes\n13 12 1 12\n"
  "0 1 0 1\n1\n0 0 0\n0 2 0 1\n2\n1 0 0\n0 3 0 1\n3\n1 1 0\n0 4 0 1\n4\n0 1 0\n"
  "0 5 0 1\n5\n0.4 0.4 0\n0 6 0 1\n6\n0.6 0.4 0\n0 7 0 1\n7\n0.6 0.6 0\n0 8 0 1\n8\n0.4 0.6 0\n"
  "1 1 0 1\n9\n0.5 0 0\n1 2 0 1\n10\n1 0.5 0\n1 3 0 1\n11\n0.5 1 0\n1 4 0 1\n12\n0 0.5 0\n"
  "2 1 0 0\n"
  "$EndNodes\n"
  "$Elements\n16 20 1 20\n"
  "0 1 15 1\n1 1 \n0 2 15 1\n2 2 \n0 3 15 1\n3 3 \n0 4 15 1\n4 4 \n"
  "0 5 15 1\n5 5 \n0 6 15 1\n6 6 \n0 7 15 1\n7 7 \n0 8 15 1\n8 8 \n"
  "1 1 1 2\n9 1 9 \n10 9 2 \n1 2 1 2\n11 2 10 \n12 10 3 \n"
  "1 3 1 2\n13 3 11 \n14 11 4 \n1 4 1 2\n15 4 12 \n16 12 1 \n"
  "1 5 1 1\n17 5 6 \n1 6 1 1\n18 6 7 \n1 7 1 1\n19 7 8 \n1 8 1 1\n20 8 5 \n"
  "$EndElements\n";

// The same in MSH 2.2: nodes `tag x y z`, elements `tag type 2 physical
// elementary nodes`, only the lines of the physical groups.
const std::string msh22_square_with_hole =
  "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
  "$PhysicalNames\n2\n1 3 \"outer\"\n1 7 \"hole\"\n$EndPhysicalNames\n"
  "$Nodes\n12\n"
  "1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0.4 0.4 0\n6 0.6 0.4 0\n7 0.6 0.6 0\n8 0.4 0.6 0\n"
  "9 0.5 0 0\n10 1 0.5 0\n11 0.5 1 0\n12 0 0.5 0\n"
  "$EndNodes\n"
  "$Elements\n12\n"
  "1 1 2 3 1 1 9\n2 1 2 3 1 9 2\n3 1 2 3 2 2 10\n4 1 2 3 2 10 3\n"
  "5 1 2 3 3 3 11\n6 1 2 3 3 11 4\n7 1 2 3 4 4 12\n8 1 2 3 4 12 1\n"
  "9 1 2 7 5 5 6\n10 1 2 7 6 6 7\n11 1 2 7 7 7 8\n12 1 2 7 8 8 5\n"
  "$EndElements\n";

// The segments as sorted pairs of end points, with their markers.
typedef std::pair<std::array<double, 2>, std::array<double, 2> > Msh_test_segment;

std::map<Msh_test_segment, int> segments_with_markers(const afm_io::Poly_data& d)
{
  std::map<Msh_test_segment, int> s;
  for(std::size_t i = 0; i < d.segments.size(); ++i) {
    std::array<double, 2> a = d.points[d.segments[i][0]], b = d.points[d.segments[i][1]];
    if(b < a) std::swap(a, b);
    s[Msh_test_segment(a, b)] = d.segment_markers.empty() ? 0 : d.segment_markers[i];
  }
  return s;
}

double domain_area(const afm_io::Poly_data& d)
{
  CDT cdt;
  afm_io::insert_poly(cdt, d);
  double area = 0;
  for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if(f->is_in_domain()) area += CGAL::to_double(cdt.triangle(f).area());
  return area;
}

void check_square_with_hole(const afm_io::Poly_data& d, const std::string& what)
{
  AFM_CHECK_MSG(d.points.size() == 12 && d.segments.size() == 12, what << ": " << d.points.size() << " points, "
                                                                      << d.segments.size() << " segments");
  AFM_CHECK_MSG(d.segment_markers.size() == 12 && d.point_markers.empty(), what);
  const std::map<Msh_test_segment, int> s = segments_with_markers(d);
  AFM_CHECK_MSG(s.size() == 12, what);
  for(const auto& seg : s) {
    const bool outer = seg.first.first[0] == 0 || seg.first.first[0] == 1 || seg.first.first[1] == 0 ||
                       seg.first.first[1] == 1 || seg.first.second[0] == 1 || seg.first.second[1] == 1;
    AFM_CHECK_MSG(seg.second == (outer ? 3 : 7), what << ": marker " << seg.second);
  }
  // the hole is found by nesting: one seed, inside it
  AFM_CHECK_MSG(d.holes.size() == 1, what << ": " << d.holes.size() << " holes");
  const double hx = d.holes[0][0], hy = d.holes[0][1];
  AFM_CHECK_MSG(hx > 0.4 && hx < 0.6 && hy > 0.4 && hy < 0.6, what << ": hole at " << hx << " " << hy);
  AFM_CHECK_MSG(std::abs(domain_area(d) - 0.96) < 1e-12, what << ": area " << domain_area(d));
  // where each item was read, by its tag
  AFM_CHECK(d.origin.file == "b.msh" && d.origin.point_file == "b.msh");
  AFM_CHECK(d.origin.point_lines.size() == 12 && d.origin.point_ids.size() == 12);
  AFM_CHECK(d.origin.segment_lines.size() == 12 && d.origin.segment_ids.size() == 12);
}

std::size_t line_of(const std::string& text, const std::string& line)
{
  std::istringstream in(text);
  std::string l;
  for(std::size_t n = 1; std::getline(in, l); ++n)
    if(l == line) return n;
  return 0;
}

} // namespace

AFM_TEST_CASE(test_io_read_gmsh_boundary_41)
{
  const afm_io::Poly_data d = parse_msh(msh41_square_with_hole);
  check_square_with_hole(d, "MSH 4.1");
  // points in the order of $Nodes; the corner tags 1..8, then the middles
  AFM_CHECK(d.points[0][0] == 0 && d.points[0][1] == 0 && d.points[8][0] == 0.5 && d.points[8][1] == 0);
  AFM_CHECK(d.origin.point_ids[11] == 12 && d.origin.point_lines[0] == line_of(msh41_square_with_hole, "0 0 0"));
  AFM_CHECK(d.origin.segment_ids[0] == 9 && d.origin.segment_lines[0] == line_of(msh41_square_with_hole, "9 1 9 "));
  AFM_CHECK(d.origin.segment_ids[11] == 20 && d.origin.segment_lines[11] == line_of(msh41_square_with_hole, "20 8 5 "));
  AFM_CHECK(d.origin.ignored_elements == 0);

  // Windows line ends read the same, with the same lines
  std::string crlf;
  for(char c : msh41_square_with_hole) {
    if(c == '\n') crlf += '\r';
    crlf += c;
  }
  const afm_io::Poly_data w = parse_msh(crlf);
  AFM_CHECK(w.points == d.points && w.segments == d.segments && w.origin.segment_lines == d.origin.segment_lines);

  // from a file, and a missing file
  const std::string path = temp_path("square.msh");
  write_text(path, msh41_square_with_hole);
  AFM_CHECK(afm_io::read_gmsh_boundary(path).segments == d.segments);
  std::remove(path.c_str());
  std::string message;
  try {
    afm_io::read_gmsh_boundary(path);
  } catch(const afm_io::Poly_read_error& e) {
    message = e.what();
  }
  AFM_CHECK_MSG(message == path + ": cannot open file", message);
}

AFM_TEST_CASE(test_io_read_gmsh_boundary_22)
{
  const afm_io::Poly_data d = parse_msh(msh22_square_with_hole);
  check_square_with_hole(d, "MSH 2.2");
  AFM_CHECK(segments_with_markers(d) == segments_with_markers(parse_msh(msh41_square_with_hole)));
  AFM_CHECK(d.origin.segment_ids[8] == 9 && d.origin.segment_lines[8] == line_of(msh22_square_with_hole, "9 1 2 7 5 5 6"));
  AFM_CHECK(d.origin.point_lines[11] == line_of(msh22_square_with_hole, "12 0 0.5 0"));

  // without physical groups (Gmsh then writes the physical tag 0, and the
  // corners as point elements): no markers at all
  std::string plain = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n"
                      "$Elements\n8\n1 15 2 0 1 1\n2 15 2 0 2 2\n3 15 2 0 3 3\n4 15 2 0 4 4\n"
                      "5 1 2 0 1 1 2\n6 1 2 0 2 2 3\n7 1 2 0 3 3 4\n8 1 2 0 4 4 1\n$EndElements\n";
  const afm_io::Poly_data p = parse_msh(plain);
  AFM_CHECK(p.points.size() == 4 && p.segments.size() == 4 && p.segment_markers.empty() && p.holes.empty());
  // an element in two physical groups is written twice: insert_poly() drops the repeat
  const std::string twice = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n"
                            "$Elements\n4\n1 1 2 5 1 1 2\n2 1 2 6 1 1 2\n3 1 2 5 2 2 3\n4 1 2 5 3 3 1\n$EndElements\n";
  const afm_io::Poly_data t = parse_msh(twice);
  AFM_CHECK(t.segments.size() == 4 && t.segment_markers == std::vector<int>({5, 6, 5, 5}));
  CDT cdt;
  AFM_CHECK(afm_io::insert_poly(cdt, t).duplicate_segments == 1);
}

// Sparse and unordered node tags, parametric nodes, a 3-node line, a
// triangle (skipped, counted), sections this reader does not use, and the
// physical group names of write_gmsh_msh(): marker_M gives the marker M.
AFM_TEST_CASE(test_io_read_gmsh_boundary_variants)
{
  const std::string msh =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$Comments\nwritten by hand; $Nodes here is not a section\n$EndComments\n"
    "$PhysicalNames\n3\n1 2 \"marker_0\"\n1 1 \"inlet #1\"\n2 5 \"domain\"\n$EndPhysicalNames\n"
    "$Entities\n0 2 1 0\n"
    "1 0 0 0 2 0 0 1 1 0\n"
    "2 0 0 0 2 1 0 1 2 0\n"
    "1 0 0 0 2 1 0 1 5 2 1 2\n"
    "$EndEntities\n"
    "$Nodes\n3 8 3 700\n"
    "1 1 1 2\n700\n30\n0 0 0 0\n2 0 0 1\n" // a parametric curve block: x y z u
    "1 2 0 5\n45\n3\n99\n98\n97\n2 1 0\n0 1 0\n2 0.5 0\n1 1.2 0\n0 0.5 0\n"
    "2 1 1 1\n500\n1 0.5 0 0.25 0.5\n" // a parametric surface node: x y z u v
    "$EndNodes\n"
    "$Elements\n3 5 1 41\n"
    "1 1 1 1\n1 700 30\n"
    "1 2 8 3\n17 30 45 99\n40 45 3 98\n41 3 700 97\n" // 3-node lines: their ends, the middle dropped
    "2 1 2 1\n2 700 30 500\n"
    "$EndElements\n"
    "$NodeData\n1\n\"a view\"\n1\n0.0\n3\n0\n1\n1\n700 1.5\n$EndNodeData\n"
    "$Periodic\n0\n$EndPeriodic\n";
  const afm_io::Poly_data d = parse_msh(msh, "v.msh");
  // nodes 700, 30, 45 and 3, the ends of the lines (not the middles 97 to
  // 99, nor 500 of the triangle), in the order of $Nodes
  AFM_CHECK_MSG(d.points.size() == 4, d.points.size());
  AFM_CHECK(d.origin.point_ids == std::vector<long long>({700, 30, 45, 3}));
  AFM_CHECK(d.points[1][0] == 2 && d.points[1][1] == 0 && d.points[3][0] == 0 && d.points[3][1] == 1);
  typedef std::array<std::size_t, 2> S;
  AFM_CHECK(d.segments == std::vector<S>({S{{0, 1}}, S{{1, 2}}, S{{2, 3}}, S{{3, 0}}}));
  AFM_CHECK(d.origin.segment_ids == std::vector<long long>({1, 17, 40, 41}));
  // curve 1 in group 1 "inlet #1", curve 2 in group 2 "marker_0"
  AFM_CHECK(d.segment_markers == std::vector<int>({1, 0, 0, 0}));
  AFM_CHECK(d.origin.ignored_elements == 1 && d.holes.empty());
  AFM_CHECK(d.origin.point_lines[0] == line_of(msh, "0 0 0 0") && d.origin.segment_lines[3] == line_of(msh, "41 3 700 97"));
  // the middle node of a 3-node line must exist too
  bool thrown = false;
  try {
    parse_msh(msh.substr(0, msh.find("40 45 3 98")) + "40 45 3 96" + msh.substr(msh.find("40 45 3 98") + 10), "v.msh");
  } catch(const afm_io::Poly_read_error& e) {
    thrown = e.line() == line_of(msh, "40 45 3 98") && e.problem() == "element 40 refers to node 96, which $Nodes does not define";
  }
  AFM_CHECK(thrown);

  // a point element adds its node as an isolated point
  const std::string with_point = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n2 4 1 4\n"
                                 "1 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n0 1 0 1\n4\n0.2 0.2 0\n$EndNodes\n"
                                 "$Elements\n2 4 1 4\n1 1 1 3\n1 1 2\n2 2 3\n3 3 1\n0 1 15 1\n4 4\n$EndElements\n";
  const afm_io::Poly_data p = parse_msh(with_point);
  AFM_CHECK(p.points.size() == 4 && p.segments.size() == 3 && p.points[3][0] == 0.2);
  CDT cdt;
  afm_io::insert_poly(cdt, p);
  AFM_CHECK(cdt.number_of_vertices() == 4);

  // a plane other than z = 0 is fine, as long as it is one plane
  const afm_io::Poly_data z = parse_msh("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 5\n2 1 0 5\n3 0 1 5\n"
                                        "$EndNodes\n$Elements\n3\n1 1 0 1 2\n2 1 0 2 3\n3 1 0 3 1\n$EndElements\n");
  AFM_CHECK(z.points.size() == 3 && z.segments.size() == 3);

  // insert_poly() names the items by their tags and lines
  const std::string crossing = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n10 0 0 0\n20 1 1 0\n30 1 0 0\n40 0 1 0\n"
                               "$EndNodes\n$Elements\n2\n11 1 0 10 20\n17 1 0 30 40\n$EndElements\n";
  const afm_io::Poly_data x = parse_msh(crossing, "x.msh");
  CDT xc;
  std::string message;
  try {
    afm_io::insert_poly(xc, x);
  } catch(const afm_io::Poly_read_error& e) {
    message = e.what();
  }
  AFM_CHECK_MSG(message == "x.msh:14: segment 17 crosses segment 11 (line 13)", message);
}

AFM_TEST_CASE(test_io_read_gmsh_boundary_rejects_malformed_input)
{
  // a triangle in MSH 4.1, without $Entities (lines 1-20), damaged below
  const std::string head = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  const std::string nodes = "$Nodes\n1 3 1 3\n1 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n";
  const std::string elements = "$Elements\n1 3 1 3\n1 1 1 3\n1 1 2\n2 2 3\n3 3 1\n$EndElements\n";
  AFM_CHECK(parse_msh(head + nodes + elements).segments.size() == 3);
  auto replace = [](std::string s, const std::string& from, const std::string& to) {
    const std::size_t i = s.find(from);
    AFM_CHECK_MSG(i != std::string::npos, from);
    return s.replace(i, from.size(), to);
  };
  const std::string v2 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n";
  const std::string entities = "$Entities\n0 1 0 0\n1 0 0 0 1 1 0 1 4 0\n$EndEntities\n";
  const std::vector<Bad_case> cases = {
    {"empty", "", 0, "file holds no data, expected $MeshFormat"},
    {"blank", "\n\n", 2, "file holds no data"},
    {"not a .msh", "solid ascii\n", 1, "expected $MeshFormat, found 'solid': not a Gmsh .msh file"},
    {"version 4", "$MeshFormat\n4 0 8\n$EndMeshFormat\n", 2, "MSH version '4' is not supported (versions 4.1 and 2.2 are)"},
    {"version 3", "$MeshFormat\n3.0 0 8\n", 2, "MSH version '3.0' is not supported"},
    {"binary", std::string("$MeshFormat\n4.1 1 8\n\x01") + std::string(3, '\0') + "\n$EndMeshFormat\n", 2,
     "binary .msh is not supported: save it as ASCII (Gmsh's default: option Mesh.Binary = 0"},
    {"file type 2", "$MeshFormat\n4.1 2 8\n", 2, "file type 2 must be 0 (ASCII) or 1 (binary)"},
    {"short format line", "$MeshFormat\n4.1 0\n", 2, "has 2 values, expected 3"},
    {"no $EndMeshFormat", "$MeshFormat\n4.1 0 8\n$Nodes\n", 3, "expected $EndMeshFormat after the format line, found '$Nodes'"},
    {"no $Nodes", head + elements, 0, "no $Nodes section"},
    {"no $Elements", head + nodes, 0, "no $Elements section"},
    {"text between sections", head + "garbage\n" + nodes + elements, 4, "expected a section ($Nodes, $Elements, ...), found 'garbage'"},
    {"stray end", head + "$EndNodes\n", 4, "'$EndNodes' closes no open section"},
    {"second $Nodes", head + nodes + nodes + elements, 14, "a second $Nodes section (the first on line 4)"},
    {"second $MeshFormat", head + head, 4, "a second $MeshFormat section (the first on line 1)"},
    {"unclosed section", head + nodes + elements + "$NodeData\n1\n", 22, "section $NodeData of line 21 is not closed"},
    {"partitioned", head + "$PartitionedEntities\n", 4, "partitioned meshes are not supported"},
    {"truncated nodes", head + "$Nodes\n1 3 1 3\n1 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n", 11,
     "file ends in section $Nodes, expected the coordinates of node 3 (3 of 3 of the block on line 6)"},
    {"nodes cut by $EndNodes", head + "$Nodes\n1 3 1 3\n1 1 0 3\n1\n2\n$EndNodes\n", 9,
     "expected node tag 3 of 3 of the block on line 6, found '$EndNodes'"},
    {"bad coordinate", replace(head + nodes + elements, "1 0 0\n", "1 0.x 0\n"), 11, "y coordinate '0.x' is not a number"},
    {"nan coordinate", replace(head + nodes + elements, "1 0 0\n", "nan 0 0\n"), 11, "x coordinate 'nan' is not finite"},
    {"fractional tag", replace(head + nodes + elements, "\n2\n", "\n2.5\n"), 8, "node tag '2.5' is not an integer"},
    {"zero tag", replace(head + nodes + elements, "\n2\n", "\n0\n"), 8, "node tag 0 is not positive"},
    {"node count", replace(head + nodes + elements, "1 3 1 3\n1 1 0 3", "1 4 1 4\n1 1 0 3"), 5,
     "the node header announces 4 nodes, its blocks hold 3"},
    {"node defined twice", replace(head + nodes + elements, "\n3\n0 0 0", "\n1\n0 0 0"), 12,
     "node 1 is defined twice (first on line 10)"},
    {"parametric node without u", replace(head + nodes + elements, "1 1 0 3", "1 1 1 3"), 10,
     "a parametric node's coordinates on an entity of dimension 1 has 3 values, expected 4"},
    {"z not constant", replace(head + nodes + elements, "1 0 0\n", "1 0 0.5\n"), 11,
     "node 2 lies at z = 0.5, node 1 (line 10) at z = 0: the boundary must lie in a plane z = constant"},
    {"undefined node", replace(head + nodes + elements, "3 3 1\n", "3 3 4\n"), 19,
     "element 3 refers to node 4, which $Nodes does not define"},
    {"line to itself", replace(head + nodes + elements, "2 2 3\n", "2 2 2\n"), 18, "element 2 joins node 2 to itself"},
    {"line with one node", replace(head + nodes + elements, "2 2 3\n", "2 2\n"), 18,
     "an element of type 1 'tag' and 2 nodes has 2 values, expected 3"},
    {"element count", replace(head + nodes + elements, "1 3 1 3\n1 1 1", "1 5 1 5\n1 1 1"), 15,
     "the element header announces 5 elements, its blocks hold 3"},
    {"truncated elements", head + nodes + "$Elements\n1 3 1 3\n1 1 1 3\n1 1 2\n2 2 3\n", 18,
     "file ends in section $Elements, expected element 3 of 3 of the block on line 16"},
    {"no $EndElements", head + nodes + "$Elements\n1 3 1 3\n1 1 1 3\n1 1 2\n2 2 3\n3 3 1\n$Foo\n", 20,
     "expected $EndElements after the 1 element block announced, found '$Foo'"},
    {"lines on a surface", replace(head + nodes + elements, "1 1 1 3\n1 1 2", "2 1 1 3\n1 1 2"), 16,
     "a block of line elements (type 1) must be on a curve entity (dimension 1), not on one of dimension 2"},
    {"only points", head + nodes + "$Elements\n1 1 1 1\n0 1 15 1\n1 1\n$EndElements\n", 0,
     "no line elements (type 1 or 8"},
    {"only triangles", head + nodes + "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n", 0,
     "give the boundary as a 1D mesh (gmsh -1, or gmsh.model.mesh.generate(1)); its 1 element of another type is not read"},
    {"curve not in $Entities", head + entities + nodes + replace(elements, "1 1 1 3", "1 9 1 3"), 20,
     "the element block is on curve 9, which $Entities does not list"},
    {"entity line short", head + "$Entities\n0 1 0 0\n1 0 0 0 1 1 0 1 4\n$EndEntities\n", 6,
     "a curve entity needs its number of bounding entities after its physical tags"},
    {"entity line long", head + "$Entities\n0 1 0 0\n1 0 0 0 1 1 0 1 4 0 7\n$EndEntities\n", 6,
     "a curve entity has 11 values, expected 10"},
    {"entities cut short", head + "$Entities\n1 1 0 0\n1 0 0 0 0\n$EndEntities\n", 7,
     "expected curve entity 1 of 1, found '$EndEntities'"},
    {"curve listed twice", head + "$Entities\n0 2 0 0\n1 0 0 0 1 1 0 0 0\n1 0 0 0 1 1 0 0 0\n$EndEntities\n", 7,
     "curve entity 1 is listed twice (first on line 6)"},
    {"unquoted name", head + "$PhysicalNames\n1\n1 3 outer\n$EndPhysicalNames\n", 6,
     "the name of physical group 3 must be in double quotes"},
    {"physical tag too large", head + "$PhysicalNames\n1\n1 3000000000 \"a\"\n$EndPhysicalNames\n", 6,
     "physical tag 3000000000 is out of range"},
    {"2.2: short node line", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1\n$EndNodes\n", 8, "a node line 'tag x y z' has 3 values, expected 4"},
    {"2.2: undefined node", v2 + "$Elements\n3\n1 1 0 1 2\n2 1 0 2 3\n3 1 2 0 1 3 7\n$EndElements\n", 14,
     "element 3 refers to node 7, which $Nodes does not define"},
    {"2.2: too many tags", v2 + "$Elements\n1\n1 1 5 1 2\n$EndElements\n", 12, "an element with 5 tags has 5 values"},
    {"2.2: line with 3 nodes", v2 + "$Elements\n1\n1 1 2 0 1 1 2 3\n$EndElements\n", 12,
     "an element of type 1 with 2 tags 'tag type numTags tags...' and 2 nodes has 8 values, expected 7"},
    {"2.2: element count", v2 + "$Elements\n3\n1 1 0 1 2\n2 1 0 2 3\n$EndElements\n", 14,
     "expected element 3 of 3, found '$EndElements'"},
    {"2.2: node count", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n", 8,
     "expected $EndNodes after the 2 nodes announced, found '3'"},
  };
  for(const Bad_case& c : cases) {
    bool thrown = false;
    try {
      parse_msh(c.content, "file.msh");
    } catch(const afm_io::Poly_read_error& e) {
      thrown = true;
      const std::string what = e.what();
      const std::string where = c.line == 0 ? std::string("file.msh: ") : "file.msh:" + std::to_string(c.line) + ": ";
      AFM_CHECK_MSG(what.compare(0, where.size(), where) == 0,
                    c.name << ": got \"" << what << "\", expected it to start with " << where);
      AFM_CHECK_MSG(e.line() == c.line && e.file() == "file.msh", c.name << ": " << what);
      AFM_CHECK_MSG(what.find(c.problem) != std::string::npos,
                    c.name << ": got \"" << what << "\", expected \"" << c.problem << "\"");
      AFM_CHECK_MSG(what.find('\n') == std::string::npos, c.name << ": " << what);
    }
    AFM_CHECK_MSG(thrown, c.name << ": accepted");
  }
}

// A mesh made here, written with its markers by write_gmsh_msh(), read back:
// the same boundary segments with the same markers, also those that are no
// Gmsh tag (0, negative), through the names marker_M.
AFM_TEST_CASE(test_io_gmsh_boundary_round_trip)
{
  typedef AFM::Markers_and_regions_2<CDT> Tags;
  afm_io::Poly_data in = afm_geometry::tagged_regions(0.1);
  for(int& m : in.segment_markers) {
    if(m == 5) m = 0;  // the interior side between the regions: written as 0
    if(m == 6) m = -3; // the inclusion
  }
  CDT cdt;
  const auto inserted = afm_io::insert_poly(cdt, in);
  Tags tags = afm_io::markers_and_regions(in, inserted);
  const auto rc = CGAL::advancing_front_mesh_2(cdt, inserted.hole_seeds.begin(), inserted.hole_seeds.end(), 0.1);
  AFM_CHECK(rc == AFM::MESH_COMPLETE);
  AFM_CHECK(in_domain_faces(cdt) > 100);
  tags.mark_regions(cdt);

  // what the mesh holds: its constrained edges with their markers
  std::map<Msh_test_segment, int> expected;
  for(const auto& e : cdt.constrained_edges()) {
    std::array<double, 2> a = {{e.first->vertex(CDT::ccw(e.second))->point().x(),
                                e.first->vertex(CDT::ccw(e.second))->point().y()}};
    std::array<double, 2> b = {{e.first->vertex(CDT::cw(e.second))->point().x(),
                                e.first->vertex(CDT::cw(e.second))->point().y()}};
    if(b < a) std::swap(a, b);
    expected[Msh_test_segment(a, b)] = tags.edge_marker(cdt, e.first, e.second);
  }
  // the mesher splits no constrained edge: the input's segments and markers
  AFM_CHECK(expected == segments_with_markers(in));

  std::ostringstream os;
  afm_io::write_gmsh_msh(os, cdt, tags);
  AFM_CHECK(os.str().find("\"marker_-3\"") != std::string::npos && os.str().find("\"marker_0\"") != std::string::npos);
  const afm_io::Poly_data back = parse_msh(os.str(), "round.msh");
  AFM_CHECK(back.segments.size() == in.segments.size());
  AFM_CHECK(segments_with_markers(back) == expected);
  AFM_CHECK_MSG(back.origin.ignored_elements == in_domain_faces(cdt), back.origin.ignored_elements);
  // a boundary vertex only: the nodes inside the domain are dropped
  AFM_CHECK(back.points.size() == in.points.size());
  // A 1D mesh cannot tell an inclusion (meshed) from a hole: by nesting,
  // both the hole and the inclusion get a seed.
  AFM_CHECK_MSG(back.holes.size() == 2, back.holes.size());
}
