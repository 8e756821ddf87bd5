// afmesh_2: the command line, parsed and checked into Options.
#ifndef AFMESH_2_OPTIONS_H
#define AFMESH_2_OPTIONS_H

#include <CGAL/Advancing_front_mesh_2/Poisson_sizing_field_2.h>

#include <boost/program_options.hpp>

#include "ogr_input.h"

#include <CGAL/Advancing_front_mesh_2/version.h>
#include <CGAL/version.h>

#include <boost/version.hpp>

#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <iostream>
#include <thread>
#include <stdexcept>
#include <string>
#include <vector>

namespace afmesh_2 {

namespace po = boost::program_options;
namespace AFM = CGAL::Advancing_front_mesh_2;

const char* const program = "afmesh_2";

// Exit code 2: the command line is wrong.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };
// Exit code 1: an input file is wrong (the message names it, and its line).
struct Input_error : std::runtime_error { using std::runtime_error::runtime_error; };

struct Options
{
  std::string input;
  double size = 0;
  bool has_size = false;
  std::string sources;
  std::string grading = "0.2";
  std::string boundary_spacing = "grow"; // or "diffuse"; "diffuse" whenever --grading is off
  double gradation = AFM::Poisson_sizing_field_options::default_gradation; // 0: off
  std::vector<std::string> outputs;
  bool no_output = false;       // --no-output: no mesh file at all
  bool default_outputs = false; // no -o: INPUT.1.node/.ele/.edge, as Triangle
  std::string kernel = "epick";
  bool stats = false;
  bool report = false;
  bool no_pocket_priority = false;
  bool keep_segments = false; // --keep-segments: no boundary discretisation, as Triangle's -Y
  double min_angle = 0;       // --min-angle A in degrees, 0: off
  std::size_t threads = 1;    // --threads N, resolved: the parts meshed at once (1: the serial mesher)
  double time_limit = 0;     // seconds of meshing, 0: none
  std::size_t max_steps = 0; // front edges processed, 0: none
  std::size_t smooth = 0;
  std::string smoother = "quality"; // or "laplacian"
  std::string svg_color = "plain";
  std::vector<double> svg_window; // --svg-window X0 Y0 X1 Y1, or empty
  std::string histogram;
  bool stream = false;
  bool vtu_ascii = false;
  std::size_t checkpoint_every = 0; // triangles, 0: no checkpoints
  std::string checkpoint_file;
  bool stop_after_checkpoint = false;
  std::string resume;               // checkpoint to resume from
  std::string arguments;            // the run's own arguments, '\0'-separated, stored in checkpoints
  std::string input_checksum, sources_checksum; // of the files a checkpointed run read
};

// What the command line gave, before it is checked.
struct Command_line
{
  Options opt;
  long long smooth = 0, max_steps = 0, threads = 0;
  std::vector<std::string> checkpoint; // --checkpoint-every K FILE
  std::vector<std::string> svg_window; // --svg-window X0 Y0 X1 Y1
  po::variables_map vm;
  po::parsed_options parsed{nullptr};
};

// An option taking exactly two values (K FILE): a multitoken option would
// also take the input file given after them.
template <unsigned N>
class Exact_tokens : public po::typed_value<std::vector<std::string> >
{
public:
  explicit Exact_tokens(std::vector<std::string>* store) : po::typed_value<std::vector<std::string> >(store) {}
  unsigned min_tokens() const override { return N; }
  unsigned max_tokens() const override { return N; }
};
typedef Exact_tokens<2> Two_tokens;

inline bool ends_with(const std::string& s, const std::string& tail)
{
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The options the user sees in --help.
inline po::options_description visible_options(Command_line& c)
{
  Options& opt = c.opt;
  po::options_description visible("Usage: afmesh_2 INPUT [--size H] [--sources FILE] [-o OUT ...] [options]\n\n"
                                  "Meshes the domain of INPUT (a Triangle .poly file; polygons with holes in\n"
                                  "WKT .wkt, GeoJSON .geojson or, built with GDAL, .shp .gpkg .gml .kml ...;\n"
                                  "or a Gmsh 1D mesh .msh) with the advancing-front\n"
                                  "Delaunay algorithm of Mavriplis (1992). With --size alone the target edge\n"
                                  "length is uniform; otherwise it comes from a background field on a quadtree:\n"
                                  "the point sources diffused by a Poisson solve, the boundary spacing grown from\n"
                                  "the boundary at the gradation rate, bounded above by --size when given.\n\nOptions");
  visible.add_options()
    ("help,h", "print this help and exit")
    ("version", "print the versions of afmesh_2 and of the libraries it was built with, and exit")
    ("size", po::value<double>(&opt.size), "target edge length H: uniform, or the largest size with --sources")
    ("sources", po::value<std::string>(&opt.sources),
     "size sources, one 'x y h' per line ('#' comments): size h prescribed at (x, y)")
    ("grading", po::value<std::string>(&opt.grading)->default_value("0.2"),
     "gradation limit G of the background field: the size changes by at most G per unit length "
     "along each axis; 'off' to switch it off (the boundary spacing is then diffused)")
    ("boundary-spacing", po::value<std::string>(&opt.boundary_spacing)->default_value("grow"),
     "how the boundary spacing makes the background field: 'grow' (default) from each boundary point at "
     "the gradation rate, up to the sources' field or the domain's extent; 'diffuse' with the sources by "
     "the Poisson solve, as in Mavriplis (1992)")
    ("output,o", po::value<std::vector<std::string> >(&opt.outputs),
     "output file, format chosen by extension: .off .vtu .node/.ele (with .edge) .poly (the boundary) .msh .svg "
     "(repeatable)")
    ("vtu-ascii", po::bool_switch(&opt.vtu_ascii),
     ".vtu outputs in ASCII (default: binary, raw appended arrays, which VTK, ParaView and meshio read)")
    ("kernel", po::value<std::string>(&opt.kernel)->default_value("epick"),
     "CGAL kernel: epick (default), epeck or exact-rational")
    ("smooth", po::value<long long>(&c.smooth)->default_value(0),
     "N passes (0 to 1000) of guarded smoothing and Delaunay edge swapping after meshing")
    ("smoother", po::value<std::string>(&opt.smoother)->default_value("quality"),
     "with --smooth: 'quality' (default), the best of Laplacian and optimal-Delaunay moves for each "
     "vertex's triangles, or 'laplacian', the paper's (Fig. 13)")
    ("svg-color", po::value<std::string>(&opt.svg_color)->default_value("plain"),
     "SVG outputs: 'plain', or 'quality' to colour triangles by radius ratio (with a key)")
    ("svg-window", new Exact_tokens<4>(&c.svg_window),
     "X0 Y0 X1 Y1: SVG outputs show only this window of the mesh (a close-up)")
    ("histogram", po::value<std::string>(&opt.histogram), "write the quality histograms as SVG to this file")
    ("keep-segments", po::bool_switch(&opt.keep_segments),
     "keep every input segment as one mesh edge, as the paper does (Triangle's -Y); by default segments "
     "longer than the local size are first split to the size field")
    ("min-angle", po::value<double>(&opt.min_angle),
     "A: after meshing (and smoothing), raise the smallest angle to A degrees (0 < A <= 30) by local "
     "Delaunay refinement of the few triangles below it (Mesh_2's, with segment splitting unless "
     "--keep-segments); triangles at input angles below about 60 degrees may stay below (see the manual)")
    ("threads", po::value<long long>(&c.threads),
     "N: cut the domain into N strips of about equal triangle counts and mesh them at once on N threads, "
     "then merge them (constrained Delaunay across the cuts); 1: the serial mesher; default: every core. "
     "--stream, --checkpoint-every, --resume, --time-limit, --max-steps and --keep-segments mesh on one thread")
    ("no-pocket-priority", po::bool_switch(&opt.no_pocket_priority),
     "mesh the front's pockets in shortest-first order too: a little better quality "
     "where patches meet, a front up to 4 times larger")
    ("time-limit", po::value<double>(&opt.time_limit),
     "stop meshing after this many seconds: the rest of the front is closed on existing points, the "
     "mesh is valid but coarser there, and a note says so (the run ends without it too)")
    ("max-steps", po::value<long long>(&c.max_steps),
     "stop meshing after this many front edges, as --time-limit does")
    ("stream", po::bool_switch(&opt.stream),
     "write triangles to the outputs while meshing and drop them from memory, for meshes larger than "
     "memory (not with .svg outputs, --smooth or --histogram; no quality figures)")
    ("checkpoint-every", new Two_tokens(&c.checkpoint),
     "K FILE: with --stream (implied), write the mesher's state to FILE after every K more triangles, "
     "so that --resume FILE can finish an interrupted run")
    ("stop-after-checkpoint", po::bool_switch(&opt.stop_after_checkpoint),
     "stop right after the first checkpoint (to run a large mesh in several sessions)")
    ("resume", po::value<std::string>(&opt.resume),
     "FILE: continue the run whose checkpoint is FILE, with the options stored there; only "
     "--checkpoint-every, --stop-after-checkpoint, --time-limit, --max-steps, --stats and --report may be given")
    ("no-output", po::bool_switch(&opt.no_output),
     "write no mesh file (without -o, INPUT.1.node/.ele/.edge are written beside the input, as Triangle does)")
    ("stats", po::bool_switch(&opt.stats), "print statistics as one JSON object on stdout")
    ("report", po::bool_switch(&opt.report),
     "print a readable quality summary (on stdout; on stderr with --stats)");
  return visible;
}

// Reads `args` into `c`; returns the options --help shows.
inline po::options_description read_command_line(const std::vector<std::string>& args, Command_line& c)
{
  po::options_description visible = visible_options(c);
  po::options_description hidden;
  hidden.add_options()("input", po::value<std::string>(&c.opt.input))
    // written into checkpoints only (see stored_arguments())
    ("input-checksum", po::value<std::string>(&c.opt.input_checksum))
    ("sources-checksum", po::value<std::string>(&c.opt.sources_checksum));
  po::options_description all;
  all.add(visible).add(hidden);
  po::positional_options_description pos;
  pos.add("input", 1);
  try {
    c.parsed = po::command_line_parser(args).options(all).positional(pos).run();
    po::store(c.parsed, c.vm);
    po::notify(c.vm);
  } catch(const po::error& e) {
    throw Usage_error(e.what());
  }
  return visible;
}

inline void parse_checkpoint(const std::vector<std::string>& checkpoint, Options& opt)
{
  long long every = 0;
  std::size_t used = 0;
  if(checkpoint.size() == 2) {
    try {
      every = std::stoll(checkpoint[0], &used);
    } catch(const std::exception&) {
      used = 0;
    }
  }
  if(checkpoint.size() != 2 || used != checkpoint[0].size() || every < 1 || checkpoint[1].empty())
    throw Usage_error("--checkpoint-every takes a positive number of triangles K and a FILE");
  // Boost hands over the next option when FILE is missing
  if(checkpoint[1][0] == '-')
    throw Usage_error("--checkpoint-every takes a positive number of triangles K and a FILE, not '" + checkpoint[1] +
                      "'");
  opt.checkpoint_every = std::size_t(every);
  opt.checkpoint_file = checkpoint[1];
  opt.stream = true;
}

// The limits of a session, checked: given now, they hold for this run only.
inline void check_limits(const Command_line& c)
{
  if(c.vm.count("time-limit") && (!(c.opt.time_limit > 0) || !std::isfinite(c.opt.time_limit)))
    throw Usage_error("--time-limit must be a positive number of seconds");
  if(c.vm.count("max-steps") && c.max_steps < 1) throw Usage_error("--max-steps must be a positive count");
}

// Whether `text` is a whole finite number, stored in `value`.
inline bool parse_finite_number(const std::string& text, double& value)
{
  std::size_t used = 0;
  try {
    value = std::stod(text, &used);
  } catch(const std::exception&) {
    return false;
  }
  return used == text.size() && std::isfinite(value);
}

inline double parse_grading(const std::string& grading)
{
  if(grading == "off") return 0;
  double g = 0;
  if(!parse_finite_number(grading, g) || !(g > 0))
    throw Usage_error("--grading must be a positive number or 'off', not '" + grading + "'");
  return g;
}

inline void check_output_formats(const Options& opt)
{
  for(const std::string& out : opt.outputs) {
    const std::string ext = out.substr(out.find_last_of('.') == std::string::npos ? out.size()
                                                                                 : out.find_last_of('.'));
    if(ext != ".off" && ext != ".vtu" && ext != ".node" && ext != ".ele" && ext != ".poly" && ext != ".msh" &&
       ext != ".svg")
      throw Usage_error("unknown output format '" + out + "' (use .off, .vtu, .node, .ele, .poly, .msh or .svg)");
  }
}

// what streaming cannot do: it never holds the whole mesh
inline void check_streaming(const Options& opt)
{
  if(!opt.stream) return;
  if(opt.outputs.empty()) throw Usage_error("--stream needs an output (-o)");
  for(const std::string& out : opt.outputs)
    if(ends_with(out, ".svg")) throw Usage_error("--stream cannot write pictures (.svg): they need the whole mesh");
  for(const std::string& out : opt.outputs)
    if(ends_with(out, ".poly"))
      throw Usage_error("--stream cannot write the boundary (.poly): it is written with the mesh in memory");
  if(opt.smooth > 0) throw Usage_error("--stream cannot be combined with --smooth (smoothing needs the whole mesh)");
  if(opt.min_angle != 0)
    throw Usage_error("--stream cannot be combined with --min-angle (the refinement needs the whole mesh)");
  if(!opt.histogram.empty()) throw Usage_error("--stream cannot be combined with --histogram");
}

// Without -o, Triangle's names beside the input: INPUT.1.node (with .ele
// and .edge), INPUT being the input's name without its .poly extension.
// Streaming needs its outputs named (it checks that before this).
inline void set_default_outputs(Options& opt)
{
  if(!opt.outputs.empty() || opt.no_output || opt.stream || opt.checkpoint_every > 0) return;
  std::string stem = opt.input;
  if(ends_with(stem, ".poly")) stem.resize(stem.size() - 5);
  opt.outputs.push_back(stem + ".1.node");
  opt.default_outputs = true;
}

// --svg-window X0 Y0 X1 Y1: four numbers, X0 < X1 and Y0 < Y1.
inline void parse_svg_window(const std::vector<std::string>& values, Options& opt)
{
  if(values.empty()) return;
  for(const std::string& v : values) {
    double x = 0;
    if(!parse_finite_number(v, x)) throw Usage_error("--svg-window takes four numbers, not '" + v + "'");
    opt.svg_window.push_back(x);
  }
  if(!(opt.svg_window[0] < opt.svg_window[2]) || !(opt.svg_window[1] < opt.svg_window[3]))
    throw Usage_error("--svg-window X0 Y0 X1 Y1 needs X0 < X1 and Y0 < Y1");
}

// --threads: given, at least 1 and not with what needs one thread (one
// mesher whose state is streamed, checkpointed or limited; every segment
// kept, which the cuts would split); not given, every core where possible.
inline void resolve_threads(Command_line& c)
{
  Options& opt = c.opt;
  const bool given = c.vm.count("threads") > 0;
  if(given && (c.threads < 1 || c.threads > 4096))
    throw Usage_error("--threads must be a number of threads from 1 to 4096");
  const char* serial_only = opt.stream                   ? "--stream"
                            : opt.checkpoint_every > 0   ? "--checkpoint-every"
                            : opt.time_limit > 0         ? "--time-limit"
                            : opt.max_steps > 0          ? "--max-steps"
                            : opt.keep_segments          ? "--keep-segments"
                                                         : nullptr;
  if(given && c.threads > 1 && serial_only != nullptr)
    throw Usage_error(std::string("--threads above 1 cannot be combined with ") + serial_only +
                      " (it meshes on one thread)");
  if(given) opt.threads = std::size_t(c.threads);
  else opt.threads = serial_only != nullptr ? 1 : (std::max)(1u, std::thread::hardware_concurrency());
}

// The options of a new run (not --resume), checked and completed.
inline void check_new_run(Command_line& c)
{
  Options& opt = c.opt;
  if(opt.input.empty()) throw Usage_error("no input file given");
  opt.has_size = c.vm.count("size") > 0;
  if(opt.has_size && (!(opt.size > 0) || !std::isfinite(opt.size)))
    throw Usage_error("--size must be a positive number");
  // read as a signed number: Boost reads "-1" into an unsigned as its largest value
  if(c.smooth < 0 || c.smooth > 1000) throw Usage_error("--smooth must be a number of passes from 0 to 1000");
  if(c.vm.count("min-angle") != 0 && !(opt.min_angle > 0 && opt.min_angle <= 30))
    throw Usage_error("--min-angle must be an angle in degrees above 0 and at most 30 (above 30 Delaunay "
                      "refinement need not terminate), not " + std::to_string(opt.min_angle));
  opt.smooth = std::size_t(c.smooth);
  if(opt.smoother != "quality" && opt.smoother != "laplacian")
    throw Usage_error("--smoother must be quality or laplacian, not '" + opt.smoother + "'");
  check_limits(c);
  opt.max_steps = std::size_t(c.max_steps);
  if(opt.svg_color != "plain" && opt.svg_color != "quality")
    throw Usage_error("--svg-color must be plain or quality, not '" + opt.svg_color + "'");
  parse_svg_window(c.svg_window, opt);
  opt.gradation = parse_grading(opt.grading);
  if(opt.boundary_spacing != "grow" && opt.boundary_spacing != "diffuse")
    throw Usage_error("--boundary-spacing must be grow or diffuse, not '" + opt.boundary_spacing + "'");
  if(opt.gradation == 0 && c.vm.count("boundary-spacing") && !c.vm["boundary-spacing"].defaulted() &&
     opt.boundary_spacing == "grow")
    throw Usage_error("--boundary-spacing grow needs a gradation (not --grading off)");
  if(opt.gradation == 0) opt.boundary_spacing = "diffuse"; // nothing to grow at
  if(opt.kernel != "epick" && opt.kernel != "epeck" && opt.kernel != "exact-rational")
    throw Usage_error("--kernel must be epick, epeck or exact-rational, not '" + opt.kernel + "'");
  check_output_formats(opt);
  if(opt.no_output && !opt.outputs.empty()) throw Usage_error("--no-output cannot be combined with -o");
  if(!c.checkpoint.empty()) parse_checkpoint(c.checkpoint, opt);
  set_default_outputs(opt);
  if(opt.stop_after_checkpoint && opt.checkpoint_every == 0)
    throw Usage_error("--stop-after-checkpoint needs --checkpoint-every");
  check_streaming(opt);
  resolve_threads(c);
}

// in resume.h
Options resumed_run_options(const Command_line& now);
std::string stored_arguments(const po::parsed_options& parsed, const Options& opt, bool resuming);

inline void print_version()
{
  std::cout << program << " " << CGAL_ADVANCING_FRONT_MESH_2_VERSION_STR << " (Advancing_front_mesh_2), built with CGAL "
            << CGAL_VERSION_STR << ", Boost " << BOOST_VERSION / 100000 << "." << BOOST_VERSION / 100 % 1000 << "."
            << BOOST_VERSION % 100 << ", "
            << (gdal_version().empty() ? std::string("without GDAL") : "GDAL " + gdal_version()) << ", "
            << (sizeof(void*) * 8) << "-bit"
#ifdef NDEBUG
            << ", assertions off"
#else
            << ", assertions on"
#endif
            << "\n";
}

// The options of `args`; with `resuming`, the options a checkpoint stored.
// --help and --version print and exit.
inline Options parse(const std::vector<std::string>& args, bool resuming = false)
{
  Command_line c;
  const po::options_description visible = read_command_line(args, c);
  if(!resuming && (c.vm.count("input-checksum") || c.vm.count("sources-checksum")))
    throw Usage_error("unrecognised option '--" + std::string(c.vm.count("input-checksum") ? "input" : "sources") +
                      "-checksum'");
  if(c.vm.count("help")) {
    std::cout << visible << "\nExit codes: 0 success, 1 invalid input, 2 bad usage, 3 an output or checkpoint that "
                            "could not be written, or an internal error.\n";
    std::exit(EXIT_SUCCESS);
  }
  if(c.vm.count("version")) {
    print_version();
    std::exit(EXIT_SUCCESS);
  }
  if(!c.opt.resume.empty()) {
    if(resuming) throw Usage_error("the checkpoint's stored options hold --resume");
    return resumed_run_options(c);
  }
  check_new_run(c);
  if(c.opt.checkpoint_every > 0) c.opt.arguments = stored_arguments(c.parsed, c.opt, resuming);
  return c.opt;
}

} // namespace afmesh_2

#endif // AFMESH_2_OPTIONS_H
