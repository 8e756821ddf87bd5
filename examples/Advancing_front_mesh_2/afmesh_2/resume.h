// afmesh_2: checkpoints and --resume. A checkpoint stores the run's own
// options; a resumed run parses them again, with what its command line adds.
#ifndef AFMESH_2_RESUME_H
#define AFMESH_2_RESUME_H

#include "input.h"
#include "options.h"

#include <CGAL/Advancing_front_mesher_2.h>
#include <CGAL/Advancing_front_mesh_2/internal/Binary_io.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace afmesh_2 {

// An absolute name, so that a checkpointed run can be resumed from another
// directory.
inline std::string absolute_path(const std::string& name)
{
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::absolute(name, ec);
  return ec ? name : p.lexically_normal().string();
}

// FNV-1a over the file's bytes, in hexadecimal ("" if it cannot be read):
// a resumed run must read the same input as the interrupted one.
inline std::string file_checksum(const std::string& name)
{
  std::ifstream is(name.c_str(), std::ios::in | std::ios::binary);
  if(!is) return std::string();
  // the hash the checkpoints themselves are checked with
  namespace AFMI = CGAL::Advancing_front_mesh_2::internal;
  std::uint64_t h = AFMI::fnv1a_offset_basis;
  char buffer[1 << 16];
  while(is.read(buffer, sizeof buffer) || is.gcount() > 0) {
    h = AFMI::fnv1a_update(h, buffer, std::size_t(is.gcount()));
    if(!is) break;
  }
  std::ostringstream os;
  os << std::hex << std::setw(16) << std::setfill('0') << h;
  return os.str();
}

inline std::string joined_arguments(const std::vector<std::string>& args)
{
  std::string joined;
  for(const std::string& a : args) {
    if(!joined.empty()) joined += '\0';
    joined += a;
  }
  return joined;
}

// The options a checkpoint stores, '\0'-separated: file names made absolute
// (a run may be resumed from another directory) and the checksums of the
// input files (a resumed run must read the same ones).
inline std::string stored_arguments(const po::parsed_options& parsed, const Options& opt, bool resuming)
{
  std::vector<std::string> out;
  for(const po::option& o : parsed.options) {
    if(o.string_key == "input") {
      out.push_back(absolute_path(o.value.at(0)));
      continue;
    }
    out.push_back("--" + o.string_key);
    for(std::size_t i = 0; i < o.value.size(); ++i) {
      const bool file = o.string_key == "sources" || o.string_key == "output" || o.string_key == "histogram" ||
                        (o.string_key == "checkpoint-every" && i == 1);
      out.push_back(file ? absolute_path(o.value[i]) : o.value[i]);
    }
  }
  if(!resuming) { // a resumed run's stored options hold them already
    // the size field's defaults as this version has them, so that a later
    // version with other defaults resumes the same field
    bool grading = false, spacing = false;
    for(const po::option& o : parsed.options) {
      grading = grading || o.string_key == "grading";
      spacing = spacing || o.string_key == "boundary-spacing";
    }
    if(!grading) out.insert(out.end(), {"--grading", opt.grading});
    if(!spacing) out.insert(out.end(), {"--boundary-spacing", opt.boundary_spacing});
    out.insert(out.end(), {"--input-checksum", file_checksum(opt.input)});
    if(!opt.sources.empty()) out.insert(out.end(), {"--sources-checksum", file_checksum(opt.sources)});
  }
  return joined_arguments(out);
}

// The interrupted run's options, as stored in its checkpoint.
inline std::vector<std::string> stored_options(const std::string& checkpoint)
{
  std::string stored;
  try {
    typedef Types<CGAL::Exact_predicates_inexact_constructions_kernel>::CDT CDT;
    stored = CGAL::Advancing_front_mesher_2<CDT>::read_checkpoint_info(checkpoint).user_data;
  } catch(const std::exception& e) {
    throw Input_error(e.what());
  }
  std::vector<std::string> args;
  for(std::size_t b = 0; b < stored.size();) {
    const std::size_t e = stored.find('\0', b);
    args.push_back(stored.substr(b, e == std::string::npos ? std::string::npos : e - b));
    b = (e == std::string::npos) ? stored.size() : e + 1;
  }
  return args;
}

// A new --checkpoint-every given with --resume: the checkpoints of this
// session store the new file, so that a later resume goes on writing there.
inline void take_new_checkpoints(const Command_line& now, const std::vector<std::string>& stored_args,
                                 Options& resumed)
{
  parse_checkpoint(now.checkpoint, resumed);
  std::vector<std::string> kept;
  for(std::size_t i = 0; i < stored_args.size(); ++i) {
    if(stored_args[i] == "--checkpoint-every") {
      i += 2;
      continue;
    }
    kept.push_back(stored_args[i]);
  }
  kept.insert(kept.end(), {"--checkpoint-every", now.checkpoint[0], absolute_path(now.checkpoint[1])});
  resumed.arguments = joined_arguments(kept);
}

// The options of `afmesh_2 --resume FILE ...`: the interrupted run's own,
// then what this command line adds (limits and reports; limits apply to a
// session: only those given now).
inline Options resumed_run_options(const Command_line& now)
{
  const Options& opt = now.opt;
  for(const auto& o : now.vm)
    if(!o.second.defaulted() && o.first != "resume" && o.first != "checkpoint-every" &&
       o.first != "stop-after-checkpoint" && o.first != "time-limit" && o.first != "max-steps" &&
       o.first != "stats" && o.first != "report")
      throw Usage_error("--resume takes the run's options from the checkpoint; --" + o.first + " cannot be given");
  const std::vector<std::string> stored_args = stored_options(opt.resume);
  Options resumed;
  try {
    resumed = parse(stored_args, true);
  } catch(const Usage_error& e) {
    throw Input_error(opt.resume + ": the stored options are not valid: " + e.what());
  }
  resumed.resume = opt.resume;
  resumed.threads = 1; // a checkpointed run is streamed, on one thread
  resumed.stats = opt.stats;
  resumed.report = opt.report;
  resumed.stop_after_checkpoint = opt.stop_after_checkpoint;
  resumed.time_limit = now.vm.count("time-limit") ? opt.time_limit : 0;
  resumed.max_steps = now.vm.count("max-steps") ? std::size_t(now.max_steps) : 0;
  if(!now.checkpoint.empty()) take_new_checkpoints(now, stored_args, resumed);
  if(resumed.stop_after_checkpoint && resumed.checkpoint_every == 0)
    throw Usage_error("--stop-after-checkpoint needs --checkpoint-every (given now or in the interrupted run)");
  check_limits(now);
  return resumed;
}

// The size field is made again from the input files: they must be those
// the checkpoint was made from.
inline void check_same_inputs(const Options& opt)
{
  if(opt.resume.empty()) return;
  if(!opt.input_checksum.empty() && file_checksum(opt.input) != opt.input_checksum)
    throw Input_error(opt.input + ": not the file the checkpoint " + opt.resume +
                      " was made from (its content changed)");
  if(!opt.sources_checksum.empty() && file_checksum(opt.sources) != opt.sources_checksum)
    throw Input_error(opt.sources + ": not the file the checkpoint " + opt.resume +
                      " was made from (its content changed)");
}

} // namespace afmesh_2

#endif // AFMESH_2_RESUME_H
