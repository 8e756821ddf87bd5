// The Python module of Advancing_front_mesh_2 (the compiled part,
// afmesh_2._afmesh_2; afmesh_2/__init__.py wraps it): NumPy arrays in, NumPy
// arrays out, through the very pipeline of the afmesh_2 command-line tool
// (afmesh_2/input.h and meshing.h), so that the same input and options give
// the same triangles.
#include "afmesh_2/input.h"
#include "afmesh_2/meshing.h"
#include "afmesh_2/options.h"

#include <CGAL/Advancing_front_mesh_2/IO/internal/Mesh_tagged_view.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace py = pybind11;
namespace AFM = CGAL::Advancing_front_mesh_2;

namespace {

typedef py::array_t<double, py::array::c_style | py::array::forcecast> Double_array;
typedef py::array_t<std::int64_t, py::array::c_style | py::array::forcecast> Int_array;

// An (n, columns) array of doubles, or a ValueError naming the argument.
Double_array as_rows(const py::object& o, py::ssize_t columns, const char* name)
{
  Double_array a = Double_array::ensure(o);
  if(!a || a.ndim() != 2 || a.shape(1) != columns)
    throw py::value_error(std::string(name) + " must be an array of shape (n, " + std::to_string(columns) + ")");
  return a;
}

Int_array as_ints(const py::object& o, py::ssize_t ndim, py::ssize_t columns, const char* name)
{
  Int_array a = Int_array::ensure(o);
  if(!a || a.ndim() != ndim || (ndim == 2 && a.shape(1) != columns))
    throw py::value_error(std::string(name) + " must be an integer array of shape " +
                          (ndim == 2 ? "(n, " + std::to_string(columns) + ")" : std::string("(n,)")));
  return a;
}

// The arguments as the .poly reader would give them.
AFM::IO::Poly_data poly_data(const py::object& vertices, const py::object& segments, const py::object& holes,
                             const py::object& regions, const py::object& vertex_markers,
                             const py::object& segment_markers)
{
  AFM::IO::Poly_data d;
  const Double_array v = as_rows(vertices, 2, "vertices");
  for(py::ssize_t i = 0; i < v.shape(0); ++i) d.points.push_back({{v.at(i, 0), v.at(i, 1)}});
  if(!segments.is_none()) {
    const Int_array s = as_ints(segments, 2, 2, "segments");
    for(py::ssize_t i = 0; i < s.shape(0); ++i) {
      const std::int64_t a = s.at(i, 0), b = s.at(i, 1);
      if(a < 0 || b < 0 || a >= v.shape(0) || b >= v.shape(0))
        throw py::value_error("segment " + std::to_string(i) + " has an end point out of range (" + std::to_string(a) +
                              ", " + std::to_string(b) + "; " + std::to_string(v.shape(0)) + " vertices)");
      if(a == b) throw py::value_error("segment " + std::to_string(i) + " joins vertex " + std::to_string(a) + " to itself");
      d.segments.push_back({{std::size_t(a), std::size_t(b)}});
    }
  }
  if(!holes.is_none()) {
    const Double_array h = as_rows(holes, 2, "holes");
    for(py::ssize_t i = 0; i < h.shape(0); ++i) d.holes.push_back({{h.at(i, 0), h.at(i, 1)}});
  }
  if(!regions.is_none()) {
    const Double_array r = as_rows(regions, 4, "regions (x, y, attribute, max_area)");
    for(py::ssize_t i = 0; i < r.shape(0); ++i) {
      AFM::IO::Poly_data::Region region;
      region.seed = {{r.at(i, 0), r.at(i, 1)}};
      region.attribute = r.at(i, 2);
      region.max_area = r.at(i, 3);
      d.regions.push_back(region);
    }
  }
  auto markers = [](const py::object& o, std::size_t n, const char* name, std::vector<int>& out) {
    if(o.is_none()) return;
    const Int_array m = as_ints(o, 1, 1, name);
    if(std::size_t(m.shape(0)) != n)
      throw py::value_error(std::string(name) + " must hold one marker per item (" + std::to_string(n) + ")");
    for(py::ssize_t i = 0; i < m.shape(0); ++i) {
      if(m.at(i) < std::numeric_limits<int>::min() || m.at(i) > std::numeric_limits<int>::max())
        throw py::value_error(std::string(name) + ": marker " + std::to_string(m.at(i)) + " does not fit in an int");
      out.push_back(int(m.at(i)));
    }
  };
  markers(vertex_markers, d.points.size(), "vertex_markers", d.point_markers);
  markers(segment_markers, d.segments.size(), "segment_markers", d.segment_markers);
  return d;
}

// What the caller asked for, beyond the graph.
struct Request
{
  afmesh_2::Options opt;
  py::object size_function = py::none(); // a callable size, or None
  std::vector<std::array<double, 3> > sources;
};

// A Python callable evaluated on arrays of points: (n, 2) in, n sizes out.
// Called while the GIL is held (the sampling happens before meshing).
afmesh_2::Cli_base_sizing_field<CGAL::Epick>::Sampled::Bulk_function bulk(const py::object& f)
{
  return [f](const double* xy, std::size_t n, double* h) {
    py::array_t<double> points({py::ssize_t(n), py::ssize_t(2)});
    std::copy(xy, xy + 2 * n, points.mutable_data());
    const Double_array values = Double_array::ensure(f(points));
    if(!values || values.size() != py::ssize_t(n))
      throw py::value_error("the size function must return one size per point (an array of shape (n,))");
    std::copy(values.data(), values.data() + n, h);
  };
}

template <class K>
py::dict mesh_with(const AFM::IO::Poly_data& data, const Request& request)
{
  using namespace afmesh_2;
  typedef typename Types<K>::CDT CDT;
  const Options& opt = request.opt;
  Input<K> in;
  in.poly = data;
  insert_boundary(opt, in);
  if(!request.size_function.is_none()) {
    double xmin = std::numeric_limits<double>::max(), ymin = xmin, xmax = -xmin, ymax = -xmin;
    for(const auto& p : data.points) {
      xmin = std::min(xmin, p[0]); xmax = std::max(xmax, p[0]);
      ymin = std::min(ymin, p[1]); ymax = std::max(ymax, p[1]);
    }
    in.sizing.base.sampled =
      std::make_shared<typename Cli_base_sizing_field<K>::Sampled>(bulk(request.size_function), xmin, ymin, xmax, ymax);
    limit_size_in_regions(in);
  } else {
    std::vector<AFM::Size_source_2<K> > sources;
    for(const auto& s : request.sources) sources.emplace_back(typename K::Point_2(s[0], s[1]), s[2]);
    make_size_field(opt, in, sources);
  }
  split_boundary(opt, in);
  Progress_visitor quiet;
  Mesher<K> mesher(in.cdt, in.sizing, quiet);
  configure(opt, in, mesher);
  AFM::Mesh_return_code rc = AFM::MESH_COMPLETE;
  {
    py::gil_scoped_release free_python;
    if(opt.threads > 1) {
      AFM::Parallel_mesh_statistics parallel;
      rc = mesh_in_parts<K>(opt, in, parallel);
    } else {
      run_mesher<K>(opt, mesher, rc);
    }
    smooth(opt, in);
    raise_minimum_angle(opt, in);
  }
  if(in.tags.has_regions()) in.tags.mark_regions(in.cdt);
  AFM::IO::internal::Mesh_domain_view<CDT> m;
  AFM::IO::internal::mesh_collect(in.cdt, &in.tags, m);

  py::array_t<double> points({py::ssize_t(m.points.size()), py::ssize_t(2)});
  for(std::size_t i = 0; i < m.points.size(); ++i) {
    points.mutable_at(i, 0) = m.points[i][0];
    points.mutable_at(i, 1) = m.points[i][1];
  }
  py::array_t<std::int64_t> triangles({py::ssize_t(m.triangles.size()), py::ssize_t(3)});
  for(std::size_t t = 0; t < m.triangles.size(); ++t)
    for(int k = 0; k < 3; ++k) triangles.mutable_at(t, k) = std::int64_t(m.triangles[t][k]);
  py::array_t<std::int64_t> segments({py::ssize_t(m.segments.size()), py::ssize_t(2)});
  for(std::size_t s = 0; s < m.segments.size(); ++s)
    for(int k = 0; k < 2; ++k) segments.mutable_at(s, k) = std::int64_t(m.segments[s][k]);
  py::dict result;
  result["points"] = points;
  result["triangles"] = triangles;
  result["segments"] = segments;
  result["vertex_markers"] = py::array_t<int>(py::ssize_t(m.point_markers.size()), m.point_markers.data());
  result["segment_markers"] = py::array_t<int>(py::ssize_t(m.segment_markers.size()), m.segment_markers.data());
  if(m.has_regions)
    result["regions"] = py::array_t<double>(py::ssize_t(m.triangle_attributes.size()), m.triangle_attributes.data());
  else
    result["regions"] = py::none();
  result["return_code"] = rc == AFM::MESH_COMPLETE ? "MESH_COMPLETE" : "LIMIT_REACHED";
  return result;
}

py::dict mesh(const py::object& vertices, const py::object& segments, const py::object& holes,
              const py::object& regions, const py::object& vertex_markers, const py::object& segment_markers,
              const py::object& size, const py::object& sources, const py::object& max_size, const py::object& grading,
              const std::string& boundary_spacing, std::size_t smooth, const std::string& smoother,
              const std::string& kernel, bool keep_segments, double min_angle, long long threads)
{
  const AFM::IO::Poly_data data = poly_data(vertices, segments, holes, regions, vertex_markers, segment_markers);
  Request r;
  afmesh_2::Options& opt = r.opt;
  opt.input = "PSLG";
  opt.keep_segments = keep_segments;
  if(min_angle != 0 && !(min_angle > 0 && min_angle <= 30))
    throw py::value_error("min_angle must be an angle in degrees above 0 and at most 30, or 0 for none");
  opt.min_angle = min_angle;
  // as afmesh_2 --threads: 0 (None) is every core, and segments kept mesh on one
  if(threads < 0 || threads > 4096)
    throw py::value_error("threads must be a number from 1 to 4096, or None (0 also means every core)");
  if(threads > 1 && keep_segments) throw py::value_error("threads above 1 cannot be combined with keep_segments");
  opt.threads = threads > 0 ? std::size_t(threads)
                : keep_segments ? 1 : std::max<std::size_t>(1, std::thread::hardware_concurrency());
  if(!size.is_none() && PyCallable_Check(size.ptr())) {
    r.size_function = size;
  } else if(!size.is_none()) {
    opt.size = size.cast<double>();
    opt.has_size = true;
  }
  if(!max_size.is_none()) {
    if(opt.has_size) throw py::value_error("give size or max_size, not both");
    opt.size = max_size.cast<double>();
    opt.has_size = true;
  }
  if(opt.has_size && (!(opt.size > 0) || !std::isfinite(opt.size)))
    throw py::value_error("the size must be a positive finite number");
  if(!sources.is_none()) {
    const Double_array s = as_rows(sources, 3, "sources (x, y, h)");
    for(py::ssize_t i = 0; i < s.shape(0); ++i) r.sources.push_back({{s.at(i, 0), s.at(i, 1), s.at(i, 2)}});
    if(!r.size_function.is_none()) throw py::value_error("give a size function or sources, not both");
  }
  if(grading.is_none()) {
    opt.gradation = 0;
    opt.boundary_spacing = "diffuse";
  } else {
    opt.gradation = grading.cast<double>();
    if(!(opt.gradation > 0) || !std::isfinite(opt.gradation))
      throw py::value_error("grading must be a positive number, or None to switch the gradation limit off");
    if(boundary_spacing != "grow" && boundary_spacing != "diffuse")
      throw py::value_error("boundary_spacing must be 'grow' or 'diffuse'");
    opt.boundary_spacing = boundary_spacing;
  }
  if(smooth > 1000) throw py::value_error("smooth must be a number of passes from 0 to 1000");
  opt.smooth = smooth;
  if(smoother != "quality" && smoother != "laplacian") throw py::value_error("smoother must be 'quality' or 'laplacian'");
  opt.smoother = smoother;
  if(kernel == "epeck") return mesh_with<CGAL::Exact_predicates_exact_constructions_kernel>(data, r);
  if(kernel == "exact-rational") return mesh_with<CGAL::Simple_cartesian<CGAL::Exact_rational> >(data, r);
  if(kernel != "epick") throw py::value_error("kernel must be 'epick', 'epeck' or 'exact-rational'");
  return mesh_with<CGAL::Epick>(data, r);
}

} // namespace

PYBIND11_MODULE(_afmesh_2, m)
{
  m.doc() = "Advancing_front_mesh_2: advancing-front Delaunay triangular meshes of planar domains (compiled part)";
  // an invalid input is a ValueError with the tool's message
  py::register_exception<afmesh_2::Input_error>(m, "InputError", PyExc_ValueError);
  py::register_exception<AFM::IO::Poly_read_error>(m, "PolyReadError", PyExc_ValueError);
  m.def("mesh", &mesh, py::arg("vertices"), py::arg("segments") = py::none(), py::arg("holes") = py::none(),
        py::arg("regions") = py::none(), py::arg("vertex_markers") = py::none(),
        py::arg("segment_markers") = py::none(), py::arg("size") = py::none(), py::arg("sources") = py::none(),
        py::arg("max_size") = py::none(), py::arg("grading") = 0.2, py::arg("boundary_spacing") = "grow",
        py::arg("smooth") = 0, py::arg("smoother") = "quality", py::arg("kernel") = "epick",
        py::arg("keep_segments") = false, py::arg("min_angle") = 0.0, py::arg("threads") = 0,
        "Meshes the domain of a planar straight-line graph; see afmesh_2.mesh().");
  m.attr("__version__") = CGAL_ADVANCING_FRONT_MESH_2_VERSION_STR;
}
