// mpi_window_check: windows cut out of afmesh_2_mpi's pieces, for the
// independent checker, when the mesh is too large to check whole (the
// 10^9-triangle run of scripts/benchmark_mpi_billion.sh).
//
//   mpi_window_check OUT.pvtu INPUT.poly PREFIX x0 y0 x1 y1 [x0 y0 x1 y1 ...]
//
// For each window (non-overlapping boxes), the triangles of every piece
// whose three vertices lie in the box, put together by their global vertex
// numbers (GlobalNodeId), are written to PREFIX<k>.off, and their boundary
// (the edges only one of them has: the domain's boundary inside the box and
// the jagged edge of the window) to PREFIX<k>.poly, with the input's hole
// points inside the box; afm_check_mesh PREFIX<k>.poly PREFIX<k>.off then
// checks that the window is a valid triangulation of its boundary and
// constrained Delaunay: across the ranks' interfaces when the window
// straddles a cut. Prints one line per window: its triangles and vertices.
//
// The pieces are read through mmap, as afmesh_2_mpi writes them (binary,
// raw appended arrays with UInt64 sizes; Int32 or Int64 connectivity):
// the points once to mark the vertices in a window, the connectivity once
// to pick the triangles. Exit 1 with a message on a file it cannot read.
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace {

struct Box
{
  double x0, y0, x1, y1;
  bool holds(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

// A file mapped read-only.
class Mapped
{
public:
  explicit Mapped(const std::string& name) : name_(name)
  {
    const int fd = ::open(name.c_str(), O_RDONLY);
    if(fd < 0) throw std::runtime_error(name + ": cannot open");
    struct stat st;
    if(::fstat(fd, &st) != 0) {
      ::close(fd);
      throw std::runtime_error(name + ": cannot read");
    }
    size_ = std::size_t(st.st_size);
    void* p = size_ > 0 ? ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0) : MAP_FAILED;
    ::close(fd);
    if(p == MAP_FAILED) throw std::runtime_error(name + ": cannot map");
    data_ = static_cast<const char*>(p);
  }
  ~Mapped() { ::munmap(const_cast<char*>(data_), size_); }
  Mapped(const Mapped&) = delete;
  Mapped& operator=(const Mapped&) = delete;
  const char* data() const { return data_; }
  std::size_t size() const { return size_; }
  const std::string& name() const { return name_; }

private:
  std::string name_;
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

std::string attribute(const std::string& tag, const std::string& name)
{
  const std::string key = " " + name + "=\"";
  const std::size_t at = tag.find(key);
  if(at == std::string::npos) return std::string();
  const std::size_t begin = at + key.size();
  return tag.substr(begin, tag.find('"', begin) - begin);
}

// A piece's arrays in its mapping.
struct Piece
{
  std::uint64_t points = 0, cells = 0, triangles = 0; // the triangles first, then the segments (lines)
  const double* xyz = nullptr;
  const char* connectivity = nullptr;
  bool wide = true; // Int64 connectivity
  const std::int64_t* global_id = nullptr;
};

Piece read_piece(const Mapped& f)
{
  const std::string marker = "<AppendedData encoding=\"raw\">\n_";
  const std::string head(f.data(), std::min<std::size_t>(f.size(), 1 << 16));
  const std::size_t appended = head.find(marker);
  if(appended == std::string::npos) throw std::runtime_error(f.name() + ": not a binary piece of afmesh_2_mpi");
  const char* base = f.data() + appended + marker.size();
  Piece p;
  const std::size_t piece_tag = head.find("<Piece ");
  p.points = std::stoull(attribute(head.substr(piece_tag, head.find('>', piece_tag) - piece_tag), "NumberOfPoints"));
  p.cells = std::stoull(attribute(head.substr(piece_tag, head.find('>', piece_tag) - piece_tag), "NumberOfCells"));
  bool in_points = false;
  std::uint64_t connectivity_bytes = 0;
  for(std::size_t at = head.find('<'); at < appended; at = head.find('<', at + 1)) {
    const std::string tag = head.substr(at, head.find('>', at) - at);
    if(tag.compare(0, 7, "<Points") == 0) in_points = true;
    if(tag.compare(0, 8, "</Points") == 0) in_points = false;
    if(tag.compare(0, 10, "<DataArray") != 0) continue;
    const std::uint64_t offset = std::stoull(attribute(tag, "offset"));
    std::uint64_t bytes = 0;
    if(base + offset + 8 > f.data() + f.size()) throw std::runtime_error(f.name() + ": an array beyond the file's end");
    std::memcpy(&bytes, base + offset, 8);
    const char* data = base + offset + 8;
    if(data + bytes > f.data() + f.size()) throw std::runtime_error(f.name() + ": an array beyond the file's end");
    const std::string name = attribute(tag, "Name");
    if(in_points) {
      p.xyz = reinterpret_cast<const double*>(data);
      if(bytes != 24 * p.points) throw std::runtime_error(f.name() + ": points of the wrong size");
    } else if(name == "connectivity") {
      p.connectivity = data;
      p.wide = attribute(tag, "type") == "Int64";
      connectivity_bytes = bytes;
    } else if(name == "types") {
      if(bytes != p.cells) throw std::runtime_error(f.name() + ": types of the wrong size");
      p.triangles = std::uint64_t(std::count(data, data + bytes, char(5)));
      if(std::count(data, data + p.triangles, char(5)) != std::ptrdiff_t(p.triangles))
        throw std::runtime_error(f.name() + ": a cell other than a triangle before the last triangle");
    } else if(name == "GlobalNodeId") {
      p.global_id = reinterpret_cast<const std::int64_t*>(data);
      if(bytes != 8 * p.points) throw std::runtime_error(f.name() + ": GlobalNodeId of the wrong size");
    }
  }
  if(p.xyz == nullptr || p.connectivity == nullptr || p.global_id == nullptr)
    throw std::runtime_error(f.name() + ": points, connectivity or GlobalNodeId missing");
  // the segments after the triangles are lines of 2 vertices
  if(connectivity_bytes != (p.wide ? 8 : 4) * (3 * p.triangles + 2 * (p.cells - p.triangles)))
    throw std::runtime_error(f.name() + ": connectivity of the wrong size");
  return p;
}

std::uint64_t vertex_of(const Piece& p, std::uint64_t k)
{
  if(p.wide) {
    std::int64_t v;
    std::memcpy(&v, p.connectivity + 8 * k, 8);
    return std::uint64_t(v);
  }
  std::int32_t v;
  std::memcpy(&v, p.connectivity + 4 * k, 4);
  return std::uint64_t(v);
}

struct Window
{
  Box box;
  std::unordered_map<std::int64_t, std::size_t> index; // global number -> vertex
  std::vector<std::array<double, 2> > points;
  std::vector<std::array<std::size_t, 3> > triangles;
};

// The hole points of a .poly (Triangle's format, comments allowed).
std::vector<std::array<double, 2> > poly_holes(const std::string& name)
{
  std::ifstream in(name);
  if(!in) throw std::runtime_error(name + ": cannot open");
  std::vector<std::string> lines;
  for(std::string line; std::getline(in, line);) {
    const std::size_t hash = line.find('#');
    if(hash != std::string::npos) line.erase(hash);
    if(line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
  }
  std::size_t at = 0;
  auto numbers = [&](std::size_t k) {
    std::istringstream is(lines.at(k));
    std::vector<double> v;
    for(double x; is >> x;) v.push_back(x);
    return v;
  };
  const std::size_t n_points = std::size_t(numbers(at).at(0));
  at += 1 + n_points;
  const std::size_t n_segments = std::size_t(numbers(at).at(0));
  at += 1 + n_segments;
  std::vector<std::array<double, 2> > holes;
  if(at >= lines.size()) return holes;
  const std::size_t n_holes = std::size_t(numbers(at).at(0));
  for(std::size_t h = 0; h < n_holes; ++h) {
    const std::vector<double> v = numbers(at + 1 + h);
    holes.push_back({{v.at(1), v.at(2)}});
  }
  return holes;
}

} // namespace

int main(int argc, char* argv[])
{
  if(argc < 8 || (argc - 4) % 4 != 0) {
    std::cerr << "usage: mpi_window_check OUT.pvtu INPUT.poly PREFIX x0 y0 x1 y1 [x0 y0 x1 y1 ...]\n";
    return 2;
  }
  try {
    const std::string pvtu = argv[1], poly = argv[2], prefix = argv[3];
    std::vector<Window> windows;
    for(int a = 4; a + 3 < argc; a += 4)
      windows.push_back(Window{{std::atof(argv[a]), std::atof(argv[a + 1]), std::atof(argv[a + 2]), std::atof(argv[a + 3])},
                               {}, {}, {}});
    // the pieces the collection names, beside it
    std::ifstream collection(pvtu);
    if(!collection) throw std::runtime_error(pvtu + ": cannot open");
    const std::string text((std::istreambuf_iterator<char>(collection)), std::istreambuf_iterator<char>());
    const std::size_t slash = pvtu.find_last_of('/');
    const std::string directory = slash == std::string::npos ? std::string() : pvtu.substr(0, slash + 1);
    std::vector<std::string> pieces;
    for(std::size_t at = text.find("Source=\""); at != std::string::npos; at = text.find("Source=\"", at + 1)) {
      const std::size_t begin = at + 8;
      pieces.push_back(directory + text.substr(begin, text.find('"', begin) - begin));
    }
    for(const std::string& name : pieces) {
      const Mapped f(name);
      const Piece p = read_piece(f);
      // which window each vertex is in (the windows do not overlap)
      std::vector<std::uint8_t> in_window(p.points, 0);
      for(std::uint64_t v = 0; v < p.points; ++v)
        for(std::size_t w = 0; w < windows.size(); ++w)
          if(windows[w].box.holds(p.xyz[3 * v], p.xyz[3 * v + 1])) {
            in_window[v] = std::uint8_t(w + 1);
            break;
          }
      for(std::uint64_t t = 0; t < p.triangles; ++t) {
        const std::uint64_t a = vertex_of(p, 3 * t), b = vertex_of(p, 3 * t + 1), c = vertex_of(p, 3 * t + 2);
        if(a >= p.points || b >= p.points || c >= p.points) throw std::runtime_error(name + ": a vertex out of range");
        const std::uint8_t w = in_window[a];
        if(w == 0 || in_window[b] != w || in_window[c] != w) continue;
        Window& win = windows[w - 1];
        std::array<std::size_t, 3> tri;
        const std::uint64_t abc[3] = {a, b, c};
        for(int k = 0; k < 3; ++k) {
          const std::uint64_t v = abc[k];
          const auto ins = win.index.emplace(p.global_id[v], win.points.size());
          if(ins.second) win.points.push_back({{p.xyz[3 * v], p.xyz[3 * v + 1]}});
          else if(win.points[ins.first->second][0] != p.xyz[3 * v] || win.points[ins.first->second][1] != p.xyz[3 * v + 1])
            throw std::runtime_error(name + ": vertex " + std::to_string(p.global_id[v]) +
                                     " is not where another piece has it");
          tri[std::size_t(k)] = ins.first->second;
        }
        win.triangles.push_back(tri);
      }
    }
    const std::vector<std::array<double, 2> > holes = poly_holes(poly);
    for(std::size_t w = 0; w < windows.size(); ++w) {
      const Window& win = windows[w];
      // the boundary: the edges one triangle has (a triangle given by two
      // pieces would show as an edge used three or four times, which the
      // checker then finds as an overlap)
      std::map<std::pair<std::size_t, std::size_t>, int> uses;
      for(const auto& t : win.triangles)
        for(int k = 0; k < 3; ++k) {
          std::size_t a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)];
          if(b < a) std::swap(a, b);
          ++uses[std::make_pair(a, b)];
        }
      const std::string base = prefix + std::to_string(w);
      std::ofstream off(base + ".off"), ps(base + ".poly");
      off << std::setprecision(17) << "OFF\n" << win.points.size() << ' ' << win.triangles.size() << " 0\n";
      for(const auto& p : win.points) off << p[0] << ' ' << p[1] << " 0\n";
      for(const auto& t : win.triangles) off << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
      std::vector<std::pair<std::size_t, std::size_t> > boundary;
      for(const auto& e : uses)
        if(e.second == 1) boundary.push_back(e.first);
      std::vector<std::array<double, 2> > inside;
      for(const auto& h : holes)
        if(win.box.holds(h[0], h[1])) inside.push_back(h);
      ps << std::setprecision(17) << win.points.size() << " 2 0 0\n";
      for(std::size_t i = 0; i < win.points.size(); ++i)
        ps << i << ' ' << win.points[i][0] << ' ' << win.points[i][1] << '\n';
      ps << boundary.size() << " 0\n";
      for(std::size_t s = 0; s < boundary.size(); ++s)
        ps << s << ' ' << boundary[s].first << ' ' << boundary[s].second << '\n';
      ps << inside.size() << '\n';
      for(std::size_t h = 0; h < inside.size(); ++h) ps << h << ' ' << inside[h][0] << ' ' << inside[h][1] << '\n';
      off.close();
      ps.close();
      if(!off || !ps) throw std::runtime_error(base + ": cannot write");
      std::cout << base << ' ' << win.triangles.size() << " triangles " << win.points.size() << " vertices\n";
    }
  } catch(const std::exception& e) {
    std::cerr << "mpi_window_check: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
