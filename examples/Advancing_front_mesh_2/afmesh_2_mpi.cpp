// afmesh_2_mpi: afmesh_2 on MPI ranks, for meshes larger than one machine.
//
//   mpirun -np N afmesh_2_mpi INPUT [--size H] [--sources FILE] [size options]
//          -o OUT.pvtu | --merge -o OUT.off|.vtu|.node|.ele|.msh|.svg|.poly
//          | --no-output
//          [--stats] [--report] [--histogram OUT.svg]
//
// Every rank reads INPUT and makes the size field, the boundary
// discretisation and the cuts of the decomposition itself (afmesh_2_mpi/
// parts.h): one part per rank, strips balanced by the triangle count the
// size field predicts, their interfaces discretised to the size field. Each
// rank meshes its part with the frontal mesher; the interfaces between the
// ranks are then released and the mesh made constrained Delaunay across
// them by merging a band of triangles on both sides (afmesh_2_mpi/bands.h).
// OUT.pvtu is a collection (ParaView, meshio) of one piece per rank,
// OUT_<rank>.vtu, with the global vertex numbers (point data GlobalNodeId)
// and the rank of each triangle (cell data partition), and the markers and
// regions as afmesh_2's .vtu has them (afmesh_2_mpi/tags.h); --merge writes
// one file instead, in any of afmesh_2's formats (rank 0 writes it as the
// ranks send their shares; afmesh_2_mpi/merged_formats.h).
//
// --stream meshes each rank's part in streaming mode, for parts larger than
// memory (afmesh_2_mpi/streamed.h): the triangles go to scratch files
// beside the pieces (OUT_<rank>.vtu.*, also with --merge) as they are
// finished, but for those near the cuts, which the interface merge needs;
// the pieces, or with --merge the one file, are then written from them.
//
// With --stream a rank keeps its part once meshed, and --checkpoint-every K
// checkpoints it every K triangles while it is meshed (the mesher's restart
// files, OUT_<rank>.vtu.checkpoint); the same command with --resume, after
// --stop-after-meshing, --stop-after-checkpoint or a failure, takes the
// kept parts, continues the others from their checkpoints and writes the
// uninterrupted run's pieces.
//
// --stats, --report and --histogram give afmesh_2's quality figures of the
// whole mesh, added up over the ranks (afmesh_2_mpi/quality.h), and each
// rank's figures (afmesh_2_mpi/report.h); with --stream, as afmesh_2
// --stream, no quality figures.
//
// The input and size options are afmesh_2's (afmesh_2 --help). Not on
// MPI: --keep-segments (the cuts split segments, as afmesh_2 --threads
// refuses it), --threads (one thread per rank: start more ranks) and
// --kernel other than epick; they are refused (exit 2). .svg and .poly
// need the whole mesh on rank 0, and are refused with --stream as afmesh_2
// refuses them.
// --smooth smooths each part before its interfaces are merged, its cuts
// held; --min-angle refines each rank's share after the merge, in rounds
// with its neighbours (afmesh_2_mpi/min_angle.h); --time-limit and
// --max-steps limit each rank's mesher.
//
// Exit codes as afmesh_2's: 0 success; 1 invalid input; 2 bad usage; 3 an
// output that could not be written, or an internal error.
#include "afmesh_2_mpi/channel.h"
#include "afmesh_2_mpi/merged_formats.h"
#include "afmesh_2_mpi/min_angle.h"
#include "afmesh_2_mpi/quality.h"
#include "afmesh_2_mpi/report.h"
#include "afmesh_2_mpi/streamed.h"
#include "afmesh_2_mpi/tags.h"

#include <CGAL/Advancing_front_mesh_2/IO/write_quality_histogram.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <sys/resource.h>
#include <vector>

namespace afmesh_2_mpi {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

struct Mpi_options
{
  afmesh_2::Options opt;
  std::vector<std::string> outputs;
  bool merge = false;
  bool help = false, version = false; // printed by rank 0 alone
  // --stream: each rank keeps its part once meshed, until the run ends;
  // --stop-after-meshing stops there, --resume takes the kept parts
  bool stop_after_meshing = false, resume = false;
  // --checkpoint-every K: each streamed rank checkpoints its part every K
  // triangles (--stop-after-checkpoint: stops after the first); --resume
  // goes on from there
  std::size_t checkpoint_every = 0;
  bool stop_after_checkpoint = false;
  std::uint64_t arguments_digest = 0; // of the arguments that make the parts
};

inline bool ends_with(const std::string& s, const std::string& tail) { return afmesh_2::ends_with(s, tail); }

// The value of --checkpoint-every: a count of triangles above 0.
inline std::size_t triangle_count_option(const std::string& option, const std::string& value)
{
  const bool digits = !value.empty() && value.size() <= 18 &&
                      value.find_first_not_of("0123456789") == std::string::npos;
  const std::size_t n = digits ? std::size_t(std::stoull(value)) : 0;
  if(n == 0) throw afmesh_2::Usage_error("the option '" + option + "' takes a number of triangles above 0, not '" +
                                         value + "'");
  return n;
}

// The tool's own options (-o, --merge) taken out, the others read by
// afmesh_2's parser; throws afmesh_2::Usage_error.
inline Mpi_options parse(const std::vector<std::string>& args)
{
  Mpi_options m;
  m.arguments_digest = digest_start;
  std::vector<std::string> rest;
  bool no_output = false, threads = false, stream = false;
  for(std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    // the checkpoints change nothing in the mesh: a resumed run may set
    // others, or none
    if(a == "--checkpoint-every" || a.compare(0, 19, "--checkpoint-every=") == 0) {
      if(a.size() == 18 && i + 1 == args.size())
        throw afmesh_2::Usage_error("the option '" + a + "' requires an argument");
      m.checkpoint_every = triangle_count_option("--checkpoint-every", a.size() == 18 ? args[++i] : a.substr(19));
      continue;
    }
    if(a == "--stop-after-checkpoint") {
      m.stop_after_checkpoint = true;
      continue;
    }
    // the options that make the parts go into the digest; not those that
    // only say what to print or how to write it, nor the limits, which
    // apply to the session they are given in (as afmesh_2 --resume takes
    // them): a resumed run may change these
    const char* session_value = nullptr;
    for(const char* f : {"--time-limit", "--max-steps", "--histogram"})
      if(a == f || a.compare(0, std::strlen(f) + 1, std::string(f) + "=") == 0) session_value = f;
    if(session_value != nullptr) {
      rest.push_back(a);
      if(a == session_value && i + 1 < args.size()) rest.push_back(args[++i]);
      continue;
    }
    const bool session_flag =
      a == "--stop-after-meshing" || a == "--resume" || a == "--stats" || a == "--report" || a == "--vtu-ascii";
    if(!session_flag) m.arguments_digest = digest_bytes(a.c_str(), a.size() + 1, m.arguments_digest);
    if(a == "--help" || a == "-h") {
      m.help = true;
      return m;
    }
    if(a == "--version") {
      m.version = true;
      return m;
    }
    if(a == "--merge") {
      m.merge = true;
    } else if(a == "--stream") {
      stream = true; // afmesh_2's parser would want its own -o
    } else if(a == "--stop-after-meshing") {
      m.stop_after_meshing = true;
      continue;
    } else if(a == "--resume") {
      m.resume = true; // not afmesh_2's --resume FILE: the parts are beside the pieces
      continue;
    } else if(a == "-o" || a == "--output") {
      if(i + 1 == args.size()) throw afmesh_2::Usage_error("the option '" + a + "' requires an argument");
      m.outputs.push_back(args[++i]);
    } else if(a.compare(0, 9, "--output=") == 0) {
      m.outputs.push_back(a.substr(9));
    } else {
      no_output = no_output || a == "--no-output";
      threads = threads || a == "--threads" || a.compare(0, 10, "--threads=") == 0;
      rest.push_back(a);
    }
  }
  if(no_output && !m.outputs.empty()) throw afmesh_2::Usage_error("--no-output cannot be combined with -o");
  if(!no_output) rest.push_back("--no-output");
  try {
    m.opt = afmesh_2::parse(rest);
  } catch(const afmesh_2::Usage_error& e) {
    // afmesh_2's --checkpoint-every K FILE: the FILE is left over as a
    // second input
    const std::string what = e.what();
    if(m.checkpoint_every > 0 && what.find("too many positional options") != std::string::npos)
      throw afmesh_2::Usage_error(what + " (afmesh_2_mpi takes --checkpoint-every K without a file: the "
                                         "checkpoints are beside the pieces)");
    throw;
  }
  m.opt.stream = stream;
  const afmesh_2::Options& o = m.opt;
  const char* refused = o.checkpoint_every > 0     ? "--checkpoint-every K FILE (here: --checkpoint-every K, "
                                                     "the checkpoints are beside the pieces)"
                        : !o.resume.empty()        ? "--resume=FILE (--resume takes no file here)"
                        : o.keep_segments          ? "--keep-segments"
                        : threads                  ? "--threads (one thread per rank: start more ranks)"
                        : o.kernel != "epick"      ? "--kernel other than epick"
                                                   : nullptr;
  if(refused != nullptr) throw afmesh_2::Usage_error(std::string("afmesh_2_mpi does not support ") + refused);
  if(m.outputs.empty() && !no_output)
    throw afmesh_2::Usage_error("no output: give -o OUT.pvtu, --merge -o OUT.vtu (or any of afmesh_2's formats), or --no-output");
  if(o.stream && o.smooth > 0)
    throw afmesh_2::Usage_error("--stream cannot be combined with --smooth (as with afmesh_2: the triangles are "
                                "written as they are finished)");
  if(o.stream && o.min_angle != 0)
    throw afmesh_2::Usage_error("--stream cannot be combined with --min-angle (as with afmesh_2: the refinement "
                                "needs the triangles in memory)");
  if(o.stream && !o.histogram.empty())
    throw afmesh_2::Usage_error("--stream cannot be combined with --histogram (no quality figures, as afmesh_2 "
                                "--stream)");
  if(o.stream && m.outputs.empty())
    throw afmesh_2::Usage_error("--stream keeps its scratch files beside the output: give -o OUT.pvtu, or --merge "
                                "-o OUT.vtu (or .off, .node, .ele, .msh)");
  if((m.stop_after_meshing || m.resume || m.checkpoint_every > 0) && !o.stream)
    throw afmesh_2::Usage_error(std::string(m.resume                ? "--resume"
                                            : m.stop_after_meshing ? "--stop-after-meshing"
                                                                   : "--checkpoint-every") +
                                " keeps the parts of a streamed run: add --stream");
  if(m.stop_after_checkpoint && m.checkpoint_every == 0)
    throw afmesh_2::Usage_error("--stop-after-checkpoint needs --checkpoint-every");
  for(const std::string& out : m.outputs) {
    if(!m.merge && !ends_with(out, ".pvtu"))
      throw afmesh_2::Usage_error("without --merge the output is a collection of pieces (.pvtu), not '" + out +
                                  "' (--merge writes one file, in any of afmesh_2's formats)");
  }
  if(m.merge) {
    // afmesh_2's formats, and what it refuses with --stream (they need the
    // whole mesh)
    afmesh_2::Options formats = o;
    formats.outputs = m.outputs;
    afmesh_2::check_output_formats(formats);
    afmesh_2::check_streaming(formats);
  }
  return m;
}

inline double seconds_since(std::chrono::steady_clock::time_point t)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Where a streamed rank keeps its scratch, kept part and checkpoint files:
// beside the first output, named as its piece (OUT_<rank>.vtu, also for
// --merge -o OUT.vtu or OUT.off).
inline std::string scratch_stem(const Mpi_options& m, int rank)
{
  const std::string& out = m.outputs.front();
  return m.merge ? out.substr(0, out.find_last_of('.')) + "_" + std::to_string(rank) + ".vtu"
                 : piece_name(out, rank);
}

// The files this rank writes for `out`: its piece (and, rank 0, the
// collection), or (rank 0) the merged file; the scratch files of --stream.
inline std::vector<std::string> files_of(const Mpi_options& m, const std::string& out, int rank)
{
  std::vector<std::string> files;
  if(!m.merge) files.push_back(piece_name(out, rank));
  else if(m.opt.stream && out == m.outputs.front()) files.push_back(scratch_stem(m, rank));
  if(rank != 0) return files;
  files.push_back(out);
  // -o OUT.node (or .ele) writes OUT.node, OUT.ele and OUT.edge
  if(m.merge && (ends_with(out, ".node") || ends_with(out, ".ele"))) {
    const std::string stem = out.substr(0, out.find_last_of('.'));
    for(const char* e : {".node", ".ele", ".edge"})
      if(stem + e != out) files.push_back(stem + e);
  }
  return files;
}

// An output that cannot be written must show before the meshing, on every
// rank at once: each rank tries a probe file beside each of its own (its
// name taken by no output), and rank 0 names the first that failed.
// Returns false then.
inline bool outputs_writable(const Mpi_options& m, int rank, int ranks)
{
  std::vector<std::vector<std::string> > groups;
  for(const std::string& out : m.outputs) groups.push_back(files_of(m, out, rank));
  // the histogram: rank 0 writes it
  if(!m.opt.histogram.empty())
    groups.push_back(rank == 0 ? std::vector<std::string>{m.opt.histogram} : std::vector<std::string>());
  for(const std::vector<std::string>& files : groups) {
    std::string failed;
    for(const std::string& mine : files) {
      const std::string probe = mine + ".afmesh_2_mpi-probe";
      const bool ok = bool(std::ofstream(probe.c_str(), std::ios::out | std::ios::binary | std::ios::app));
      std::remove(probe.c_str());
      if(!ok && failed.empty()) failed = mine;
    }
    const std::vector<char> all = gather_to_root<char>(failed.empty() ? 1 : 0, ranks);
    int first = -1;
    for(int r = 0; r < ranks && first < 0 && rank == 0; ++r)
      if(!all[std::size_t(r)]) first = r;
    // the rank that failed names its file to rank 0
    int named = first;
    MPI_Bcast(&named, 1, MPI_INT, 0, MPI_COMM_WORLD);
    if(named < 0) continue;
    if(named == rank && rank != 0) send_vector(std::vector<char>(failed.begin(), failed.end()), 0, OUTPUT_NAME);
    if(rank == 0) {
      const std::vector<char> name = named == 0 ? std::vector<char>(failed.begin(), failed.end())
                                                : receive_vector<char>(named, OUTPUT_NAME);
      std::cerr << "afmesh_2_mpi: error: cannot write " << std::string(name.begin(), name.end()) << "\n";
    }
    return false;
  }
  return true;
}

// A 64-bit digest of the decomposition: the ranks must all have made the
// same (the same input and options on every machine).
template <class K>
std::uint64_t digest(const Decomposition<K>& d)
{
  std::uint64_t h = digest_start;
  auto mix = [&h](const void* data, std::size_t n) { h = digest_bytes(data, n, h); };
  mix(&d.parts, sizeof d.parts);
  mix(&d.plan.axis, sizeof d.plan.axis);
  for(const auto& c : d.plan.cuts) mix(&c.position, sizeof c.position);
  for(const auto& points : d.interface_points)
    for(const auto& p : points) {
      mix(&p.first, sizeof p.first);
      mix(&p.second, sizeof p.second);
    }
  return h;
}

// The digest of the options that make the parts and of the input files'
// content (a file changed under the same name is another run's).
inline std::uint64_t input_files_digest(const Mpi_options& m)
{
  std::uint64_t h = m.arguments_digest;
  for(const std::string& f : {m.opt.input, m.opt.sources})
    if(!f.empty()) {
      const std::string sum = afmesh_2::file_checksum(f);
      h = digest_bytes(sum.data(), sum.size() + 1, h);
    }
  return h;
}

// --resume, for a part that was not kept whole: whether the part has a
// checkpoint of this run to go on from (ck.file, its user data the run's);
// if so, `stream` is set back to it. A checkpoint of another run is not
// taken (the part is meshed again); one that cannot be read stops the rank.
template <class K>
bool continue_from_checkpoint(Part_stream<K>& stream, const Part_checkpoints& ck)
{
  if(!std::ifstream(ck.file.c_str())) return false;
  try {
    const AFM::Checkpoint_info info = Part_mesher<K>::read_checkpoint_info(ck.file);
    if(info.user_data != ck.user_data) {
      std::cerr << "afmesh_2_mpi: note: " << ck.file
                << " is the checkpoint of another run (other options or input files): the part is meshed again\n";
      return false;
    }
    stream.resume_checkpoint(info.sink_state);
  } catch(const std::runtime_error& e) {
    throw std::runtime_error(std::string(e.what()) + " (delete " + ck.file + " to mesh the part again)");
  }
  return true;
}

inline int run(const Mpi_options& m, int rank, int ranks)
{
  const auto t_start = std::chrono::steady_clock::now();
  if(!outputs_writable(m, rank, ranks)) return 3;
  // every rank reads the input and decomposes the domain: invalid input
  // stops them all at the same place (rank 0 says why); a rank that fails
  // alone (a file another machine cannot see) says so itself. A part too
  // narrow for its interface bands, or parts that do not fit the domain
  // (as mesh_in_parallel_2() checks its threads' parts), make the ranks
  // start again with fewer parts.
  std::unique_ptr<afmesh_2::Input<K> > input;
  std::unique_ptr<Share_tags<K> > tags;
  Decomposition<K> d;
  CDT<K> part_cdt;
  std::size_t part = 0;
  std::string fewer_parts_reason;
  for(std::size_t wanted = std::size_t(ranks);;) {
    input.reset(new afmesh_2::Input<K>());
    std::string input_error;
    try {
      afmesh_2::load_input(m.opt, *input);
      // found on the input before the cuts are made in it
      tags.reset(new Share_tags<K>(input->cdt, input->tags));
      Share_tags<K>& t = *tags;
      d = decompose<K>(*input, int(wanted), [&t](const typename K::Point_2& a, const typename K::Point_2& b,
                                                  const typename K::Point_2& v) { t.split_segment(a, b, v); });
    } catch(const afmesh_2::Input_error& e) {
      input_error = e.what();
    } catch(const std::invalid_argument& e) {
      input_error = m.opt.input + ": " + e.what();
    }
    if(any_rank(!input_error.empty())) {
      const bool everyone = all_ranks(!input_error.empty());
      if(!input_error.empty() && (rank == 0 || !everyone))
        std::cerr << "afmesh_2_mpi: " << (everyone ? std::string() : "rank " + std::to_string(rank) + ": ")
                  << "error: " << input_error << "\n";
      return 1;
    }
    const std::uint64_t mine = digest(d);
    std::uint64_t low = 0, high = 0;
    MPI_Allreduce(&mine, &low, 1, MPI_UINT64_T, MPI_MIN, MPI_COMM_WORLD);
    MPI_Allreduce(&mine, &high, 1, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
    if(low != high) {
      if(rank == 0)
        std::cerr << "afmesh_2_mpi: error: the ranks cut the domain differently (do they read the same input "
                     "with the same options and the same build?)\n";
      return 3;
    }
    const double ratio = narrowest_part_ratio(d, initial_band_sizes);
    if(d.parts > 2 && ratio < 1) {
      const std::size_t fewer =
        (std::max)(std::size_t(2), (std::min)(d.parts - 1, std::size_t(double(d.parts) * ratio)));
      fewer_parts_reason = std::to_string(d.parts) + " parts: one was narrower than its interface bands";
      wanted = fewer;
      continue;
    }
    // this rank's part: with one part, rank 0 meshes the input's
    // triangulation with afmesh_2's serial mesher
    part = d.parts == 1 ? (rank == 0 ? 0 : 1) : std::size_t(rank);
    part_cdt.clear();
    if(d.parts > 1 && part < d.parts) build_part<K>(*input, d, part, part_cdt);
    if(!parts_fit<K>(*input, d, part, part_cdt, rank, ranks)) {
      fewer_parts_reason = std::to_string(d.parts) + " parts did not fit the domain";
      wanted = 1;
      continue;
    }
    break;
  }
  afmesh_2::Input<K>& in = *input;
  const double t_decomposition = seconds_since(t_start);

  const auto t_mesh = std::chrono::steady_clock::now();
  const bool has_part = part < d.parts;
  CDT<K>& meshed = d.parts == 1 ? in.cdt : part_cdt;
  // --stream: a part kept by a previous run of the same command is taken
  // as it is (--resume), or continued from its checkpoint; a part meshed
  // is kept until the run ends, so that a run that fails after it can be
  // resumed without meshing it again
  const std::uint64_t run_digest = digest(d) ^ input_files_digest(m);
  const std::string stem = m.opt.stream ? scratch_stem(m, rank) : std::string();
  std::unique_ptr<Part_stream<K> > stream;
  if(m.opt.stream) stream.reset(new Part_stream<K>(d, part, meshed, stem, run_digest, *tags));
  Part_checkpoints ck;
  if(stream) {
    ck.every = m.checkpoint_every;
    ck.file = Part_stream<K>::checkpoint_file(stem);
    ck.user_data = "afmesh_2_mpi run " + std::to_string(run_digest);
    ck.stop = m.stop_after_checkpoint;
  }
  bool resumed = false;
  if(stream && has_part && m.resume) {
    resumed = stream->resume();
    if(!resumed && std::ifstream(Part_stream<K>::kept_part_file(stem).c_str()))
      std::cerr << "afmesh_2_mpi: note: " << Part_stream<K>::kept_part_file(stem)
                << " is not whole, or the part of another run (other options or input files), or its scratch "
                   "files are not there: the part is not taken\n";
    if(!resumed) ck.resume = continue_from_checkpoint<K>(*stream, ck);
  }
  if(stream && has_part && !resumed) {
    if(ck.resume) std::remove(Part_stream<K>::kept_part_file(stem).c_str());
    else stream->start_anew();
    // a checkpoint on disk refers to the scratch files
    if(ck.every > 0 || ck.resume) stream->keep_scratch();
  }
  AFM::Statistics st;
  AFM::Mesh_return_code rc = AFM::MESH_COMPLETE;
  // from here on a rank may fail alone: what it throws must not pass for
  // invalid input (which every rank would see), but end every rank
  // (main()'s MPI_Abort), or its neighbours would wait for it forever
  try {
    if(resumed) {
      st.number_of_faces = stream->streamed_triangles() + stream->held().size();
    } else if(has_part && d.parts == 1) {
      rc = mesh_whole<K>(m.opt, in, stream.get(), ck, st);
    } else if(has_part) {
      rc = mesh_part<K>(m.opt, in, part_cdt, stream.get(), ck, st);
    }
  } catch(const std::invalid_argument& e) {
    throw std::runtime_error(std::string("meshing the part: ") + e.what());
  }
  const double t_meshing = seconds_since(t_mesh);
  // --smooth: each part smoothed in memory before its interfaces are
  // merged, its cuts held (the one part: as afmesh_2 smooths)
  AFM::Smoothing_statistics smoothing;
  double t_smoothing = 0;
  if(!stream && has_part && m.opt.smooth > 0) {
    const auto t_smooth = std::chrono::steady_clock::now();
    smoothing = d.parts == 1 ? afmesh_2::smooth(m.opt, in) : smooth_part<K>(m.opt, part_cdt, d.free_points[part]);
    t_smoothing = seconds_since(t_smooth);
  }
  const bool stopped = rc == AFM::STOPPED_AT_CHECKPOINT;
  if(stream && has_part && !resumed && !stopped) {
    stream->close();
    stream->keep();
  }
  const std::uint64_t parts_resumed = sum_over_ranks(resumed ? 1 : 0);
  const std::uint64_t parts_stopped = sum_over_ranks(stopped ? 1 : 0);
  const std::uint64_t timed_out = sum_over_ranks(rc == AFM::TIME_LIMIT_REACHED ? 1 : 0);
  const std::uint64_t out_of_steps = sum_over_ranks(rc == AFM::ITERATION_LIMIT_REACHED ? 1 : 0);
  for(const auto& limit : {std::make_pair("--time-limit", timed_out), std::make_pair("--max-steps", out_of_steps)})
    if(rank == 0 && limit.second > 0)
      std::cerr << "afmesh_2_mpi: note: " << m.opt.input << ": " << limit.first << " reached on " << limit.second
                << " of " << d.parts
                << " parts: the rest of their fronts was closed on existing points (valid, coarser there)\n";
  if(parts_stopped > 0) {
    if(rank == 0)
      std::cerr << "afmesh_2_mpi: note: " << parts_stopped << " of " << d.parts
                << " parts stopped after a checkpoint (OUT_<rank>.vtu.checkpoint beside the pieces), the others are "
                   "meshed and kept; the same command with --resume instead of --stop-after-checkpoint goes on from "
                   "there\n";
    return 0;
  }
  if(m.stop_after_meshing) {
    if(rank == 0)
      std::cerr << "afmesh_2_mpi: note: the parts are meshed and kept beside the pieces (" << parts_resumed
                << " taken from the previous run); the same command with --resume instead of "
                   "--stop-after-meshing merges them and writes the pieces\n";
    return 0;
  }
  if(sum_over_ranks(st.number_of_faces) == 0)
    throw afmesh_2::Input_error(m.opt.input +
                                ": nothing to mesh: no bounded region is left once the holes are removed");

  // the interfaces merged, the rank's share numbered, its quality added to
  // the others' (not streamed: as afmesh_2 --stream, no quality figures)
  // and written
  Share_figures share;
  double t_interfaces = 0, t_writing = 0, t_quality = 0;
  const bool want_quality = !stream && (m.opt.stats || m.opt.report || !m.opt.histogram.empty());
  AFM::Mesh_quality quality;
  Min_angle_figures min_angle;
  if(stream) {
    const auto t_merge = std::chrono::steady_clock::now();
    Interface_work<K, Band<K, std::size_t> > w;
    merge_interfaces<K>(
      in, d, rank, [&](std::size_t c, double width) { return stream->band(c, width); }, most_streamed_widenings, w);
    const Streamed_share mesh = streamed_share<K>(*stream, w, rank);
    t_interfaces = seconds_since(t_merge);
    const auto t_write = std::chrono::steady_clock::now();
    if(m.merge)
      write_merged_outputs<K>(m.opt, m.outputs, [&] { return merged_share<K>(*stream, mesh); }, in.tags,
                              tags->attributes(), rank, ranks);
    else
      for(const std::string& out : m.outputs) write_streamed_piece<K>(out, *stream, mesh, rank, ranks, !m.opt.vtu_ascii);
    t_writing = seconds_since(t_write);
    // every piece is written: the kept parts go
    if(all_ranks(true) && has_part) stream->discard();
    share = share_figures(w, mesh.triangle_count(), mesh.owned.total());
    share.held_triangles = stream->held().size();
  } else {
    const auto t_merge = std::chrono::steady_clock::now();
    Interface_work<K> w;
    merge_interfaces<K>(in, d, rank, meshed, w, m.opt.min_angle);
    Rank_mesh mesh;
    double t_refining = 0; // this rank's --min-angle time, not the interfaces'
    std::uint64_t registered_splits = 0, counted_splits = 0;
    if(m.opt.min_angle > 0) {
      // --min-angle: each share refined in rounds with its neighbours
      // (min_angle.h); one part: the input's triangulation on rank 0. When
      // no share has a triangle below the bound (smoothed meshes of smooth
      // fields), the shares are left as they are
      const auto t_angle = std::chrono::steady_clock::now();
      const bool whole = d.parts == 1 && has_part;
      CDT<K> share_cdt;
      std::vector<unsigned char> input_constraints;
      Rank_mesh share;
      if(d.parts > 1) share = rank_mesh<K>(meshed, w, rank, has_part, &input_constraints);
      const AFM::Minimum_angle_statistics unrefined = share_angles(share, m.opt.min_angle);
      if(d.parts > 1 && !any_rank(unrefined.below_before > 0)) {
        share = Rank_mesh();
        mesh = rank_mesh<K>(meshed, w, rank, has_part);
        min_angle = min_angle_figures(unrefined, 0, 0, 0, seconds_since(t_angle));
      } else {
        const auto once = share_triangulation<K>(share, input_constraints, share_cdt);
        share = Rank_mesh();
        Share_refinement<K> refinement(whole ? meshed : share_cdt, *tags, rank, w.has_lower ? rank - 1 : -1,
                                       w.has_upper ? rank + 1 : -1);
        refinement.find_shared_edges(once);
        refinement.refine(m.opt.min_angle, most_refinement_rounds);
        mesh = d.parts == 1 ? rank_mesh<K>(meshed, w, rank, has_part)
                            : refined_rank_mesh<K>(share_cdt, refinement, rank);
        registered_splits = refinement.registered_segment_splits();
        counted_splits = refinement.counted_segment_splits();
        min_angle = min_angle_figures(refinement.statistics(), refinement.rounds(), refinement.upper_points(),
                                      refinement.upper_delaunay_splits(), seconds_since(t_angle));
      }
      t_refining = seconds_since(t_angle);
      if(rank == 0 && !min_angle.total.completed)
        std::cerr << "afmesh_2_mpi: warning: " << m.opt.input << ": --min-angle " << m.opt.min_angle
                  << ": the refinement stopped at its limit with " << min_angle.total.below_after
                  << " triangles below the bound (the mesh is valid)\n";
    } else {
      mesh = rank_mesh<K>(meshed, w, rank, has_part);
    }
    mesh.tags = tag_share<K>(*tags, mesh.points, mesh.triangles);
    check_segments_found<K>(*tags, mesh.tags.segments.size(), registered_splits, counted_splits);
    t_interfaces = seconds_since(t_merge) - t_refining;
    if(want_quality) {
      const auto t_q = std::chrono::steady_clock::now();
      quality = mesh_quality_over_ranks<typename K::Point_2>(mesh, in.sizing, rank, ranks);
      t_quality = seconds_since(t_q);
    }
    const auto t_write = std::chrono::steady_clock::now();
    if(m.merge)
      write_merged_outputs<K>(m.opt, m.outputs, [&] { return merged_share(mesh); }, in.tags, tags->attributes(),
                              rank, ranks);
    else
      for(const std::string& out : m.outputs) write_piece(out, mesh, rank, ranks, !m.opt.vtu_ascii);
    t_writing = seconds_since(t_write);
    share = share_figures(w, mesh.triangles.size(), mesh.owned_count);
  }

  // the figures of every rank, printed by rank 0
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  const Rank_figures mine{t_meshing, t_interfaces, t_writing, double(usage.ru_maxrss) / 1024, share, int(rc),
                          resumed, ck.resume, std::uint64_t(st.checkpoints_written), t_smoothing,
                          std::uint64_t(smoothing.passes), std::uint64_t(smoothing.moves),
                          std::uint64_t(smoothing.rejected_moves), std::uint64_t(smoothing.flips)};
  const std::vector<Rank_figures> all = gather_to_root(mine, ranks);
  if(rank != 0) return 0;
  const Run_summary<K> summary{m.opt, d, fewer_parts_reason, all, want_quality ? &quality : nullptr,
                               t_decomposition, t_quality, seconds_since(t_start),
                               m.opt.min_angle > 0 ? &min_angle : nullptr};
  if(m.opt.report) afmesh_2::print_report_text(m.opt, report_text(summary, afmesh_2::boundary_summary(m.opt, in)));
  // input names that are not UTF-8 with replacement characters, as afmesh_2
  if(m.opt.stats) afmesh_2::print_statistics(statistics_json(summary));
  if(!m.opt.histogram.empty()) {
    std::ofstream os(m.opt.histogram);
    AFM::IO::write_quality_histogram_SVG(os, quality, m.opt.input);
    os.close();
    if(os.fail()) {
      std::cerr << "afmesh_2_mpi: error: cannot write " << m.opt.histogram << "\n";
      return 3;
    }
  }
  return 0;
}

} // namespace afmesh_2_mpi

int main(int argc, char* argv[])
{
  using namespace afmesh_2_mpi;
  Mpi_session mpi(argc, argv);
  auto say = [&](const std::string& what) {
    if(mpi.rank == 0) std::cerr << "afmesh_2_mpi: " << what << "\n";
  };
  Mpi_options m;
  try {
    m = parse(std::vector<std::string>(argv + 1, argv + argc));
    if(m.help && mpi.rank == 0)
      std::cout << "Usage: mpirun -np N afmesh_2_mpi INPUT [--size H] [--sources FILE] [size opts]\n"
                   "         (-o OUT.pvtu | --merge -o OUT.EXT...) [--stream [--checkpoint-every K]\n"
                   "         [--resume]] | --no-output\n"
                   "         [--stats] [--report] [--histogram OUT.svg]\n\n"
                   "Meshes the domain of INPUT as afmesh_2 does, one part per MPI rank. -o OUT.pvtu\n"
                   "writes one piece per rank (OUT_<rank>.vtu) and their collection; --merge writes\n"
                   "one file, EXT any of afmesh_2's formats (.off .vtu .node/.ele .msh .svg .poly;\n"
                   "-o repeatable; not .svg and .poly with --stream). --stream meshes each part in\n"
                   "streaming mode (parts larger than memory; scratch files beside the output,\n"
                   "OUT_<rank>.vtu.*). A streamed rank keeps its part, once meshed, until the\n"
                   "output is written: --stop-after-meshing stops there, and the same command with\n"
                   "--resume (after a stop or a failure) meshes only the parts not kept.\n"
                   "--checkpoint-every K (with --stream) checkpoints each part every K triangles\n"
                   "while it is meshed (OUT_<rank>.vtu.checkpoint); --resume goes on from there.\n"
                   "--stop-after-checkpoint stops each rank after its first checkpoint.\n"
                   "--smooth N smooths each part before the interfaces are merged, its cuts held\n"
                   "(not with --stream); --min-angle A refines each rank's share after the merge, the\n"
                   "ranks exchanging the points on their shared edges (not with --stream);\n"
                   "--time-limit and --max-steps limit each rank's mesher.\n"
                   "--stats, --report and --histogram give the quality of the whole mesh as afmesh_2\n"
                   "does (not with --stream), and each rank's figures.\n"
                   "The input and size options are afmesh_2's (afmesh_2 --help).\n\n"
                   "Exit codes: 0 success, 1 invalid input, 2 bad usage, 3 an output that could not\n"
                   "be written, or an internal error.\n";
    if(m.version && mpi.rank == 0) afmesh_2::print_version();
    if(m.help || m.version) return 0;
  } catch(const afmesh_2::Usage_error& e) {
    say(std::string(e.what()) + "\nTry 'afmesh_2_mpi --help'.");
    return 2;
  } catch(const afmesh_2::Input_error& e) {
    say(std::string("error: ") + e.what());
    return 1;
  }
  // every rank reads the input and meshes in the same way, so invalid input
  // stops them all at the same place; anything else may stop one rank only,
  // and MPI_Abort then ends them all
  try {
    return run(m, mpi.rank, mpi.ranks);
  } catch(const afmesh_2::Input_error& e) {
    say(std::string("error: ") + e.what());
    return 1;
  } catch(const std::invalid_argument& e) {
    say("error: " + m.opt.input + ": " + e.what());
    return 1;
  } catch(const std::exception& e) {
    std::cerr << "afmesh_2_mpi: rank " << mpi.rank << ": error: " << e.what() << "\n";
    MPI_Abort(MPI_COMM_WORLD, 3);
    return 3;
  }
}
