// Streaming mode and the restart facility (Mavriplis 1992, section 4):
// finished triangles go to a sink while meshing, the mesh they make is the
// mesh of the same run without streaming, and a run resumed from a
// checkpoint gives the sink exactly what the uninterrupted run gives.
#include "afm_test_harness.h"
#include "afm_test_mesh.h"
#include "afm_geometries.h"
#include "afm_hard_inputs.h"
#include "afm_robustness_catalogue.h"
#include "afm_brute_force_indices.h"

#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Advancing_front_mesh_2/Kd_tree_point_index.h>
#include <CGAL/Advancing_front_mesh_2/internal/Binary_io.h>
#include <CGAL/Advancing_front_mesh_2/internal/Durable_files.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

namespace AFM = CGAL::Advancing_front_mesh_2;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef std::array<double, 6> Canonical_triangle;

// The checkpoint tests need search structures that can be saved; with the
// others (the Kd_tree and brute-force builds of the tests) they are skipped,
// and test_streaming_checkpoints_need_saveable_indices checks that
// checkpoints are refused instead.
bool checkpoints_skipped()
{
  if(afm_test::Mesher<afm_test::Types<Epick>::CDT>::supports_checkpoints) return false;
  std::cout << "  skipped: the " << afm_test::search_structures() << " cannot be saved\n";
  return true;
}

// Records every call in order; its checkpoint state is the number of calls
// so far, and a sink resumed from it starts from the recorded calls cut
// back to that point (as a file writer truncates its files).
template <class Point>
struct Recording_sink : AFM::Mesh_sink_2<Point>
{
  std::vector<std::array<double, 2> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
  std::vector<std::size_t> order; // 0: a vertex, 1: a triangle, in call order
  bool misnumbered = false;

  void add_vertex(std::size_t i, const Point& p) override
  {
    if(i != points.size()) misnumbered = true;
    points.push_back({{CGAL::to_double(p.x()), CGAL::to_double(p.y())}});
    order.push_back(0);
  }
  void add_triangle(std::size_t i, std::size_t j, std::size_t k) override
  {
    if(i >= points.size() || j >= points.size() || k >= points.size()) misnumbered = true;
    triangles.push_back({{i, j, k}});
    order.push_back(1);
  }
  std::string checkpoint_state() override
  {
    return std::to_string(points.size()) + " " + std::to_string(triangles.size()) + " " + std::to_string(order.size());
  }
  void resume_from(const Recording_sink& interrupted, const std::string& state)
  {
    std::size_t nv = 0, nt = 0, no = 0;
    AFM_CHECK(std::sscanf(state.c_str(), "%zu %zu %zu", &nv, &nt, &no) == 3);
    points.assign(interrupted.points.begin(), interrupted.points.begin() + nv);
    triangles.assign(interrupted.triangles.begin(), interrupted.triangles.begin() + nt);
    order.assign(interrupted.order.begin(), interrupted.order.begin() + no);
  }

  afm_check::Mesh mesh() const
  {
    afm_check::Mesh m;
    m.vertices = points;
    m.triangles = triangles;
    return m;
  }
};

template <class Point>
Canonical_triangle canonical(const Point& a, const Point& b, const Point& c)
{
  const std::array<std::array<double, 2>, 3> v = {{{{CGAL::to_double(a.x()), CGAL::to_double(a.y())}},
                                                   {{CGAL::to_double(b.x()), CGAL::to_double(b.y())}},
                                                   {{CGAL::to_double(c.x()), CGAL::to_double(c.y())}}}};
  int f = 0;
  for(int i = 1; i < 3; ++i)
    if(v[i] < v[f]) f = i;
  return {{v[f][0], v[f][1], v[(f + 1) % 3][0], v[(f + 1) % 3][1], v[(f + 2) % 3][0], v[(f + 2) % 3][1]}};
}

template <class Point>
std::multiset<Canonical_triangle> canonical(const Recording_sink<Point>& s)
{
  std::multiset<Canonical_triangle> out;
  for(const auto& t : s.triangles) {
    const auto& a = s.points[t[0]];
    const auto& b = s.points[t[1]];
    const auto& c = s.points[t[2]];
    out.insert(canonical(Point(a[0], a[1]), Point(b[0], b[1]), Point(c[0], c[1])));
  }
  return out;
}

struct Counting_visitor : AFM::Default_visitor
{
  std::size_t* finished = nullptr;
  template <class Face_handle> void on_face_finished(Face_handle) { ++*finished; }
};

std::filesystem::path scratch_directory()
{
  const std::filesystem::path dir =
    std::filesystem::temp_directory_path() / ("afm_streaming_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir;
}

// The streamed triangles are the in-core ones, checked, with every
// vertex written once and used; with a small sweep interval the finished
// triangles leave memory while the run goes on.
template <class K, class Sizing>
void check_streaming(const afm_test::Poly_data& in, const Sizing& sizing, const std::string& label,
                     std::size_t sweep_interval)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  typedef typename K::Point_2 Point;
  std::multiset<Canonical_triangle> in_core;
  {
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    const auto seeds = afm_test::seeds_of<CDT>(in);
    afm_test::Mesher<CDT, Sizing> mesher(cdt, sizing);
    mesher.set_seeds(seeds.begin(), seeds.end());
    mesher.refine_mesh();
    for(auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if(f->is_in_domain())
        in_core.insert(canonical(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
  }
  CDT cdt;
  afm_test::build_cdt(cdt, in);
  const auto seeds = afm_test::seeds_of<CDT>(in);
  Recording_sink<Point> sink;
  std::size_t finished = 0;
  Counting_visitor visitor;
  visitor.finished = &finished;
  afm_test::Mesher<CDT, Sizing, Counting_visitor> mesher(cdt, sizing, visitor);
  mesher.set_seeds(seeds.begin(), seeds.end());
  mesher.set_output_sink(&sink);
  mesher.set_sweep_interval(sweep_interval);
  AFM_CHECK(mesher.refine_mesh() == AFM::MESH_COMPLETE);
  const AFM::Statistics& st = mesher.statistics();
  AFM_CHECK_MSG(!sink.misnumbered, label << ": vertices not numbered 0, 1, 2, ... before their use");
  AFM_CHECK_MSG(cdt.number_of_vertices() == 0, label << ": the triangulation is not left empty");
  AFM_CHECK_MSG(st.points_refused_for_finished_triangles == 0,
                label << ": " << st.points_refused_for_finished_triangles
                      << " points refused because their cavity reached finished triangles ("
                      << st.finished_triangles_broken << " would have broken one)");
  // the check of the finished triangles (no final Lawson pass here) found
  // nothing to repair
  AFM_CHECK_MSG(st.delaunay_repair_flips == 0 && st.finished_triangles_held == 0 &&
                  st.finished_edges_not_delaunay == 0,
                label << ": finished triangles not Delaunay: " << st.delaunay_repair_flips << " flipped, "
                      << st.finished_triangles_held << " held, " << st.finished_edges_not_delaunay << " unrepaired");
  AFM_CHECK_MSG(canonical(sink) == in_core, label << ": the streamed triangles differ from the in-core mesh ("
                                                  << sink.triangles.size() << " vs " << in_core.size() << ")");
  AFM_CHECK_MSG(finished == sink.triangles.size() && st.number_of_faces == sink.triangles.size() &&
                  st.number_of_vertices == sink.points.size(),
                label << ": counts disagree");
  std::vector<bool> used(sink.points.size(), false);
  for(const auto& t : sink.triangles)
    for(std::size_t v : t) used[v] = true;
  AFM_CHECK_MSG(std::find(used.begin(), used.end(), false) == used.end(), label << ": a vertex no triangle uses");
  const afm_check::Report report = afm_test::check_split_mesh(in, sink.mesh());
  AFM_CHECK_MSG(report.ok, label << ": " << report.summary());
  std::cout << "  " << label << ": " << sink.triangles.size() << " triangles, at most "
            << st.largest_triangles_in_memory << " in memory, " << st.stream_sweeps << " sweeps\n";
}

} // namespace

AFM_TEST_CASE(test_streaming_equals_in_core)
{
  // small sweep intervals: the triangles leave memory early and often,
  // which is where a wrong test of "finished" would show
  for(const afm_robustness::Case& c : afm_robustness::catalogue())
    check_streaming<Epick>(c.in, afm_robustness::Case_size<Epick>(c), c.name, 16);
  const auto square = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.01);
  check_streaming<Epick>(square, afm_test::uniform<Epick>(0.01), "square with hole, h = 0.01", 1);
  check_streaming<Epick>(square, afm_test::uniform<Epick>(0.01), "square with hole, h = 0.01", 4096);
  check_streaming<Epeck>(afm_geometry::multi_element_airfoil(10, 32),
                         afm_test::Boundary_graded_size<Epeck>(afm_geometry::multi_element_airfoil(10, 32), 0.3),
                         "four-element airfoil, Epeck", 64);
}

AFM_TEST_CASE(test_streaming_memory_stays_near_the_front)
{
  typedef afm_test::Types<Epick>::CDT CDT;
  const auto square = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.004);
  CDT cdt;
  afm_test::build_cdt(cdt, square);
  const auto seeds = afm_test::seeds_of<CDT>(square);
  AFM::Mesh_sink_2<Epick::Point_2> discard;
  afm_test::Mesher<CDT> mesher(cdt, AFM::Uniform_sizing_field_2<Epick>(0.004));
  mesher.set_seeds(seeds.begin(), seeds.end());
  mesher.set_output_sink(&discard);
  mesher.refine_mesh();
  const AFM::Statistics& st = mesher.statistics();
  std::cout << "  " << st.number_of_faces << " triangles, at most " << st.largest_triangles_in_memory
            << " in memory, largest front " << st.largest_front << " edges\n";
  // A band along the front, not the mesh: the triangles within about five
  // target circumradii of the front (the disk of the finished test and the
  // neighbours' disks), up to twice as many between two sweeps. Here
  // 17,060 of 116,699 triangles (14.6%; 6.1 per edge of the largest front, 2,791 edges); at 10M
  // 3.2% (319,900), at 100M 2.6% (2,626,021).
  AFM_CHECK_MSG(st.number_of_faces > 100000, st.number_of_faces);
  AFM_CHECK_MSG(st.largest_triangles_in_memory < 16 * st.largest_front, st.largest_triangles_in_memory);
  AFM_CHECK_MSG(st.largest_triangles_in_memory * 5 < st.number_of_faces, st.largest_triangles_in_memory);
}

namespace {

// A run interrupted after its first checkpoint (and a few hundred steps
// more, whose output a resumed run must discard), resumed in a new mesher
// and triangulation: the sink receives exactly the calls of the
// uninterrupted run.
template <class K, class Sizing>
void check_resume(const afm_test::Poly_data& in, const Sizing& sizing, const std::string& label,
                  std::size_t every, std::size_t sweep_interval)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  typedef typename K::Point_2 Point;
  typedef afm_test::Mesher<CDT, Sizing> Mesher;
  const std::filesystem::path dir = scratch_directory();
  const std::string file = (dir / "run.checkpoint").string();
  const auto seeds = afm_test::seeds_of<CDT>(in);

  Recording_sink<Point> whole;
  AFM::Statistics whole_stats;
  {
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    Mesher mesher(cdt, sizing);
    mesher.set_seeds(seeds.begin(), seeds.end());
    mesher.set_output_sink(&whole);
    mesher.set_sweep_interval(sweep_interval);
    mesher.refine_mesh();
    whole_stats = mesher.statistics();
  }
  Recording_sink<Point> first;
  std::size_t checkpoints = 0;
  {
    CDT cdt;
    afm_test::build_cdt(cdt, in);
    Mesher mesher(cdt, sizing);
    mesher.set_seeds(seeds.begin(), seeds.end());
    mesher.set_output_sink(&first);
    mesher.set_sweep_interval(sweep_interval);
    mesher.set_checkpoint(every, file, "user data");
    std::size_t after = 0;
    while(mesher.step_by_step_refine_mesh()) {
      if(mesher.statistics().checkpoints_written > 0 && ++after == 300) break;
    }
    checkpoints = mesher.statistics().checkpoints_written;
    // abandoned here, as by a crash: nothing is finished
  }
  AFM_CHECK_MSG(checkpoints > 0, label << ": no checkpoint was written");
  const typename Mesher::Checkpoint_info info = Mesher::read_checkpoint_info(file);
  AFM_CHECK(info.user_data == "user data");
  Recording_sink<Point> resumed;
  resumed.resume_from(first, info.sink_state);
  AFM_CHECK(info.vertices_written == resumed.points.size() && info.triangles_written == resumed.triangles.size());
  CDT empty;
  Mesher mesher(empty, sizing);
  mesher.set_output_sink(&resumed);
  mesher.resume(file);
  AFM_CHECK(mesher.refine_mesh() == AFM::MESH_COMPLETE);
  const AFM::Statistics& st = mesher.statistics();
  AFM_CHECK_MSG(resumed.order == whole.order && resumed.points == whole.points && resumed.triangles == whole.triangles,
                label << ": the resumed run gave " << resumed.triangles.size() << " triangles, the uninterrupted one "
                      << whole.triangles.size() << " (or the same in another order or numbering)");
  AFM_CHECK_MSG(st.points_inserted == whole_stats.points_inserted &&
                  st.front_edges_processed == whole_stats.front_edges_processed &&
                  st.largest_front == whole_stats.largest_front && st.number_of_faces == whole_stats.number_of_faces,
                label << ": the statistics differ");
  AFM_CHECK_MSG(empty.number_of_vertices() == 0, label << ": the triangulation is not left empty");
  std::cout << "  " << label << ": resumed after " << info.triangles_written << " of " << whole.triangles.size()
            << " triangles: same output\n";
  std::filesystem::remove_all(dir);
}

} // namespace

AFM_TEST_CASE(test_streaming_resume_equals_uninterrupted)
{
  if(checkpoints_skipped()) return;
  for(const afm_robustness::Case& c : afm_robustness::catalogue())
    // every 10 triangles: on "many holes" the mesh grades away from the
    // holes in layers, and only 17 triangles are finished before the last
    // steps
    check_resume<Epick>(c.in, afm_robustness::Case_size<Epick>(c), c.name, 10, 8);
  const auto square = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.01);
  check_resume<Epick>(square, afm_test::uniform<Epick>(0.01), "square with hole, h = 0.01", 5000, 4096);
  // a centre where 60 constraints meet: the hubs of the front and of the
  // constraints (Front_hubs.h, Constraint_hubs.h) go through the checkpoint
  check_resume<Epick>(afm_hard_inputs::constraint_star(60), afm_test::uniform<Epick>(0.05), "star of 60 spokes", 10, 8);
  const auto airfoil = afm_geometry::multi_element_airfoil(10, 32);
  check_resume<Epeck>(airfoil, afm_test::Boundary_graded_size<Epeck>(airfoil, 0.3), "four-element airfoil, Epeck",
                      1000, 64);
}

namespace {

// Meshes the square with a hole at uniform size h until its first
// checkpoint, written to `file`, and returns the checkpoint's bytes.
std::string stopped_checkpoint(const std::string& file, double h, std::size_t sweep_interval, std::size_t every)
{
  typedef afm_test::Types<Epick>::CDT CDT;
  Recording_sink<Epick::Point_2> sink;
  CDT cdt;
  afm_test::build_cdt(cdt, afm_geometry::square_with_circular_hole(1.0, 0.25, h));
  afm_test::Mesher<CDT> mesher(cdt, AFM::Uniform_sizing_field_2<Epick>(h));
  mesher.set_output_sink(&sink);
  mesher.set_sweep_interval(sweep_interval);
  mesher.set_checkpoint(every, file, "", true);
  AFM_CHECK(mesher.refine_mesh() == AFM::STOPPED_AT_CHECKPOINT);
  std::ifstream is(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(is), std::istreambuf_iterator<char>());
}

} // namespace

// A checkpoint depends on the input and the options only (no times): the
// same run writes the same bytes, which is what lets a refactoring be
// proven a pure move by comparing checkpoints.
AFM_TEST_CASE(test_streaming_checkpoint_is_deterministic)
{
  if(checkpoints_skipped()) return;
  const std::string file = (scratch_directory() / "deterministic.checkpoint").string();
  const std::string first = stopped_checkpoint(file, 0.01, 256, 4000);
  const std::string second = stopped_checkpoint(file, 0.01, 256, 4000);
  AFM_CHECK(first.size() > 1000);
  AFM_CHECK_MSG(first == second, "two runs wrote different checkpoints (" << first.size() << " and "
                                                                            << second.size() << " bytes)");
  std::filesystem::remove(file);
}

AFM_TEST_CASE(test_streaming_checkpoint_errors)
{
  if(checkpoints_skipped()) return;
  typedef afm_test::Types<Epick>::CDT CDT;
  typedef afm_test::Types<Epeck>::CDT CDT_exact;
  typedef afm_test::Mesher<CDT> Mesher;
  const std::filesystem::path dir = scratch_directory();
  const std::string file = (dir / "run.checkpoint").string();
  const auto square = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.05);
  Recording_sink<Epick::Point_2> sink;
  const std::string bytes = stopped_checkpoint(file, 0.05, 16, 50);
  AFM_CHECK(bytes.size() > 1000);
  auto resume_fails = [&](const std::string& content, const std::string& what) {
    const std::string bad = (dir / "bad.checkpoint").string();
    std::ofstream(bad, std::ios::binary) << content;
    Recording_sink<Epick::Point_2> s;
    CDT empty;
    Mesher mesher(empty, AFM::Uniform_sizing_field_2<Epick>(0.05));
    mesher.set_output_sink(&s);
    bool thrown = false;
    try {
      mesher.resume(bad);
    } catch(const std::runtime_error& e) {
      thrown = std::string(e.what()).find(bad) == 0;
    }
    AFM_CHECK_MSG(thrown, what << ": not refused with a message naming the file");
    AFM_CHECK_MSG(empty.number_of_vertices() == 0 && empty.tds().number_of_faces() == 0,
                  what << ": left something in the triangulation");
  };
  for(std::size_t at : {std::size_t(100), bytes.size() / 3, bytes.size() / 2, bytes.size() - 20}) {
    std::string flipped = bytes;
    flipped[at] = char(flipped[at] ^ 0x5a);
    resume_fails(flipped, "a byte flipped at " + std::to_string(at));
  }
  resume_fails(bytes.substr(0, bytes.size() / 2), "truncated");
  resume_fails("", "empty");
  resume_fails("not a checkpoint at all", "garbage");
  {
    // another kernel
    CDT_exact empty;
    afm_test::Mesher<CDT_exact> mesher(empty, AFM::Uniform_sizing_field_2<Epeck>(0.05));
    Recording_sink<Epeck::Point_2> s;
    mesher.set_output_sink(&s);
    bool thrown = false;
    try {
      mesher.resume(file);
    } catch(const std::runtime_error& e) {
      thrown = std::string(e.what()).find("kernel") != std::string::npos;
    }
    AFM_CHECK(thrown);
  }
  {
    // not empty, no sink
    CDT cdt;
    afm_test::build_cdt(cdt, square);
    Mesher mesher(cdt, AFM::Uniform_sizing_field_2<Epick>(0.05));
    bool thrown = false;
    try {
      mesher.resume(file);
    } catch(const std::logic_error&) {
      thrown = true;
    }
    AFM_CHECK_MSG(thrown, "resumed without a sink");
    mesher.set_output_sink(&sink);
    thrown = false;
    try {
      mesher.resume(file);
    } catch(const std::logic_error&) {
      thrown = true;
    }
    AFM_CHECK_MSG(thrown, "resumed into a triangulation that is not empty");
  }
  std::filesystem::remove_all(dir);
}

// A checkpoint that passes its checksum but whose content is inconsistent
// (made by hand, or by a bug) is refused, or, where the change is harmless
// to the mesher's structures (a coordinate, a statistic), resumed: never a
// crash (this test runs under AddressSanitizer too). Every 4-byte word of
// the state is changed in turn, to values that index nothing, the ghost
// face, zero and the next index, and the checksum is made right again.
AFM_TEST_CASE(test_streaming_checkpoint_consistency_is_checked)
{
  if(checkpoints_skipped()) return;
  typedef afm_test::Types<Epick>::CDT CDT;
  typedef afm_test::Mesher<CDT> Mesher;
  const std::filesystem::path dir = scratch_directory();
  const std::string file = (dir / "run.checkpoint").string();
  const std::string bad = (dir / "bad.checkpoint").string();
  const std::string bytes = stopped_checkpoint(file, 0.1, 8, 40);
  const std::size_t body = bytes.size() - sizeof(std::uint64_t);
  std::size_t refused = 0, resumed = 0;
  const std::uint32_t values[] = {0xffffffffu, 0xfffffffeu, 0u, 1u};
  for(std::size_t at = 0, n = 0; at + 4 <= body; at += 4, ++n) {
    std::string content = bytes;
    std::uint32_t word;
    std::memcpy(&word, &content[at], 4);
    const std::uint32_t changed = (n % 4 == 3) ? word + 1 : values[n % 4];
    if(changed == word) continue;
    std::memcpy(&content[at], &changed, 4);
    const std::uint64_t h = AFM::internal::fnv1a_update(AFM::internal::fnv1a_offset_basis, content.data(), body);
    std::memcpy(&content[body], &h, sizeof h);
    std::ofstream(bad, std::ios::binary | std::ios::trunc) << content;
    Recording_sink<Epick::Point_2> s;
    CDT empty;
    Mesher mesher(empty, AFM::Uniform_sizing_field_2<Epick>(0.1));
    mesher.set_output_sink(&s);
    try {
      mesher.resume(bad);
    } catch(const std::runtime_error& e) {
      AFM_CHECK_MSG(std::string(e.what()).find(bad) == 0, "byte " << at << ": " << e.what());
      AFM_CHECK_MSG(empty.number_of_vertices() == 0 && empty.tds().number_of_faces() == 0,
                    "byte " << at << ": a refused checkpoint left something in the triangulation");
      ++refused;
      continue;
    } catch(const std::exception& e) {
      // a Point the kernel rejects, an allocation too large: refused too
      ++refused;
      continue;
    }
    ++resumed;
    // whatever the change did, meshing ends (the limit guards against a
    // front that a changed coordinate made inconsistent)
    mesher.set_iteration_limit(20000);
    try {
      mesher.refine_mesh();
    } catch(const std::exception&) {
    }
  }
  std::cout << "  " << body / 4 << " words changed: " << refused << " checkpoints refused, " << resumed
            << " resumed\n";
  // most words are indices, counts or structure: at least a quarter of the
  // changes must be caught (48% are, the rest change coordinates, statistics
  // or tree bounds, which the mesher tolerates)
  AFM_CHECK_MSG(refused * 4 > body / 4, refused);
  std::filesystem::remove_all(dir);
}

// A checkpoint is made durable before it is renamed into place:
// sync_file() succeeds on a written file and fails on one that is not
// there (so a checkpoint whose temporary file vanished is not renamed).
AFM_TEST_CASE(test_durable_files)
{
  const std::filesystem::path dir = scratch_directory();
  const std::string written = (dir / "durable.bin").string();
  {
    std::ofstream os(written, std::ios::binary);
    os << "content";
  }
  AFM_CHECK(AFM::internal::sync_file(written));
  AFM_CHECK(!AFM::internal::sync_file((dir / "not-there.bin").string()));
  AFM::internal::sync_directory_of(written); // must not throw or fail
  AFM::internal::sync_directory_of("relative-name-in-the-working-directory");
  std::filesystem::remove(written);
}

// A checkpoint that cannot be written stops refine_mesh() with
// Checkpoint_error and nothing else: the front is not closed, and once the
// checkpoint can be written again the run goes on to the output of a run
// that never failed.
AFM_TEST_CASE(test_streaming_checkpoint_write_failure_is_retried)
{
  if(checkpoints_skipped()) return;
  typedef afm_test::Types<Epick>::CDT CDT;
  typedef afm_test::Mesher<CDT> Mesher;
  const std::filesystem::path dir = scratch_directory();
  const auto square = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.02);
  Recording_sink<Epick::Point_2> whole;
  {
    CDT cdt;
    afm_test::build_cdt(cdt, square);
    Mesher mesher(cdt, AFM::Uniform_sizing_field_2<Epick>(0.02));
    mesher.set_output_sink(&whole);
    mesher.set_sweep_interval(64);
    AFM_CHECK(mesher.refine_mesh() == AFM::MESH_COMPLETE);
  }
  Recording_sink<Epick::Point_2> sink;
  CDT cdt;
  afm_test::build_cdt(cdt, square);
  Mesher mesher(cdt, AFM::Uniform_sizing_field_2<Epick>(0.02));
  mesher.set_output_sink(&sink);
  mesher.set_sweep_interval(64);
  const std::string unwritable = (dir / "no such directory" / "run.checkpoint").string();
  mesher.set_checkpoint(500, unwritable);
  bool thrown = false;
  try {
    mesher.refine_mesh();
  } catch(const AFM::Checkpoint_error& e) {
    thrown = std::string(e.what()).find(unwritable) == 0;
  }
  AFM_CHECK_MSG(thrown, "no Checkpoint_error naming the file");
  AFM_CHECK(!mesher.is_refinement_done() && mesher.front_size() > 0 && mesher.is_front_valid());
  AFM_CHECK(mesher.statistics().checkpoints_written == 0);
  AFM_CHECK(!std::filesystem::exists(unwritable + ".tmp"));
  const std::size_t written = sink.triangles.size();
  AFM_CHECK(written >= 500 && written < whole.triangles.size());
  // the disk has room again: the checkpoint is written at the next sweep
  const std::string file = (dir / "run.checkpoint").string();
  mesher.set_checkpoint(500, file);
  AFM_CHECK(mesher.refine_mesh() == AFM::MESH_COMPLETE);
  AFM_CHECK(mesher.statistics().checkpoints_written > 0 && std::filesystem::exists(file));
  AFM_CHECK_MSG(sink.order == whole.order && sink.points == whole.points && sink.triangles == whole.triangles,
                "the run that went on after the failed checkpoint differs from one that never failed");
  std::filesystem::remove_all(dir);
}

namespace {

// A mesher whose point index or circle index cannot be saved meshes in every
// mode, streaming included, and refuses checkpoints with a clear error.
template <class Mesher>
void check_checkpoints_refused(const std::string& label)
{
  typedef typename Mesher::Triangulation CDT;
  static_assert(!Mesher::supports_checkpoints, "the models cannot be saved");
  const std::string file = (scratch_directory() / "refused.checkpoint").string();
  auto refused = [&](const std::function<void()>& call, const std::string& what) {
    try {
      call();
    } catch(const std::logic_error& e) {
      AFM_CHECK_MSG(std::string(e.what()).find("checkpoints need search structures that can be saved") !=
                      std::string::npos,
                    label << ", " << what << ": " << e.what());
      return;
    }
    AFM_CHECK_MSG(false, label << ", " << what << ": accepted");
  };
  const auto square = afm_geometry::square_with_circular_hole(1.0, 0.25, 0.05);
  CDT cdt;
  afm_test::build_cdt(cdt, square);
  const auto seeds = afm_test::seeds_of<CDT>(square);
  Recording_sink<Epick::Point_2> sink;
  Mesher mesher(cdt, AFM::Uniform_sizing_field_2<Epick>(0.05));
  mesher.set_seeds(seeds.begin(), seeds.end());
  mesher.set_output_sink(&sink);
  mesher.set_sweep_interval(16);
  refused([&] { mesher.set_checkpoint(100, file); }, "set_checkpoint()");
  mesher.set_checkpoint(0, file); // switching them off is fine
  refused([&] { mesher.write_checkpoint(file); }, "write_checkpoint()");
  AFM_CHECK(mesher.refine_mesh() == AFM::MESH_COMPLETE);
  AFM_CHECK_MSG(!std::ifstream(file), label << ": a checkpoint was written");
  const afm_check::Report report = afm_check::check_mesh(afm_test::to_pslg(square), sink.mesh());
  AFM_CHECK_MSG(report.ok, label << ": " << report.summary());
  CDT empty;
  Mesher resumed(empty, AFM::Uniform_sizing_field_2<Epick>(0.05));
  resumed.set_output_sink(&sink);
  refused([&] { resumed.resume(file); }, "resume()");
  std::cout << "  " << label << ": " << sink.triangles.size() << " triangles streamed, checkpoints refused\n";
}

} // namespace

AFM_TEST_CASE(test_streaming_checkpoints_need_saveable_indices)
{
  typedef afm_test::Types<Epick>::CDT CDT;
  typedef AFM::Uniform_sizing_field_2<Epick> Uniform;
  static_assert(CGAL::Advancing_front_mesher_2<CDT>::supports_checkpoints, "the default models can be saved");
  check_checkpoints_refused<CGAL::Advancing_front_mesher_2<CDT, Uniform, AFM::Default_visitor,
                                                           AFM::Kd_tree_point_index> >("Kd_tree point index");
  check_checkpoints_refused<CGAL::Advancing_front_mesher_2<CDT, Uniform, AFM::Default_visitor, CGAL::Default,
                                                           afm_test::Brute_force_circle_index<> > >(
    "brute-force circle index");
}
