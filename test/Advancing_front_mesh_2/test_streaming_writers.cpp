// Tests of the streaming mesh writer (IO/Streaming_mesh_writer.h).
//
// Every format is checked by parsing the output back, with every coordinate
// compared bit for bit (the coordinates are chosen to be awkward: 0.1, a
// subnormal, -0, the largest double, ...), and against the non-streaming
// writers of write_mesh.h where both can be fed the same mesh. The resume
// tests interrupt a writer after a checkpoint, after it went on writing, and
// require files byte-identical to those of an uninterrupted writer. The
// error tests include every truncation and every one-byte change of a
// checkpoint state, which must be refused cleanly (under ASan in CI).

#include "afm_test_harness.h"

#include <CGAL/Advancing_front_mesh_2/IO/Streaming_mesh_writer.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_vertex_base_2.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <typeinfo>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Simple_cartesian<double> SC;
typedef SC::Point_2 Point;
typedef CGAL::Advancing_front_mesh_2::IO::Streaming_mesh_writer<Point> Writer;

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Triangulation_vertex_base_2<K> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;

namespace afm_io = CGAL::Advancing_front_mesh_2::IO;
namespace fs = std::filesystem;

// A fresh directory under the system's temporary directory, removed with
// everything in it at the end of the test case. Declare it before any
// writer, so that the writers are destroyed first.
class Temp_dir
{
public:
  explicit Temp_dir(const std::string& tag)
  {
    static int counter = 0;
    for(int attempt = 0;; ++attempt) {
      AFM_CHECK_MSG(attempt < 100, "cannot create a temporary directory");
      const fs::path p = fs::temp_directory_path() /
        ("afm_test_streaming_" + tag + "_" +
         std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()) +
         "_" + std::to_string(++counter));
      std::error_code ec;
      if(fs::create_directory(p, ec)) {
        path_ = p;
        return;
      }
    }
  }
  ~Temp_dir()
  {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  Temp_dir(const Temp_dir&) = delete;
  Temp_dir& operator=(const Temp_dir&) = delete;

  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }

private:
  fs::path path_;
};

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

std::string read_text(const std::string& path)
{
  std::ifstream in(path.c_str(), std::ios::binary);
  AFM_CHECK_MSG(in.good(), "cannot open " << path);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::string> tokens(const std::string& s)
{
  std::vector<std::string> t;
  std::istringstream in(s);
  std::string w;
  while(in >> w)
    t.push_back(w);
  return t;
}

std::vector<std::string> lines(const std::string& s)
{
  std::vector<std::string> r;
  std::size_t b = 0;
  while(b < s.size()) {
    const std::size_t e = s.find('\n', b);
    AFM_CHECK_MSG(e != std::string::npos, "last line not ended");
    r.push_back(s.substr(b, e - b));
    b = e + 1;
  }
  return r;
}

double to_double(const std::string& s)
{
  double v = 0;
  const std::from_chars_result r = std::from_chars(s.data(), s.data() + s.size(), v);
  AFM_CHECK_MSG(r.ec == std::errc() && r.ptr == s.data() + s.size(), "not a double: " << s);
  return v;
}

std::uint64_t to_uint(const std::string& s)
{
  std::uint64_t v = 0;
  const std::from_chars_result r = std::from_chars(s.data(), s.data() + s.size(), v);
  AFM_CHECK_MSG(r.ec == std::errc() && r.ptr == s.data() + s.size(), "not an integer: " << s);
  return v;
}

// ---------------------------------------------------------------------------
// A test mesh, in the order a streaming mesher would hand it over

struct Event
{
  bool is_vertex;
  std::size_t index;
};

struct Test_mesh
{
  std::vector<std::array<double, 2> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<Event> events;
  // tags, when `markers` is not empty: a marker per vertex, an attribute per
  // triangle (empty: no regions), segments with their markers
  std::vector<int> markers;
  std::vector<double> attributes;
  std::vector<std::array<std::size_t, 2> > segments;
  std::vector<int> segment_markers;

  // the bounding box, updated as write_gmsh_msh() does
  std::array<double, 4> bbox() const
  {
    std::array<double, 4> b{{0, 0, 0, 0}};
    for(std::size_t i = 0; i < points.size(); ++i) {
      const std::array<double, 2>& p = points[i];
      if(i == 0) {
        b = {{p[0], p[1], p[0], p[1]}};
      } else {
        b[0] = (std::min)(b[0], p[0]); b[2] = (std::max)(b[2], p[0]);
        b[1] = (std::min)(b[1], p[1]); b[3] = (std::max)(b[3], p[1]);
      }
    }
    return b;
  }
};

// Deterministic coordinates, one in four of which is a hard case for
// decimal output.
double awkward(std::size_t v, int axis)
{
  static const double special[] = {
    0.1, 1e-300, -2.5e17, 1.0 / 3, -0.0, std::numeric_limits<double>::denorm_min(),
    (std::numeric_limits<double>::max)(), -123456.789e-5, 0.1 + 0.2, 1e23,
    9007199254740993.0, 2.5e-17, -(std::numeric_limits<double>::min)()};
  const std::size_t n = sizeof(special) / sizeof(special[0]);
  const std::uint32_t h = static_cast<std::uint32_t>(v * 2654435761u + std::size_t(axis) * 40503u);
  if(h % 4 == 0)
    return special[(h / 4) % n];
  return (double(v) + axis) * 0.1 / 3.0 * ((h / 4) % 2 ? 1 : -1);
}

// An nx by ny grid of cells, two triangles each, counter-clockwise in index
// space; the vertices of a row come before the triangles of the cells below.
Test_mesh grid_mesh(std::size_t nx, std::size_t ny)
{
  Test_mesh m;
  auto vid = [nx](std::size_t i, std::size_t j) { return j * (nx + 1) + i; };
  for(std::size_t j = 0; j <= ny; ++j) {
    for(std::size_t i = 0; i <= nx; ++i) {
      const std::size_t v = vid(i, j);
      m.points.push_back({{awkward(v, 0), awkward(v, 1)}});
      m.events.push_back(Event{true, v});
    }
    if(j == 0)
      continue;
    for(std::size_t i = 0; i < nx; ++i) {
      const std::size_t a = vid(i, j - 1), b = vid(i + 1, j - 1), c = vid(i + 1, j), d = vid(i, j);
      m.triangles.push_back({{a, b, c}});
      m.events.push_back(Event{false, m.triangles.size() - 1});
      m.triangles.push_back({{a, c, d}});
      m.events.push_back(Event{false, m.triangles.size() - 1});
    }
  }
  return m;
}

template <class P>
void stream(afm_io::Streaming_mesh_writer<P>& w, const Test_mesh& m,
            std::size_t from, std::size_t to)
{
  for(std::size_t e = from; e < to; ++e) {
    const Event& ev = m.events[e];
    const bool tagged = !m.markers.empty();
    if(ev.is_vertex) {
      const P p(m.points[ev.index][0], m.points[ev.index][1]);
      if(tagged) w.add_vertex(ev.index, p, m.markers[ev.index]);
      else w.add_vertex(ev.index, p);
    } else {
      const std::array<std::size_t, 3>& t = m.triangles[ev.index];
      if(!m.attributes.empty()) w.add_triangle(t[0], t[1], t[2], m.attributes[ev.index]);
      else w.add_triangle(t[0], t[1], t[2]);
    }
  }
}

// The vertex and triangle counts after the first `e` events.
std::array<std::size_t, 2> counts_at(const Test_mesh& m, std::size_t e)
{
  std::array<std::size_t, 2> c{{0, 0}};
  for(std::size_t i = 0; i < e; ++i)
    ++c[m.events[i].is_vertex ? 0 : 1];
  return c;
}

// ---------------------------------------------------------------------------
// Readers of the four formats, strict about the layout

void check_point(const Test_mesh& m, std::size_t i, const std::string& x, const std::string& y,
                 const std::string& what)
{
  AFM_CHECK_MSG(same_bits(to_double(x), m.points[i][0]) && same_bits(to_double(y), m.points[i][1]),
                what << ": vertex " << i << " is " << x << " " << y);
}

void check_off(const std::string& path, const Test_mesh& m)
{
  const std::string text = read_text(path);
  const std::string header = "OFF\n" + std::to_string(m.points.size()) + " " +
                             std::to_string(m.triangles.size()) + " 0\n";
  AFM_CHECK_MSG(text.compare(0, header.size(), header) == 0, "OFF header of " << path);
  const std::vector<std::string> t = tokens(text);
  AFM_CHECK(t.size() == 4 + 3 * m.points.size() + 4 * m.triangles.size());
  std::size_t k = 4;
  for(std::size_t i = 0; i < m.points.size(); ++i, k += 3) {
    check_point(m, i, t[k], t[k + 1], path);
    AFM_CHECK(t[k + 2] == "0");
  }
  for(std::size_t i = 0; i < m.triangles.size(); ++i, k += 4)
    AFM_CHECK_MSG(t[k] == "3" && to_uint(t[k + 1]) == m.triangles[i][0] &&
                  to_uint(t[k + 2]) == m.triangles[i][1] && to_uint(t[k + 3]) == m.triangles[i][2],
                  path << ": triangle " << i);
}

std::string padded_count(std::size_t n)
{
  std::string s = std::to_string(n);
  s.resize(20, ' ');
  return s;
}

void check_node_ele(const std::string& base, const Test_mesh& m)
{
  const std::string node = read_text(base + ".node");
  const std::string ele = read_text(base + ".ele");
  // the count is padded to 20 characters, the rest as write_triangle_node_ele()
  AFM_CHECK(node.compare(0, 27, padded_count(m.points.size()) + " 2 0 0\n") == 0);
  AFM_CHECK(ele.compare(0, 25, padded_count(m.triangles.size()) + " 3 0\n") == 0);
  const std::vector<std::string> nt = tokens(node), et = tokens(ele);
  AFM_CHECK(nt.size() == 4 + 3 * m.points.size());
  AFM_CHECK(et.size() == 3 + 4 * m.triangles.size());
  for(std::size_t i = 0, k = 4; i < m.points.size(); ++i, k += 3) {
    AFM_CHECK(to_uint(nt[k]) == i + 1);
    check_point(m, i, nt[k + 1], nt[k + 2], base + ".node");
  }
  for(std::size_t i = 0, k = 3; i < m.triangles.size(); ++i, k += 4)
    AFM_CHECK_MSG(to_uint(et[k]) == i + 1 && to_uint(et[k + 1]) == m.triangles[i][0] + 1 &&
                  to_uint(et[k + 2]) == m.triangles[i][1] + 1 &&
                  to_uint(et[k + 3]) == m.triangles[i][2] + 1,
                  base << ".ele: triangle " << i);
}

void check_msh(const std::string& path, const Test_mesh& m)
{
  const std::vector<std::string> l = lines(read_text(path));
  const std::size_t nv = m.points.size(), nt = m.triangles.size();
  std::size_t k = 0;
  auto expect = [&](const std::string& s) {
    AFM_CHECK_MSG(k < l.size() && l[k] == s, path << " line " << k + 1 << ": expected '" << s
                                                  << "', found '" << (k < l.size() ? l[k] : "") << "'");
    ++k;
  };
  expect("$MeshFormat");
  expect("4.1 0 8");
  expect("$EndMeshFormat");
  expect("$Entities");
  expect("0 0 1 0");
  AFM_CHECK(k < l.size());
  const std::vector<std::string> e = tokens(l[k++]);
  // tag minX minY minZ maxX maxY maxZ numPhysicalTags numBoundingCurves
  AFM_CHECK(e.size() == 9 && e[0] == "1" && e[3] == "0" && e[6] == "0" && e[7] == "0" && e[8] == "0");
  const std::array<double, 4> b = m.bbox();
  AFM_CHECK_MSG(same_bits(to_double(e[1]), b[0]) && same_bits(to_double(e[2]), b[1]) &&
                same_bits(to_double(e[4]), b[2]) && same_bits(to_double(e[5]), b[3]),
                "bounding box " << l[k - 1]);
  expect("$EndEntities");
  expect("$Nodes");
  if(nv == 0) {
    expect("0 0 0 0");
  } else {
    expect("1 " + std::to_string(nv) + " 1 " + std::to_string(nv));
    expect("2 1 0 " + std::to_string(nv));
    for(std::size_t i = 1; i <= nv; ++i)
      expect(std::to_string(i));
    for(std::size_t i = 0; i < nv; ++i) {
      AFM_CHECK(k < l.size());
      const std::vector<std::string> c = tokens(l[k++]);
      AFM_CHECK(c.size() == 3 && c[2] == "0");
      check_point(m, i, c[0], c[1], path);
    }
  }
  expect("$EndNodes");
  expect("$Elements");
  if(nt == 0) {
    expect("0 0 0 0");
  } else {
    expect("1 " + std::to_string(nt) + " 1 " + std::to_string(nt));
    expect("2 1 2 " + std::to_string(nt));
    for(std::size_t i = 0; i < nt; ++i) {
      const std::array<std::size_t, 3>& t = m.triangles[i];
      expect(std::to_string(i + 1) + " " + std::to_string(t[0] + 1) + " " +
             std::to_string(t[1] + 1) + " " + std::to_string(t[2] + 1));
    }
  }
  expect("$EndElements");
  AFM_CHECK(k == l.size());
}

// The arrays of a VTU file in our layout, ASCII or raw appended binary,
// keyed "points", "connectivity", "offsets", "types", "point marker",
// "cell marker", "region"; Float64 arrays as doubles (bit for bit),
// integers as int64. The layout is checked on the way.
struct Vtu_arrays
{
  bool binary = false;
  std::map<std::string, std::vector<double> > reals;
  std::map<std::string, std::vector<std::int64_t> > integers;
};

std::string xml_attribute(const std::string& tag, const std::string& name)
{
  const std::size_t a = tag.find(" " + name + "=\"");
  if(a == std::string::npos) return std::string();
  const std::size_t b = a + name.size() + 3;
  return tag.substr(b, tag.find('"', b) - b);
}

Vtu_arrays read_vtu_arrays(const std::string& text)
{
  Vtu_arrays r;
  const std::size_t appended = text.find("<AppendedData encoding=\"raw\">\n_");
  r.binary = appended != std::string::npos;
  const std::size_t data = appended + std::strlen("<AppendedData encoding=\"raw\">\n_");
  std::string section;
  for(std::size_t p = text.find('<'); p != std::string::npos && (!r.binary || p < appended);
      p = text.find('<', p + 1)) {
    const std::size_t q = text.find('>', p);
    const std::string tag = text.substr(p, q - p + 1);
    for(const char* s : {"<Points", "<Cells", "<PointData", "<CellData"})
      if(tag.compare(0, std::strlen(s), s) == 0) section = s + 1;
    if(tag.compare(0, 10, "<DataArray") != 0) continue;
    const std::string type = xml_attribute(tag, "type"), name = xml_attribute(tag, "Name");
    std::string key = section == "Points" ? "points" : name;
    if(section == "PointData") key = "point " + name;
    if(section == "CellData" && name == "marker") key = "cell marker";
    const std::size_t width = type == "Float64" || type == "Int64" ? 8 : type == "Int32" ? 4 : 1;
    AFM_CHECK_MSG(type == "Float64" || type == "Int64" || type == "Int32" || type == "UInt8", "type " << type);
    if(r.binary) {
      AFM_CHECK_MSG(xml_attribute(tag, "format") == "appended" && tag.compare(tag.size() - 2, 2, "/>") == 0, tag);
      const std::size_t at = data + std::size_t(to_uint(xml_attribute(tag, "offset")));
      AFM_CHECK(at + 8 <= text.size());
      std::uint64_t bytes = 0;
      std::memcpy(&bytes, text.data() + at, 8);
      AFM_CHECK_MSG(bytes % width == 0 && at + 8 + bytes <= text.size(), key << ": " << bytes << " bytes");
      for(std::size_t i = 0; i < bytes; i += width) {
        const char* v = text.data() + at + 8 + i;
        if(type == "Float64") { double d; std::memcpy(&d, v, 8); r.reals[key].push_back(d); }
        else if(type == "Int64") { std::int64_t k; std::memcpy(&k, v, 8); r.integers[key].push_back(k); }
        else if(type == "Int32") { std::int32_t k; std::memcpy(&k, v, 4); r.integers[key].push_back(k); }
        else r.integers[key].push_back(static_cast<unsigned char>(*v));
      }
      r.reals[key];
      r.integers[key];
    } else {
      AFM_CHECK_MSG(xml_attribute(tag, "format") == "ascii", tag);
      const std::size_t e = text.find("</DataArray>", q);
      AFM_CHECK_MSG(text.find('<', q) == e, "markup inside the DataArray " << key);
      r.reals[key];
      r.integers[key];
      for(const std::string& t : tokens(text.substr(q + 1, e - q - 1))) {
        if(type == "Float64") r.reals[key].push_back(to_double(t));
        else r.integers[key].push_back(std::stoll(t));
      }
    }
  }
  if(r.binary) {
    const std::string tail = "\n</AppendedData>\n</VTKFile>\n";
    AFM_CHECK(text.compare(text.size() - tail.size(), tail.size(), tail) == 0);
  }
  return r;
}

void check_vtu(const std::string& path, const Test_mesh& m, bool binary = true)
{
  const std::string text = read_text(path);
  const std::size_t nv = m.points.size(), nt = m.triangles.size();
  AFM_CHECK(text.compare(0, 21, "<?xml version=\"1.0\"?>") == 0);
  AFM_CHECK(text.find("<VTKFile type=\"UnstructuredGrid\"") != std::string::npos);
  AFM_CHECK(text.find("NumberOfPoints=\"" + std::to_string(nv) + "\"") != std::string::npos);
  AFM_CHECK(text.find("NumberOfCells=\"" + std::to_string(nt) + "\"") != std::string::npos);
  const std::size_t tail = text.size() - std::strlen("</VTKFile>\n");
  AFM_CHECK(text.size() > 11 && text.compare(tail, std::string::npos, "</VTKFile>\n") == 0);
  // every element opened is closed, in order (the raw data is not markup)
  const std::size_t end_of_markup = binary ? text.find("<AppendedData") : text.size();
  AFM_CHECK(end_of_markup != std::string::npos);
  std::vector<std::string> stack;
  for(std::size_t p = text.find('<'); p < end_of_markup; p = text.find('<', p + 1)) {
    const std::size_t q = text.find('>', p);
    AFM_CHECK(q != std::string::npos);
    const std::string tag = text.substr(p + 1, q - p - 1);
    if(tag[0] == '?')
      continue;
    if(tag[0] == '/') {
      AFM_CHECK_MSG(!stack.empty() && stack.back() == tag.substr(1), "unbalanced " << tag);
      stack.pop_back();
    } else if(tag.back() != '/') {
      stack.push_back(tag.substr(0, tag.find(' ')));
    }
  }
  AFM_CHECK(binary ? stack == std::vector<std::string>{"VTKFile"} : stack.empty());

  const Vtu_arrays a = read_vtu_arrays(text);
  AFM_CHECK(a.binary == binary);
  const std::vector<double>& pts = a.reals.at("points");
  AFM_CHECK(pts.size() == 3 * nv);
  for(std::size_t i = 0; i < nv; ++i) {
    AFM_CHECK_MSG(same_bits(pts[3 * i], m.points[i][0]) && same_bits(pts[3 * i + 1], m.points[i][1]),
                  path << ": vertex " << i);
    AFM_CHECK(pts[3 * i + 2] == 0);
  }
  const std::vector<std::int64_t>& conn = a.integers.at("connectivity");
  const std::vector<std::int64_t>& offsets = a.integers.at("offsets");
  const std::vector<std::int64_t>& types = a.integers.at("types");
  AFM_CHECK(conn.size() == 3 * nt && offsets.size() == nt && types.size() == nt);
  for(std::size_t i = 0; i < nt; ++i) {
    for(int j = 0; j < 3; ++j)
      AFM_CHECK(conn[3 * i + j] == std::int64_t(m.triangles[i][j]));
    AFM_CHECK(offsets[i] == std::int64_t(3 * (i + 1)));
    AFM_CHECK(types[i] == 5);
  }
}

// Nothing but the given files left in `dir`: no part file.
void check_only_files(const Temp_dir& dir, std::vector<std::string> expected)
{
  std::vector<std::string> found;
  for(const fs::directory_entry& e : fs::recursive_directory_iterator(dir.path()))
    if(e.is_regular_file())
      found.push_back(e.path().string());
  std::sort(found.begin(), found.end());
  std::sort(expected.begin(), expected.end());
  std::ostringstream os;
  for(const std::string& f : found)
    os << " " << f;
  AFM_CHECK_MSG(found == expected, "files left:" << os.str());
}

template <class E, class F>
std::string thrown_message(F f)
{
  try {
    f();
  } catch(const E& e) {
    // exactly E: std::invalid_argument is a std::logic_error too
    AFM_CHECK_MSG(typeid(e) == typeid(E), "unexpected exception type: " << e.what());
    return e.what();
  }
  AFM_CHECK_MSG(false, "expected exception not thrown");
  return std::string();
}

// ---------------------------------------------------------------------------
// Each format

AFM_TEST_CASE(test_streaming_writer_off)
{
  Temp_dir dir("off");
  const Test_mesh m = grid_mesh(17, 13);
  const std::string out = dir.file("mesh.OFF"); // the extension in any case
  {
    Writer w({out});
    AFM_CHECK(w.file_names().size() == 1 && w.file_names()[0] == out);
    AFM_CHECK(fs::exists(out + ".vertices.part") && fs::exists(out + ".triangles.part"));
    stream(w, m, 0, m.events.size());
    AFM_CHECK(w.number_of_vertices() == m.points.size());
    AFM_CHECK(w.number_of_triangles() == m.triangles.size());
    w.close();
    w.close(); // idempotent
  }
  check_off(out, m);
  check_only_files(dir, {out});

  // CGAL's own reader takes it, with the same numbers (the file is read
  // through iostreams there, not from_chars).
  std::vector<SC::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  AFM_CHECK(CGAL::IO::read_OFF(out, points, polygons));
  AFM_CHECK(points.size() == m.points.size() && polygons.size() == m.triangles.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    AFM_CHECK_MSG(same_bits(points[i].x(), m.points[i][0]) && same_bits(points[i].y(), m.points[i][1]) &&
                  points[i].z() == 0, "read_OFF: vertex " << i);
  for(std::size_t i = 0; i < polygons.size(); ++i)
    AFM_CHECK(polygons[i].size() == 3 && polygons[i][0] == m.triangles[i][0] &&
              polygons[i][1] == m.triangles[i][1] && polygons[i][2] == m.triangles[i][2]);
}

AFM_TEST_CASE(test_streaming_writer_node_ele)
{
  Temp_dir dir("node_ele");
  const Test_mesh m = grid_mesh(11, 19);
  for(const char* ext : {".node", ".ele", ".Ele"}) {
    const std::string base = dir.file(std::string("mesh") + (ext[1] == 'E' ? "2" : ""));
    {
      Writer w({base + ext});
      stream(w, m, 0, m.events.size());
      w.close();
    }
    check_node_ele(base, m);
    fs::remove(base + ".node");
    fs::remove(base + ".ele");
    check_only_files(dir, {});
  }
}

AFM_TEST_CASE(test_streaming_writer_msh)
{
  Temp_dir dir("msh");
  const Test_mesh m = grid_mesh(23, 7);
  const std::string out = dir.file("mesh.msh");
  {
    Writer w({out});
    stream(w, m, 0, m.events.size());
    w.close();
  }
  check_msh(out, m);
  check_only_files(dir, {out});
}

AFM_TEST_CASE(test_streaming_writer_vtu)
{
  Temp_dir dir("vtu");
  const Test_mesh m = grid_mesh(9, 21);
  const std::string out = dir.file("mesh.Vtu");
  {
    Writer w({out});
    stream(w, m, 0, m.events.size());
    w.close();
  }
  check_vtu(out, m);
  check_only_files(dir, {out});
}

AFM_TEST_CASE(test_streaming_writer_empty_mesh)
{
  Temp_dir dir("empty");
  const Test_mesh m; // nothing at all
  const std::vector<std::string> names = {dir.file("e.off"), dir.file("e.node"), dir.file("e.msh"),
                                          dir.file("e.vtu")};
  {
    Writer w(names);
    w.close();
  }
  check_off(names[0], m);
  check_node_ele(dir.file("e"), m);
  check_msh(names[2], m);
  check_vtu(names[3], m);
  // with only zeros to write, the numbers of the non-streaming writers agree
  CDT cdt;
  std::ostringstream off, msh;
  afm_io::write_OFF(off, cdt);
  afm_io::write_gmsh_msh(msh, cdt);
  AFM_CHECK(read_text(names[0]) == off.str());
  AFM_CHECK(read_text(names[2]) == msh.str());
  check_only_files(dir, {names[0], dir.file("e.node"), dir.file("e.ele"), names[2], names[3]});
}

// The same triangulation through write_mesh.h and through the streaming
// writer, in the numbering of the former: the files hold the same tokens,
// numbers compared by value (max_digits10 against shortest decimals).
AFM_TEST_CASE(test_streaming_writer_matches_write_mesh)
{
  Temp_dir dir("match");
  CDT cdt;
  std::vector<K::Point_2> pts = {K::Point_2(-2.5e17, 0.1), K::Point_2(2.5e17, 1e-300),
                                 K::Point_2(0.1, 2.5e17), K::Point_2(1.0 / 3, -2.5e17)};
  for(int i = 0; i < 300; ++i) {
    // the awkward values, but none so large that predicates overflow
    double a = awkward(std::size_t(i), 0), b = awkward(std::size_t(i), 1);
    if(!(std::abs(a) < 1e20)) a = 0.7;
    if(!(std::abs(b) < 1e20)) b = 0.3;
    pts.push_back(K::Point_2(a * 1e-3 + 0.1 * (i % 17), b * 1e-3 + 0.1 * (i / 17)));
  }
  cdt.insert(pts.begin(), pts.end());
  cdt.insert_constraint(pts[0], pts[1]);
  for(CDT::Finite_faces_iterator f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    f->set_in_domain(true);
  afm_io::internal::Mesh_domain_view<CDT> view;
  afm_io::internal::mesh_collect_domain(cdt, view);
  AFM_CHECK(view.triangles.size() > 300);

  typedef afm_io::Streaming_mesh_writer<K::Point_2> Epick_writer;
  const std::vector<std::string> names = {dir.file("s.off"), dir.file("s.ele"), dir.file("s.msh"),
                                          dir.file("s.vtu")};
  {
    Epick_writer w(names);
    for(std::size_t i = 0; i < view.points.size(); ++i)
      w.add_vertex(i, K::Point_2(view.points[i][0], view.points[i][1]));
    for(const std::array<std::size_t, 3>& t : view.triangles)
      w.add_triangle(t[0], t[1], t[2]);
    w.close();
  }
  afm_io::write_mesh(dir.file("r.off"), cdt);
  afm_io::write_mesh(dir.file("r.node"), cdt);
  afm_io::write_mesh(dir.file("r.msh"), cdt);
  afm_io::write_mesh(dir.file("r.vtu"), cdt);
  // binary VTU: the same bytes
  AFM_CHECK(read_text(dir.file("s.vtu")) == read_text(dir.file("r.vtu")));
  // ASCII VTU: the same numbers
  {
    afm_io::Streaming_mesh_writer_options ascii;
    ascii.use_binary_mode = false;
    Epick_writer w({dir.file("sa.vtu")}, ascii);
    for(std::size_t i = 0; i < view.points.size(); ++i)
      w.add_vertex(i, K::Point_2(view.points[i][0], view.points[i][1]));
    for(const std::array<std::size_t, 3>& t : view.triangles)
      w.add_triangle(t[0], t[1], t[2]);
    w.close();
  }
  afm_io::write_mesh(dir.file("ra.vtu"), cdt, CGAL::parameters::use_binary_mode(false));
  {
    const Vtu_arrays a = read_vtu_arrays(read_text(dir.file("sa.vtu")));
    const Vtu_arrays b = read_vtu_arrays(read_text(dir.file("ra.vtu")));
    const Vtu_arrays c = read_vtu_arrays(read_text(dir.file("r.vtu")));
    AFM_CHECK(!a.binary && !b.binary && c.binary);
    AFM_CHECK(a.integers == b.integers && a.integers == c.integers);
    AFM_CHECK(a.reals.size() == b.reals.size() && a.reals.size() == c.reals.size());
    for(const auto& k : a.reals) {
      const std::vector<double>& x = k.second;
      const std::vector<double>& y = b.reals.at(k.first);
      const std::vector<double>& z = c.reals.at(k.first);
      AFM_CHECK(x.size() == y.size() && x.size() == z.size());
      for(std::size_t i = 0; i < x.size(); ++i)
        AFM_CHECK_MSG(same_bits(x[i], y[i]) && same_bits(x[i], z[i]), k.first << " " << i);
    }
  }

  for(const char* ext : {".off", ".node", ".ele", ".msh"}) {
    const std::vector<std::string> a = tokens(read_text(dir.file(std::string("s") + ext)));
    const std::vector<std::string> b = tokens(read_text(dir.file(std::string("r") + ext)));
    AFM_CHECK_MSG(a.size() == b.size(), ext);
    for(std::size_t i = 0; i < a.size(); ++i)
      AFM_CHECK_MSG(a[i] == b[i] || same_bits(to_double(a[i]), to_double(b[i])),
                    ext << " token " << i << ": " << a[i] << " vs " << b[i]);
  }
}

// ---------------------------------------------------------------------------
// Resume

// Writes `m` to `names` with a writer that dies after each pair of `plan`
// (checkpoint at event `first`, dies at event `second` >= `first`) and is
// resumed from that checkpoint; then finishes and closes.
void write_with_interruptions(const std::vector<std::string>& names, const Test_mesh& m,
                              const std::vector<std::pair<std::size_t, std::size_t> >& plan,
                              const afm_io::Streaming_mesh_writer_options& options =
                                afm_io::Streaming_mesh_writer_options())
{
  std::unique_ptr<Writer> w(new Writer(names, options));
  std::size_t done = 0;
  for(const std::pair<std::size_t, std::size_t>& p : plan) {
    stream(*w, m, done, p.first);
    const std::string state = w->checkpoint_state();
    // sizes at the checkpoint of the files that grow
    std::vector<std::pair<std::string, std::uintmax_t> > sizes;
    for(const fs::directory_entry& e : fs::directory_iterator(fs::path(names[0]).parent_path()))
      sizes.emplace_back(e.path().string(), fs::file_size(e.path()));
    stream(*w, m, p.first, p.second);
    w.reset(); // dies without close()
    // the dead writer went on writing: the resume has to cut it off
    bool grown = p.second == p.first;
    for(const std::pair<std::string, std::uintmax_t>& s : sizes)
      grown = grown || fs::file_size(s.first) > s.second;
    AFM_CHECK_MSG(grown, "nothing written after the checkpoint reached the files");

    w = Writer::resume(state);
    AFM_CHECK(w->file_names() == names);
    const std::array<std::size_t, 2> c = counts_at(m, p.first);
    AFM_CHECK(w->number_of_vertices() == c[0] && w->number_of_triangles() == c[1]);
    done = p.first;
  }
  stream(*w, m, done, m.events.size());
  for(std::size_t i = 0; i < m.segments.size(); ++i)
    w->add_segment(m.segments[i][0], m.segments[i][1], m.segment_markers[i]);
  w->close();
}

AFM_TEST_CASE(test_streaming_writer_resume_all_formats)
{
  Temp_dir ref("resume_ref"), run("resume_run");
  // more than the 1 MiB buffer per file, so that buffers are drained mid-line
  const Test_mesh m = grid_mesh(150, 160);
  const std::vector<std::string> outputs = {"a.off", "b with spaces.vtu", "c.NODE", "d.msh", "e.ele"};
  std::vector<std::string> ref_names, run_names;
  for(const std::string& o : outputs) {
    ref_names.push_back(ref.file(o));
    run_names.push_back(run.file(o));
  }
  {
    Writer w(ref_names);
    stream(w, m, 0, m.events.size());
    w.close();
  }
  check_off(ref_names[0], m);
  check_vtu(ref_names[1], m);
  check_node_ele(ref.file("c"), m);
  check_msh(ref_names[3], m);
  check_node_ele(ref.file("e"), m);

  const std::size_t n = m.events.size();
  const std::vector<std::vector<std::pair<std::size_t, std::size_t> > > plans = {
    {{n / 3, n / 2}},                        // once, mid-mesh
    {{0, n / 5}, {n / 7, n / 4 + 1}, {n - 3, n}}, // from the start, again, at the very end
    {{n / 2, n / 2}, {n / 2, n / 2 + 1000}}     // nothing written after one checkpoint
  };
  for(const auto& plan : plans) {
    write_with_interruptions(run_names, m, plan);
    for(const char* f : {"a.off", "b with spaces.vtu", "c.node", "c.ele", "d.msh", "e.node", "e.ele"})
      AFM_CHECK_MSG(read_text(run.file(f)) == read_text(ref.file(f)), f << " differs after resume");
    check_only_files(run, {run.file("a.off"), run.file("b with spaces.vtu"), run.file("c.node"),
                           run.file("c.ele"), run.file("d.msh"), run.file("e.node"), run.file("e.ele")});
    for(const fs::directory_entry& e : fs::directory_iterator(run.path()))
      fs::remove(e.path());
  }
}

// ---------------------------------------------------------------------------
// Errors

AFM_TEST_CASE(test_streaming_writer_rejects_bad_outputs)
{
  Temp_dir dir("bad_outputs");
  const std::string empty_msg =
    thrown_message<std::invalid_argument>([] { Writer w(std::vector<std::string>{}); });
  AFM_CHECK(!empty_msg.empty());
  for(const char* name : {"m.svg", "m.stl", "m", "m.off.part", "m.offx", "dir.off/m"}) {
    const std::string msg = thrown_message<std::invalid_argument>(
      [&] { Writer w({dir.file("ok.off"), dir.file(name)}); });
    AFM_CHECK_MSG(msg.find("cannot be streamed") != std::string::npos &&
                  msg.find(".off") != std::string::npos && msg.find(".msh") != std::string::npos, msg);
  }
  // two outputs writing the same files
  thrown_message<std::invalid_argument>([&] { Writer w({dir.file("m.node"), dir.file("m.ele")}); });
  thrown_message<std::invalid_argument>([&] { Writer w({dir.file("m.off"), dir.file("./m.off")}); });
  // nothing was created by a refused writer
  check_only_files(dir, {});

  const std::string missing = dir.file("no such dir/m.msh");
  const std::string msg = thrown_message<std::runtime_error>([&] { Writer w({missing}); });
  AFM_CHECK_MSG(msg.find("cannot write") == 0 && msg.find("no such dir") != std::string::npos, msg);
}

AFM_TEST_CASE(test_streaming_writer_rejects_bad_sequences)
{
  Temp_dir dir("bad_sequences");
  const std::string out = dir.file("m.off");
  {
    Writer w({out});
    thrown_message<std::logic_error>([&] { w.add_vertex(1, Point(0, 0)); });
    w.add_vertex(0, Point(0, 0));
    thrown_message<std::logic_error>([&] { w.add_vertex(0, Point(1, 0)); });
    thrown_message<std::logic_error>([&] { w.add_triangle(0, 0, 0 + 1); });
    w.add_vertex(1, Point(1, 0));
    thrown_message<std::invalid_argument>(
      [&] { w.add_vertex(2, Point(std::numeric_limits<double>::quiet_NaN(), 0)); });
    thrown_message<std::invalid_argument>(
      [&] { w.add_vertex(2, Point(0, std::numeric_limits<double>::infinity())); });
    w.add_vertex(2, Point(0, 1));
    thrown_message<std::logic_error>([&] { w.add_triangle(3, 0, 1); });
    thrown_message<std::logic_error>([&] { w.add_triangle(0, 3, 1); });
    thrown_message<std::logic_error>([&] { w.add_triangle(0, 1, 3); });
    thrown_message<std::logic_error>([&] { w.add_triangle(std::size_t(-1), 1, 2); });
    w.add_triangle(0, 1, 2); // refused calls left the writer usable
    w.close();
    thrown_message<std::logic_error>([&] { w.add_vertex(3, Point(0, 0)); });
    thrown_message<std::logic_error>([&] { w.add_triangle(0, 1, 2); });
    thrown_message<std::logic_error>([&] { w.checkpoint_state(); });
    w.close();
  }
  AFM_CHECK(read_text(out) == "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
}

AFM_TEST_CASE(test_streaming_writer_rejects_corrupt_states)
{
  Temp_dir dir("corrupt");
  const Test_mesh m = grid_mesh(10, 10);
  std::string state;
  {
    Writer w({dir.file("a b.off"), dir.file("c.node"), dir.file("d.msh"), dir.file("e.vtu")});
    stream(w, m, 0, m.events.size() / 2);
    state = w.checkpoint_state();
  }
  auto corrupt = [](const std::string& s) {
    const std::string msg = thrown_message<std::invalid_argument>([&] { Writer::resume(s); });
    AFM_CHECK_MSG(msg.find("corrupt streaming writer state: ") == 0, msg);
  };
  // the state itself is fine, and can be resumed repeatedly
  Writer::resume(state);
  Writer::resume(state)->checkpoint_state();

  for(std::size_t n = 0; n < state.size(); ++n)
    corrupt(state.substr(0, n));
  corrupt(state + "x");
  corrupt(state + "\n");
  corrupt("");
  corrupt(std::string(1000, '\0'));

  auto replaced = [&state](const std::string& from, const std::string& to) {
    const std::size_t p = state.find(from);
    AFM_CHECK_MSG(p != std::string::npos, from);
    return state.substr(0, p) + to + state.substr(p + from.size());
  };
  const std::string nv = "\nvertices " + std::to_string(counts_at(m, m.events.size() / 2)[0]) + "\n";
  for(const char* bad : {"abc", "-1", "", " 1", "+1", "99999999999999999999999", "18446744073709551615",
                         "1000000000"})
    corrupt(replaced(nv, std::string("\nvertices ") + bad + "\n"));
  corrupt(replaced("\ntriangles ", "\ntriangles 18446744073709551615"));
  corrupt(replaced("\noutputs 4\n", "\noutputs 18446744073709551615\n"));
  corrupt(replaced("\noutputs 4\n", "\noutputs 5\n"));
  corrupt(replaced("\noutputs 4\n", "\noutputs 0\n"));
  corrupt(replaced("output ", "output 99999999999"));  // a name longer than the state
  corrupt(replaced("output ", "output 18446744073709551615")); // ... and than memory
  corrupt(replaced("state 2\n", "state 3\n"));
  corrupt(replaced("content 1 0 0", "content 2 0 0"));
  corrupt(replaced("content 1 0 0", "content 1 0 1 0x1p+0")); // regions without tags
  corrupt(replaced("files 2\n", "files 3\n"));
  corrupt(replaced("groups 0", "groups 1 5"));
  corrupt(replaced("bbox ", "bbox inf "));
  corrupt(replaced("bbox ", "bbox nan "));
  corrupt(replaced("\nfile ", "\nfile 99999999999999999999999"));
  corrupt(replaced("c.node\n", "c.nodx\n"));                       // not a streamed format
  corrupt(replaced("d.msh.vertices.part", "d.msh.vertices.parx")); // not a file of this output
  corrupt(replaced("c.node\n", "c.svg\n"));                        // length prefix wrong

  // Any one byte changed: refused cleanly, or (a digit of the bounding box,
  // a smaller count) accepted; never anything else. Last, since an accepted
  // change of a file size truncates the file.
  for(std::size_t i = 0; i < state.size(); ++i)
    for(char c : {'0', '9', 'x', '\n', ':'}) {
      if(state[i] == c)
        continue;
      std::string s = state;
      s[i] = c;
      try {
        Writer::resume(s);
      } catch(const std::invalid_argument& e) {
        AFM_CHECK_MSG(std::string(e.what()).find("corrupt streaming writer state: ") == 0, e.what());
      } catch(const std::runtime_error&) {
      }
    }
}

AFM_TEST_CASE(test_streaming_writer_resume_missing_or_short_file)
{
  Temp_dir dir("missing");
  const Test_mesh m = grid_mesh(10, 10);
  const std::vector<std::string> names = {dir.file("a.off"), dir.file("b.node")};
  std::string state;
  {
    Writer w(names);
    stream(w, m, 0, m.events.size() / 2);
    state = w.checkpoint_state();
    stream(w, m, m.events.size() / 2, m.events.size());
  }
  auto sizes = [&] {
    std::vector<std::uintmax_t> r;
    for(const char* f : {"a.off.vertices.part", "a.off.triangles.part", "b.node.part", "b.ele.part"})
      r.push_back(fs::exists(dir.file(f)) ? fs::file_size(dir.file(f)) : 0);
    return r;
  };

  // a part file removed
  const std::string part = dir.file("a.off.triangles.part");
  fs::rename(part, part + ".away");
  const std::vector<std::uintmax_t> before = sizes();
  std::string msg = thrown_message<std::runtime_error>([&] { Writer::resume(state); });
  AFM_CHECK_MSG(msg.find(part) != std::string::npos && msg.find("missing or shorter") != std::string::npos,
                msg);
  AFM_CHECK(sizes() == before); // a failed resume truncates nothing
  fs::rename(part + ".away", part);

  // a file shorter than at the checkpoint
  const std::string node = dir.file("b.node.part");
  const std::uintmax_t node_size = fs::file_size(node);
  fs::resize_file(node, 30);
  msg = thrown_message<std::runtime_error>([&] { Writer::resume(state); });
  AFM_CHECK_MSG(msg.find(node) != std::string::npos && msg.find("missing or shorter") != std::string::npos,
                msg);

  // a file that is long enough but is not the one of the checkpoint
  fs::resize_file(node, node_size);
  msg = thrown_message<std::runtime_error>([&] { Writer::resume(state); });
  AFM_CHECK_MSG(msg.find(node) != std::string::npos && msg.find("does not match") != std::string::npos,
                msg);

  // after close(), the part files are gone
  {
    Temp_dir dir2("closed");
    std::string s2;
    {
      Writer w({dir2.file("x.msh")});
      stream(w, m, 0, 10);
      s2 = w.checkpoint_state();
      stream(w, m, 10, m.events.size());
      w.close();
    }
    msg = thrown_message<std::runtime_error>([&] { Writer::resume(s2); });
    AFM_CHECK_MSG(msg.find("x.msh.vertices.part") != std::string::npos, msg);
  }
}

// A full disk, through /dev/full where the system has it.
AFM_TEST_CASE(test_streaming_writer_write_error)
{
  if(!fs::exists("/dev/full")) {
    std::cout << "skipped: no /dev/full\n";
    return;
  }
  Temp_dir dir("full");
  const std::string out = dir.file("x.off");
  fs::create_symlink("/dev/full", out + ".vertices.part");
  const Test_mesh m = grid_mesh(5, 5);
  {
    Writer w({out});
    stream(w, m, 0, m.events.size());
    const std::string msg = thrown_message<std::runtime_error>([&] { w.checkpoint_state(); });
    AFM_CHECK_MSG(msg == "cannot write " + out + ".vertices.part", msg);
    // a writer whose outputs disagree refuses everything
    thrown_message<std::runtime_error>([&] { w.add_vertex(m.points.size(), Point(0, 0)); });
    thrown_message<std::runtime_error>([&] { w.checkpoint_state(); });
    thrown_message<std::runtime_error>([&] { w.close(); });
  } // and its destructor does not throw
  {
    // the same, found by close()
    Writer w({out});
    stream(w, m, 0, m.events.size());
    const std::string msg = thrown_message<std::runtime_error>([&] { w.close(); });
    AFM_CHECK_MSG(msg == "cannot write " + out + ".vertices.part", msg);
  }
}

// ---------------------------------------------------------------------------
// Markers and regions

// The grid with tags: vertex markers, three region attributes (0 among
// them), the grid's border as segments with a marker per side.
Test_mesh tagged_grid_mesh(std::size_t nx, std::size_t ny)
{
  Test_mesh m = grid_mesh(nx, ny);
  for(std::size_t v = 0; v < m.points.size(); ++v) m.markers.push_back(int(v % 7) - 2);
  for(std::size_t t = 0; t < m.triangles.size(); ++t) m.attributes.push_back(t % 5 == 0 ? 0. : t % 5 < 3 ? 1.5 : -7.);
  auto vid = [nx](std::size_t i, std::size_t j) { return j * (nx + 1) + i; };
  for(std::size_t i = 0; i < nx; ++i) {
    m.segments.push_back({{vid(i, 0), vid(i + 1, 0)}});
    m.segment_markers.push_back(3);
    m.segments.push_back({{vid(i + 1, ny), vid(i, ny)}});
    m.segment_markers.push_back(-4);
  }
  for(std::size_t j = 0; j < ny; ++j) {
    m.segments.push_back({{vid(nx, j), vid(nx, j + 1)}});
    m.segment_markers.push_back(0);
  }
  return m;
}

afm_io::Streaming_mesh_writer_options tag_options(bool binary = true)
{
  afm_io::Streaming_mesh_writer_options o;
  o.use_binary_mode = binary;
  o.markers = true;
  o.region_attributes = {1.5, 0., -7., 1.5}; // any order, duplicates ignored
  return o;
}

void check_tagged_node_ele_edge(const std::string& base, const Test_mesh& m)
{
  const std::vector<std::string> nt = tokens(read_text(base + ".node"));
  const std::vector<std::string> et = tokens(read_text(base + ".ele"));
  const std::vector<std::string> st = tokens(read_text(base + ".edge"));
  AFM_CHECK(read_text(base + ".node").compare(0, 27, padded_count(m.points.size()) + " 2 0 1\n") == 0);
  AFM_CHECK(read_text(base + ".ele").compare(0, 25, padded_count(m.triangles.size()) + " 3 1\n") == 0);
  AFM_CHECK(nt.size() == 4 + 4 * m.points.size() && et.size() == 3 + 5 * m.triangles.size());
  for(std::size_t i = 0, k = 4; i < m.points.size(); ++i, k += 4) {
    AFM_CHECK(to_uint(nt[k]) == i + 1);
    check_point(m, i, nt[k + 1], nt[k + 2], base + ".node");
    AFM_CHECK_MSG(std::stoi(nt[k + 3]) == m.markers[i], base << ".node: marker of " << i);
  }
  for(std::size_t i = 0, k = 3; i < m.triangles.size(); ++i, k += 5) {
    AFM_CHECK(to_uint(et[k]) == i + 1 && to_uint(et[k + 1]) == m.triangles[i][0] + 1);
    AFM_CHECK_MSG(same_bits(to_double(et[k + 4]), m.attributes[i]), base << ".ele: attribute of " << i);
  }
  AFM_CHECK(st.size() == 2 + 4 * m.segments.size() && to_uint(st[0]) == m.segments.size() && st[1] == "1");
  for(std::size_t i = 0, k = 2; i < m.segments.size(); ++i, k += 4)
    AFM_CHECK_MSG(to_uint(st[k]) == i + 1 && to_uint(st[k + 1]) == m.segments[i][0] + 1 &&
                  to_uint(st[k + 2]) == m.segments[i][1] + 1 && std::stoi(st[k + 3]) == m.segment_markers[i],
                  base << ".edge: segment " << i);
}

void check_tagged_vtu(const std::string& path, const Test_mesh& m, bool binary)
{
  const Vtu_arrays a = read_vtu_arrays(read_text(path));
  AFM_CHECK(a.binary == binary);
  const std::size_t nt = m.triangles.size(), ns = m.segments.size();
  const std::vector<std::int64_t>& conn = a.integers.at("connectivity");
  const std::vector<std::int64_t>& types = a.integers.at("types");
  const std::vector<std::int64_t>& offsets = a.integers.at("offsets");
  AFM_CHECK(conn.size() == 3 * nt + 2 * ns && types.size() == nt + ns && offsets.size() == nt + ns);
  for(std::size_t i = 0; i < ns; ++i) {
    AFM_CHECK(conn[3 * nt + 2 * i] == std::int64_t(m.segments[i][0]) &&
              conn[3 * nt + 2 * i + 1] == std::int64_t(m.segments[i][1]));
    AFM_CHECK(types[nt + i] == 3 && offsets[nt + i] == std::int64_t(3 * nt + 2 * (i + 1)));
  }
  const std::vector<std::int64_t>& pm = a.integers.at("point marker");
  AFM_CHECK(pm.size() == m.points.size());
  for(std::size_t v = 0; v < pm.size(); ++v) AFM_CHECK(pm[v] == m.markers[v]);
  const std::vector<std::int64_t>& cm = a.integers.at("cell marker");
  const std::vector<double>& region = a.reals.at("region");
  AFM_CHECK(cm.size() == nt + ns && region.size() == nt + ns);
  for(std::size_t t = 0; t < nt; ++t) AFM_CHECK(cm[t] == 0 && same_bits(region[t], m.attributes[t]));
  for(std::size_t i = 0; i < ns; ++i) AFM_CHECK(cm[nt + i] == m.segment_markers[i] && region[nt + i] == 0);
}

// The physical groups of a tagged .msh: for each element tag, the name of
// its group; node coordinates as in the mesh.
void check_tagged_msh(const std::string& path, const Test_mesh& m)
{
  const std::vector<std::string> l = lines(read_text(path));
  std::map<std::pair<int, int>, std::string> names; // (dim, physical tag)
  std::map<std::pair<int, int>, int> entity_group; // (dim, entity) -> physical tag
  std::map<std::uint64_t, std::pair<std::string, std::vector<std::uint64_t> > > elements; // tag -> group, nodes
  std::size_t k = 0;
  auto find = [&](const std::string& s) {
    while(k < l.size() && l[k] != s) ++k;
    AFM_CHECK_MSG(k < l.size(), path << ": no " << s);
    ++k;
  };
  find("$PhysicalNames");
  for(std::size_t n = to_uint(l[k++]), i = 0; i < n; ++i) {
    const std::vector<std::string> t = tokens(l[k++]);
    names[{std::stoi(t[0]), std::stoi(t[1])}] = t[2].substr(1, t[2].size() - 2);
  }
  find("$Entities");
  const std::vector<std::string> counts = tokens(l[k++]);
  AFM_CHECK(counts[0] == "0" && counts[3] == "0");
  for(int dim = 1; dim <= 2; ++dim)
    for(std::uint64_t i = 0; i < to_uint(counts[dim]); ++i) {
      const std::vector<std::string> t = tokens(l[k++]);
      AFM_CHECK(t.size() == 10 && t[7] == "1" && t[9] == "0");
      entity_group[{dim, std::stoi(t[0])}] = std::stoi(t[8]);
    }
  find("$Nodes");
  const std::vector<std::string> nh = tokens(l[k++]);
  AFM_CHECK(to_uint(nh[1]) == m.points.size());
  k += 1 + m.points.size(); // the block header and the tags
  for(std::size_t i = 0; i < m.points.size(); ++i) {
    const std::vector<std::string> c = tokens(l[k++]);
    check_point(m, i, c[0], c[1], path);
  }
  find("$Elements");
  const std::vector<std::string> eh = tokens(l[k++]);
  const std::uint64_t ne = to_uint(eh[1]);
  AFM_CHECK(ne == m.triangles.size() + m.segments.size() && eh[2] == "1" && to_uint(eh[3]) == ne);
  for(std::uint64_t b = 0, blocks = to_uint(eh[0]); b < blocks; ++b) {
    const std::vector<std::string> bh = tokens(l[k++]);
    const int dim = std::stoi(bh[0]);
    AFM_CHECK(bh[2] == (dim == 1 ? "1" : "2"));
    const std::string group = names.at({dim, entity_group.at({dim, std::stoi(bh[1])})});
    for(std::uint64_t e = 0, n = to_uint(bh[3]); e < n; ++e) {
      const std::vector<std::string> t = tokens(l[k++]);
      std::vector<std::uint64_t> nodes;
      for(std::size_t j = 1; j < t.size(); ++j) nodes.push_back(to_uint(t[j]) - 1);
      AFM_CHECK_MSG(elements.emplace(to_uint(t[0]), std::make_pair(group, nodes)).second, "element tag twice");
    }
  }
  AFM_CHECK(l[k] == "$EndElements");
  AFM_CHECK(elements.size() == ne && elements.begin()->first == 1 && elements.rbegin()->first == ne);
  // triangles first, in the order received, then the segments
  for(std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& e = elements.at(t + 1);
    const double a = m.attributes[t];
    const std::string want = a == 1.5 ? "region_1.5" : a == 0 ? "region_0" : "region_-7";
    AFM_CHECK_MSG(e.first == want && e.second == std::vector<std::uint64_t>(m.triangles[t].begin(), m.triangles[t].end()),
                  path << ": triangle " << t << " in " << e.first);
  }
  for(std::size_t i = 0; i < m.segments.size(); ++i) {
    const auto& e = elements.at(m.triangles.size() + i + 1);
    AFM_CHECK(e.first == "marker_" + std::to_string(m.segment_markers[i]));
    AFM_CHECK(e.second == std::vector<std::uint64_t>(m.segments[i].begin(), m.segments[i].end()));
  }
}

AFM_TEST_CASE(test_streaming_writer_markers_and_regions)
{
  Temp_dir dir("tagged");
  const Test_mesh m = tagged_grid_mesh(23, 17);
  for(bool binary : {true, false}) {
    const std::vector<std::string> names = {dir.file("t.node"), dir.file("t.msh"), dir.file("t.vtu"),
                                            dir.file("t.off")};
    {
      Writer w(names, tag_options(binary));
      stream(w, m, 0, m.events.size());
      for(std::size_t i = 0; i < m.segments.size(); ++i)
        w.add_segment(m.segments[i][0], m.segments[i][1], m.segment_markers[i]);
      w.close();
    }
    check_tagged_node_ele_edge(dir.file("t"), m);
    check_tagged_msh(names[1], m);
    check_tagged_vtu(names[2], m, binary);
    check_off(names[3], m);
    check_only_files(dir, {dir.file("t.node"), dir.file("t.ele"), dir.file("t.edge"), names[1], names[2], names[3]});
  }

  // interrupted and resumed: the same files
  Temp_dir ref("tagged_ref");
  const std::vector<std::string> outputs = {"a.node", "b.msh", "c.vtu"};
  std::vector<std::string> run_names, ref_names;
  for(const std::string& o : outputs) {
    run_names.push_back(dir.file(o));
    ref_names.push_back(ref.file(o));
  }
  write_with_interruptions(ref_names, m, {}, tag_options());
  const std::size_t n = m.events.size();
  write_with_interruptions(run_names, m, {{n / 3, n / 2}, {n / 2, n - 1}}, tag_options());
  for(const char* f : {"a.node", "a.ele", "a.edge", "b.msh", "c.vtu"})
    AFM_CHECK_MSG(read_text(dir.file(f)) == read_text(ref.file(f)), f << " differs after resume");

  // without regions: one surface, "domain"
  {
    Test_mesh plain = m;
    plain.attributes.clear();
    afm_io::Streaming_mesh_writer_options o;
    o.markers = true;
    Writer w({dir.file("p.msh"), dir.file("p.ele")}, o);
    stream(w, plain, 0, plain.events.size());
    w.add_segment(0, 1, 5);
    w.close();
    const std::string text = read_text(dir.file("p.msh"));
    AFM_CHECK(text.find("$PhysicalNames\n2\n1 5 \"marker_5\"\n2 1 \"domain\"\n") != std::string::npos);
    AFM_CHECK(read_text(dir.file("p.ele")).compare(0, 25, padded_count(m.triangles.size()) + " 3 0\n") == 0);
    AFM_CHECK(tokens(read_text(dir.file("p.edge"))) == (std::vector<std::string>{"1", "1", "1", "1", "2", "5"}));
  }
}

AFM_TEST_CASE(test_streaming_writer_rejects_bad_tags)
{
  Temp_dir dir("bad_tags");
  afm_io::Streaming_mesh_writer_options regions_only;
  regions_only.region_attributes = {1.};
  thrown_message<std::invalid_argument>([&] { Writer w({dir.file("a.off")}, regions_only); });
  afm_io::Streaming_mesh_writer_options nan = tag_options();
  nan.region_attributes.push_back(std::numeric_limits<double>::quiet_NaN());
  thrown_message<std::invalid_argument>([&] { Writer w({dir.file("a.off")}, nan); });
  check_only_files(dir, {});
  {
    Writer w({dir.file("a.off")});
    w.add_vertex(0, Point(0, 0));
    w.add_vertex(1, Point(1, 0));
    thrown_message<std::logic_error>([&] { w.add_segment(0, 1, 1); }); // no markers
  }
  {
    Writer w({dir.file("b.vtu")}, tag_options());
    w.add_vertex(0, Point(0, 0), 1);
    w.add_vertex(1, Point(1, 0), 1);
    w.add_vertex(2, Point(0, 1), 1);
    thrown_message<std::invalid_argument>([&] { w.add_triangle(0, 1, 2, 2.5); }); // not announced
    w.add_triangle(0, 1, 2, -7.);
    thrown_message<std::logic_error>([&] { w.add_segment(0, 3, 1); });
    w.add_segment(0, 1, 1);
    thrown_message<std::logic_error>([&] { w.checkpoint_state(); }); // segments are not checkpointed
    w.close();
  }
  // the writer of a.off was abandoned: its part files stay, for a resume
  check_only_files(dir, {dir.file("b.vtu"), dir.file("a.off.vertices.part"), dir.file("a.off.triangles.part")});
}

// Until close(), no file under a final name: the constructor removes those
// of an earlier run, and a writer that dies leaves only its part files.
AFM_TEST_CASE(test_streaming_writer_no_final_file_before_close)
{
  Temp_dir dir("interrupted");
  const Test_mesh m = tagged_grid_mesh(8, 9);
  const std::vector<std::string> finals = {dir.file("a.off"), dir.file("b.vtu"), dir.file("c.msh"),
                                           dir.file("d.node"), dir.file("d.ele"), dir.file("d.edge")};
  for(const std::string& f : finals) std::ofstream(f.c_str()) << "a mesh of an earlier run\n";
  std::string state;
  {
    Writer w({finals[0], finals[1], finals[2], finals[3]}, tag_options());
    for(const std::string& f : finals) AFM_CHECK_MSG(!fs::exists(f), f << " was not removed");
    stream(w, m, 0, m.events.size() / 2);
    state = w.checkpoint_state();
    stream(w, m, m.events.size() / 2, m.events.size());
  } // dies before close()
  for(const std::string& f : finals) AFM_CHECK_MSG(!fs::exists(f), f << " exists before close()");
  std::unique_ptr<Writer> w = Writer::resume(state);
  stream(*w, m, m.events.size() / 2, m.events.size());
  for(std::size_t i = 0; i < m.segments.size(); ++i)
    w->add_segment(m.segments[i][0], m.segments[i][1], m.segment_markers[i]);
  for(const std::string& f : finals) AFM_CHECK(!fs::exists(f));
  w->close();
  check_only_files(dir, finals);
  check_tagged_node_ele_edge(dir.file("d"), m);
  check_tagged_vtu(finals[1], m, true);
  check_tagged_msh(finals[2], m);

  // a final name that is a directory is refused before anything is written
  Temp_dir dir2("final_is_dir");
  fs::create_directory(dir2.file("x.off"));
  const std::string msg = thrown_message<std::runtime_error>([&] { Writer w2({dir2.file("x.off")}); });
  AFM_CHECK_MSG(msg.find("cannot write") == 0, msg);
}

} // namespace
