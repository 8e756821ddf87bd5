// What the mesher does with inexact predicates: every geometry of the
// robustness catalogue (the tests' kernel matrix) and the real inputs of
// ../shared/data meshed with CGAL::Simple_cartesian<double>, whose
// orientation and in-circle tests are plain floating point, next to Epick
// (exact predicates, the same double constructions) as the reference.
//
// Each run happens in a child process with a time limit, so that a crash,
// an assertion, an exception or a hang is recorded as an outcome instead of
// ending the report. Every mesh that comes back is checked by the tests'
// independent validity checker (exact arithmetic) and compared with the
// Epick mesh of the same input.
//
//   inexact_kernel_report [--data SHARED_DATA_DIR] [--time-limit S] [--only SUBSTRING]
//
// Prints a Markdown table (scripts/inexact_kernel_report.sh puts it into
// the user manual).
#include "afm_gmsh_geo.h"
#include "afm_robustness_catalogue.h"
#include "afm_shared_data.h"
#include "afm_test_mesh.h"

#include <CGAL/Advancing_front_mesh_2/IO/insert_poly.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Simple_cartesian<double> Inexact;
typedef afm_test::Poly_data Poly_data;

// an input and its size, as in the tests' kernel matrix
typedef afm_robustness::Case Input;

// What one run produced, as sent from the child to the parent.
struct Outcome
{
  std::string kind = "no result";  // "mesh", "exception", "crash", "hang", "refused"
  std::string detail;
  std::size_t triangles = 0, vertices = 0, forced = 0, repair_flips = 0;
  bool valid = false;
  double mean_quality = 0, min_quality = 0, seconds = 0;
  std::size_t fingerprint = 0;  // of the vertex coordinates and triangles, to compare meshes
  std::string cgal_is_valid;    // what the triangulation's own is_valid() said, with the same kernel
};

// The child's end of the pipe: the stage it is in goes there before the
// result, so that a crash can be placed.
int child_fd = -1;

void send(const std::string& s)
{
  std::size_t written = 0;
  while(written < s.size()) {
    const ssize_t w = write(child_fd, s.data() + written, s.size() - written);
    if(w <= 0) break;
    written += std::size_t(w);
  }
}

std::string one_line(std::string s)
{
  for(char& c : s)
    if(c == '\n' || c == '\t' || c == '|') c = ' ';
  if(s.size() > 160) s = s.substr(0, 157) + "...";
  return s;
}

std::size_t fingerprint(const afm_check::Mesh& m)
{
  // the order-independent sum of hashes of the triangles' coordinates
  std::size_t sum = 0;
  std::hash<double> hd;
  for(const auto& t : m.triangles) {
    std::size_t h = 0;
    for(int i = 0; i < 3; ++i)
      h += (hd(m.vertices[t[i]][0]) * 31 + hd(m.vertices[t[i]][1])) * 0x9e3779b97f4a7c15ull;
    sum += h ^ (h >> 29);
  }
  return sum;
}

template <class K>
Outcome mesh_one(const Input& input, double time_limit)
{
  typedef typename afm_test::Types<K>::CDT CDT;
  afm_robustness::Case_size<K> size(input);
  Outcome o;
  CDT cdt;
  CGAL::Advancing_front_mesh_2::IO::Poly_insertion<CDT> inserted;
  send("stage building the constrained triangulation\n");
  try {
    inserted = CGAL::Advancing_front_mesh_2::IO::insert_poly(cdt, input.in);
  } catch(const CGAL::Advancing_front_mesh_2::IO::Poly_read_error& e) {
    o.kind = "refused";
    o.detail = e.what();
    return o;
  }
  send("stage meshing\n");
  const auto start = std::chrono::steady_clock::now();
  CGAL::Advancing_front_mesher_2<CDT, afm_robustness::Case_size<K> > mesher(cdt, size);
  // the paper's mode, in which the manual's figures were measured (these
  // inputs' boundaries are at the size)
  mesher.set_constraint_splitting(false);
  mesher.set_seeds(inserted.hole_seeds.begin(), inserted.hole_seeds.end());
  mesher.set_time_limit(time_limit);
  const auto code = mesher.refine_mesh();
  o.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if(code != CGAL::Advancing_front_mesh_2::MESH_COMPLETE) o.detail = "return code " + std::to_string(int(code));
  const auto& st = mesher.statistics();
  o.kind = "mesh";
  o.forced = st.forced_closures;
  o.repair_flips = st.delaunay_repair_flips;
  send("stage checking\n");
  const afm_check::Mesh m = afm_test::extract_mesh(cdt);
  o.fingerprint = fingerprint(m);
  const afm_check::Report r = afm_test::check_split_mesh(input.in, m);
  o.valid = r.ok;
  o.triangles = r.n_triangles;
  o.vertices = r.n_vertices;
  o.mean_quality = r.mean_radius_ratio;
  o.min_quality = r.min_radius_ratio;
  if(!r.ok) {
    std::ostringstream os;
    for(const auto& kc : r.error_counts) os << (os.tellp() > 0 ? ", " : "") << kc.first << " x" << kc.second;
    o.detail += (o.detail.empty() ? "" : "; ") + os.str();
  }
  // CGAL's own test decides with the kernel's predicates, so with inexact
  // ones it can fail on a mesh the exact checker accepts
  send("stage CGAL is_valid()\n");
  try {
    o.cgal_is_valid = cdt.is_valid() ? "true" : "false";
  } catch(const std::exception& e) {
    o.cgal_is_valid = "assertion";
  }
  return o;
}

std::string encode(const Outcome& o)
{
  std::ostringstream os;
  os.precision(17);
  os << o.kind << '\t' << one_line(o.detail) << '\t' << o.triangles << '\t' << o.vertices << '\t' << o.forced << '\t'
     << o.repair_flips << '\t' << o.valid << '\t' << o.mean_quality << '\t' << o.min_quality << '\t' << o.seconds
     << '\t' << o.fingerprint << '\t' << o.cgal_is_valid << '\n';
  return os.str();
}

Outcome decode(const std::string& line)
{
  Outcome o;
  std::vector<std::string> f;
  std::string::size_type start = 0;
  for(std::string::size_type tab; (tab = line.find('\t', start)) != std::string::npos; start = tab + 1)
    f.push_back(line.substr(start, tab - start));
  f.push_back(line.substr(start));
  if(f.size() != 12) return o;
  try {
    o.kind = f[0];
    o.detail = f[1];
    o.triangles = std::stoull(f[2]);
    o.vertices = std::stoull(f[3]);
    o.forced = std::stoull(f[4]);
    o.repair_flips = std::stoull(f[5]);
    o.valid = f[6] == "1";
    o.mean_quality = std::stod(f[7]);
    o.min_quality = std::stod(f[8]);
    o.seconds = std::stod(f[9]);
    o.fingerprint = std::stoull(f[10]);
    o.cgal_is_valid = f[11];
  } catch(const std::exception&) {
    o = Outcome();
    o.detail = "unreadable result: " + one_line(line);
  }
  return o;
}

// Runs mesh_one<K> in a child process. The child gets the mesher's time
// limit and, in case it hangs outside the mesher's loop, an alarm at twice
// that; a signal is reported as a crash (or a hang for the alarm).
template <class K>
Outcome run_isolated(const Input& input, double time_limit)
{
  int fd[2];
  if(pipe(fd) != 0) {
    Outcome o;
    o.kind = "harness error";
    o.detail = std::strerror(errno);
    return o;
  }
  std::cout.flush();
  const pid_t pid = fork();
  if(pid < 0) {
    close(fd[0]);
    close(fd[1]);
    Outcome o;
    o.kind = "harness error";
    o.detail = std::string("fork: ") + std::strerror(errno);
    return o;
  }
  if(pid == 0) {
    close(fd[0]);
    child_fd = fd[1];
    if(time_limit > 0) alarm(static_cast<unsigned>(2 * time_limit + 1));
    // a run that goes astray must not take the machine's memory with it
    const rlimit memory = {rlim_t(8) << 30, rlim_t(8) << 30};
    setrlimit(RLIMIT_AS, &memory);
    Outcome o;
    try {
      o = mesh_one<K>(input, time_limit);
    } catch(const std::exception& e) {
      o.kind = "exception";
      o.detail = e.what();
    } catch(...) {
      o.kind = "exception";
      o.detail = "unknown exception";
    }
    send("result\t" + encode(o));
    close(fd[1]);
    _exit(0);
  }
  close(fd[1]);
  std::string text;
  char buf[4096];
  for(ssize_t r; (r = read(fd[0], buf, sizeof buf)) > 0;) text.append(buf, std::size_t(r));
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  // the stages reached, then the result
  std::string stage = "starting", result;
  std::istringstream lines(text);
  for(std::string line; std::getline(lines, line);) {
    if(line.compare(0, 6, "stage ") == 0) stage = line.substr(6);
    else if(line.compare(0, 7, "result\t") == 0) result = line.substr(7);
  }
  if(WIFSIGNALED(status)) {
    Outcome o;
    const int sig = WTERMSIG(status);
    o.kind = sig == SIGALRM ? "hang" : "crash";
    o.detail = (sig == SIGALRM ? "killed after " + std::to_string(int(2 * time_limit + 1)) + " s"
                               : std::string("signal ") + strsignal(sig)) + ", " + stage;
    return o;
  }
  Outcome o = decode(result);
  if(result.empty()) o.detail = "exit status " + std::to_string(WEXITSTATUS(status)) + ", " + stage;
  if(o.kind == "exception") o.detail += " (" + stage + ")";
  return o;
}

std::vector<Input> inputs(const std::string& data)
{
  std::vector<Input> v = afm_robustness::catalogue();
  if(data.empty()) return v;
  auto add = [&](const std::string& name, const std::string& file, auto read, double h, double grading) {
    try {
      if(std::ifstream(data + "/" + file)) v.push_back({name, read(data + "/" + file), h, grading});
    } catch(const std::exception& e) {
      std::cerr << file << ": " << e.what() << "\n";
    }
  };
  auto poly = [](const std::string& p) { return CGAL::Advancing_front_mesh_2::IO::read_poly(p); };
  auto jigsaw = [](const std::string& p) { return afm_shared_data::mesh2d_jigsaw(p); };
  auto cdt_txt = [](const std::string& p) {
    Poly_data d;
    std::string why;
    if(!afm_robustness::read_cdt_txt(p, d, why)) throw std::runtime_error(why);
    return d;
  };
  add("MESH2D lake", "mesh2d/lake.msh", jigsaw, 1e300, 0.3);
  add("MESH2D islands (Bahamas)", "mesh2d/islands.msh", jigsaw, 1e300, 0.3);
  add("MESH2D river (x near 4e7)", "mesh2d/river.msh", jigsaw, 1e300, 0.3);
  add("Triangle face.poly", "triangle_drufat/face.poly", poly, 1e300, 0.3);
  add("Triangle la.poly", "triangle_drufat/la.poly", poly, 1e300, 0.3);
  add("Mesh_2 clusters.poly", "cgal_mesh2/clusters.poly", poly, 1e300, 0.3);
  add("Mesh_2 fish-and-rectangle.poly", "cgal_mesh2/fish-and-rectangle.poly", poly, 1e300, 0.3);
  add("CDT guitar", "cdt_artem-ogre/guitar.txt", cdt_txt, 1e300, 0.3);
  add("CDT square with crack", "cdt_artem-ogre/square with crack.txt", cdt_txt, 1e300, 0.3);
  add("CDT Orange County", "cdt_artem-ogre/Orange County.txt", cdt_txt, 1e300, 0.3);
  auto geo = [](const std::string& p) { return afm_gmsh_geo::read_plane_surface(p); };
  add("Gmsh ocean.geo (North Atlantic, 60 islands)", "gmsh/ocean.geo", geo, 1e300, 0.3);
  add("Gmsh uk.geo (British Isles)", "gmsh/uk.geo", geo, 1e300, 0.3);
  return v;
}

std::string cell(const Outcome& o)
{
  std::ostringstream os;
  if(o.kind != "mesh") {
    os << "**" << o.kind << "**" << (o.detail.empty() ? "" : ": " + o.detail);
    return os.str();
  }
  os << (o.valid ? "valid" : "**INVALID**") << ", " << o.triangles << " tri";
  if(o.forced > 0) os << ", " << o.forced << " forced";
  if(o.repair_flips > 0) os << ", " << o.repair_flips << " repair flips";
  if(!o.detail.empty()) os << " (" << o.detail << ")";
  if(o.cgal_is_valid != "true") os << "; CGAL's is_valid(): " << o.cgal_is_valid;
  return os.str();
}

} // namespace

int main(int argc, char** argv)
{
  std::string data, only;
  double time_limit = 60;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if(a == "--data" && i + 1 < argc) data = argv[++i];
    else if(a == "--time-limit" && i + 1 < argc) time_limit = std::stod(argv[++i]);
    else if(a == "--only" && i + 1 < argc) only = argv[++i];
    else {
      std::cerr << "usage: inexact_kernel_report [--data SHARED_DATA_DIR] [--time-limit S] [--only SUBSTRING]\n";
      return 2;
    }
  }
#ifdef CGAL_NDEBUG
  const char* assertions = "off";
#else
  const char* assertions = "on";
#endif
  std::cout << "CGAL assertions " << assertions << ", time limit " << time_limit << " s per run.\n\n"
            << "| input | Epick (exact predicates) | Simple_cartesian<double> | same mesh |\n"
            << "|---|---|---|---|\n";
  std::size_t n = 0, same = 0, valid = 0, invalid = 0, failed = 0;
  for(const Input& input : inputs(data)) {
    if(!only.empty() && input.name.find(only) == std::string::npos) continue;
    const Outcome exact = run_isolated<Epick>(input, time_limit);
    const Outcome inexact = run_isolated<Inexact>(input, time_limit);
    const bool identical = exact.kind == "mesh" && inexact.kind == "mesh" && exact.fingerprint == inexact.fingerprint &&
                           exact.triangles == inexact.triangles;
    ++n;
    same += identical;
    if(inexact.kind == "mesh") (inexact.valid ? valid : invalid) += 1;
    else failed += 1;
    std::cout << "| " << input.name << " | " << cell(exact) << " | " << cell(inexact) << " | "
              << (identical ? "yes" : "no") << " |" << std::endl;
  }
  std::cout << "\n" << n << " inputs: with Simple_cartesian<double>, " << valid << " valid meshes (" << same
            << " identical to Epick's), " << invalid << " invalid meshes, " << failed
            << " runs without a mesh (exception, crash, hang or refusal).\n";
  return 0;
}
