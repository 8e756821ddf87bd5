// afmesh_2: the mesh written in the formats of the outputs' extensions,
// and the quality histograms.
#ifndef AFMESH_2_OUTPUT_H
#define AFMESH_2_OUTPUT_H

#include "options.h"

#include <CGAL/Advancing_front_mesh_2/IO/write_mesh.h>
#include <CGAL/Advancing_front_mesh_2/IO/write_quality_histogram.h>
#include <CGAL/Advancing_front_mesh_2/Markers_and_regions_2.h>
#include <CGAL/Advancing_front_mesh_2/Mesh_quality.h>

#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

namespace afmesh_2 {

// Writes one output, with the markers and regions; throws what went wrong.
template <class CDT>
void write_output(const Options& opt, const std::string& out, const CDT& cdt,
                  const AFM::Markers_and_regions_2<CDT>& tags)
{
  if(!ends_with(out, ".svg")) {
    AFM::IO::write_mesh(out, cdt, tags, CGAL::parameters::use_binary_mode(!opt.vtu_ascii));
    return;
  }
  std::ofstream os(out);
  AFM::IO::SVG_options svg;
  svg.title = opt.input;
  svg.color_by_quality = opt.svg_color == "quality";
  if(!opt.svg_window.empty()) {
    svg.has_window = true;
    svg.xmin = opt.svg_window[0];
    svg.ymin = opt.svg_window[1];
    svg.xmax = opt.svg_window[2];
    svg.ymax = opt.svg_window[3];
  }
  AFM::IO::write_SVG(os, cdt, svg);
  os.close();
  if(os.fail()) throw std::runtime_error("cannot write " + out);
}

// Writes the outputs and the histogram; false (after saying which failed on
// stderr) when one could not be written. The regions are found on the
// final faces first.
template <class CDT>
bool write_outputs(const Options& opt, const CDT& cdt, AFM::Markers_and_regions_2<CDT>& tags,
                   const AFM::Mesh_quality& quality)
{
  if(tags.has_regions()) tags.mark_regions(cdt);
  auto failed = [](const std::string& out, const std::exception& e) {
    std::cerr << program << ": error: " << out << ": " << e.what() << "\n";
    return false;
  };
  for(const std::string& out : opt.outputs) {
    try {
      write_output(opt, out, cdt, tags);
    } catch(const std::exception& e) {
      return failed(out, e);
    }
  }
  if(opt.default_outputs) {
    const std::string stem = opt.outputs.front().substr(0, opt.outputs.front().size() - 5);
    std::cerr << program << ": note: no -o given: wrote " << stem << ".node, " << stem << ".ele and " << stem
              << ".edge, as Triangle does (-o FILE chooses the files and formats, --no-output writes none)\n";
  }
  if(!opt.histogram.empty()) {
    std::ofstream os(opt.histogram);
    AFM::IO::write_quality_histogram_SVG(os, quality, opt.input);
    os.close();
    if(os.fail()) return failed(opt.histogram, std::runtime_error("cannot write " + opt.histogram));
  }
  return true;
}

} // namespace afmesh_2

#endif // AFMESH_2_OUTPUT_H
