// afmesh_2: one run with kernel K, from the input to the outputs and the
// reports. Returns the exit code of a run that did not throw: 0, or 3 when
// an output or a checkpoint could not be written.
#ifndef AFMESH_2_RUN_H
#define AFMESH_2_RUN_H

#include "input.h"
#include "meshing.h"
#include "options.h"
#include "output.h"
#include "report.h"

#include <chrono>
#include <iostream>
#include <memory>

namespace afmesh_2 {

// A streamed run: the mesh is in the files; no quality figures, no pictures.
template <class K>
int finish_streamed_run(const Options& opt, Mesher<K>& mesher, AFM::Mesh_return_code rc,
                        Tagging_sink<K>* sink, double t_meshing,
                        std::chrono::steady_clock::time_point t_start)
{
  const AFM::Statistics& st = mesher.statistics();
  if(rc == AFM::STOPPED_AT_CHECKPOINT) {
    std::cerr << "afmesh_2: note: stopped after writing the checkpoint " << opt.checkpoint_file << " ("
              << st.number_of_faces << " triangles written so far); continue with: afmesh_2 --resume "
              << opt.checkpoint_file << "\n";
  } else if(sink != nullptr) {
    try {
      sink->close();
    } catch(const std::exception& e) {
      std::cerr << program << ": error: " << e.what() << "\n";
      return 3;
    }
  }
  if(opt.report) print_streamed_report(opt, st, t_meshing);
  if(opt.stats) print_statistics(streamed_statistics_json(opt, rc, st, t_meshing, seconds_since(t_start)));
  return 0;
}

// A run in memory: smoothing, outputs, quality figures.
template <class K>
int finish_run_in_memory(const Options& opt, Input<K>& in, const AFM::Statistics& st, AFM::Mesh_return_code rc,
                         Run_times t, std::chrono::steady_clock::time_point t_start,
                         const AFM::Parallel_mesh_statistics* parallel = nullptr)
{
  const bool want_quality = opt.stats || opt.report || !opt.histogram.empty();
  AFM::Mesh_quality unsmoothed;
  if(want_quality) unsmoothed = AFM::mesh_quality(in.cdt, in.sizing);
  const auto t_smooth = std::chrono::steady_clock::now();
  const AFM::Smoothing_statistics smoothing = smooth(opt, in);
  t.smoothing = seconds_since(t_smooth);
  const auto t_angle = std::chrono::steady_clock::now();
  const AFM::Minimum_angle_statistics angle = raise_minimum_angle(opt, in);
  t.min_angle = seconds_since(t_angle);
  const AFM::Mesh_quality q =
    want_quality && (opt.smooth > 0 || opt.min_angle > 0) ? AFM::mesh_quality(in.cdt, in.sizing) : unsmoothed;
  const auto t_write = std::chrono::steady_clock::now();
  if(!write_outputs(opt, in.cdt, in.tags, q)) return 3;
  t.writing = seconds_since(t_write);
  if(opt.report) print_report(opt, st, unsmoothed, q, smoothing, t, boundary_summary(opt, in), angle, parallel);
  t.total = seconds_since(t_start);
  if(opt.stats) print_statistics(statistics_json(opt, in, rc, st, q, smoothing, t, angle, parallel));
  return 0;
}

// --threads N above 1: the parts meshed at once (mesh_in_parts()), then
// the run in memory as on one thread.
template <class K>
int run_in_parallel(const Options& opt, Input<K>& in, std::chrono::steady_clock::time_point t_start)
{
  const auto t_mesh = std::chrono::steady_clock::now();
  AFM::Parallel_mesh_statistics parallel;
  const AFM::Mesh_return_code rc = mesh_in_parts<K>(opt, in, parallel);
  Run_times t;
  t.meshing = seconds_since(t_mesh);
  // the counters of every part's mesher, and the merged mesh's size
  AFM::Statistics st = AFM::sum_of(parallel.part_statistics);
  st.number_of_vertices = in.cdt.number_of_vertices();
  st.number_of_faces = 0;
  for(auto f = in.cdt.finite_faces_begin(); f != in.cdt.finite_faces_end(); ++f)
    if(f->is_in_domain()) ++st.number_of_faces;
  if(st.number_of_faces == 0)
    throw Input_error(opt.input + ": nothing to mesh: no bounded region is left once the holes are removed");
  return finish_run_in_memory<K>(opt, in, st, rc, t, t_start, &parallel);
}

template <class K>
int run(const Options& opt)
{
  const auto t_start = std::chrono::steady_clock::now();
  Input<K> in;
  load_input(opt, in);
  if(opt.threads > 1) return run_in_parallel<K>(opt, in, t_start);
  Progress_visitor progress;
  progress.enabled = isatty(2) != 0;
  // a resumed run meshes in an empty triangulation: the state comes from
  // the checkpoint; the input was read again for the size field only
  typename Types<K>::CDT resumed_cdt;
  Mesher<K> mesher(opt.resume.empty() ? in.cdt : resumed_cdt, in.sizing, progress);
  configure(opt, in, mesher);
  std::unique_ptr<Tagging_sink<K> > sink;
  if(opt.stream) sink = start_streaming<K>(opt, in, mesher);
  const auto t_mesh = std::chrono::steady_clock::now();
  AFM::Mesh_return_code rc = AFM::MESH_COMPLETE;
  if(!run_mesher<K>(opt, mesher, rc)) return 3;
  Run_times t;
  t.meshing = seconds_since(t_mesh);
  const AFM::Statistics& st = mesher.statistics();
  if(rc != AFM::STOPPED_AT_CHECKPOINT && st.number_of_faces == 0)
    throw Input_error(opt.input + ": nothing to mesh: no bounded region is left once the holes are removed");
  if(opt.stream) return finish_streamed_run<K>(opt, mesher, rc, sink.get(), t.meshing, t_start);
  return finish_run_in_memory<K>(opt, in, mesher.statistics(), rc, t, t_start);
}

} // namespace afmesh_2

#endif // AFMESH_2_RUN_H
