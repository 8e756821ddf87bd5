// A log-log line plot written as plain SVG, so that the benchmark needs no
// plotting tool: axes over whole decades, a grid line at every decade (and
// lighter ones at 2..9 times it), tick labels 10^k, a legend, and per series
// a polyline with markers.
#ifndef AFM_BENCHMARK_SVG_PLOT_H
#define AFM_BENCHMARK_SVG_PLOT_H

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace afm_bench {

struct Plot_series
{
  std::string name;
  std::string color;  // any SVG colour
  std::string marker; // "circle", "square", "triangle", "diamond"
  bool dashed = false;
  std::vector<std::pair<double, double> > points; // (x, y), both > 0
};

struct Log_log_plot
{
  std::string title, x_label, y_label;
  std::vector<Plot_series> series;
  double width = 900, height = 600;

  // Writes the plot; returns false if the file cannot be written or there
  // is no positive data point.
  bool write(const std::string& file) const
  {
    double xmin = std::numeric_limits<double>::infinity(), xmax = 0;
    double ymin = xmin, ymax = 0;
    for(const Plot_series& s : series)
      for(const auto& p : s.points) {
        if(!(p.first > 0) || !(p.second > 0)) continue;
        xmin = (std::min)(xmin, p.first);
        xmax = (std::max)(xmax, p.first);
        ymin = (std::min)(ymin, p.second);
        ymax = (std::max)(ymax, p.second);
      }
    if(!(xmax > 0) || !(ymax > 0)) return false;
    // whole decades about the data
    const int dx0 = int(std::floor(std::log10(xmin) + 1e-9)), dx1 = (std::max)(dx0 + 1, int(std::ceil(std::log10(xmax) - 1e-9)));
    const int dy0 = int(std::floor(std::log10(ymin) + 1e-9)), dy1 = (std::max)(dy0 + 1, int(std::ceil(std::log10(ymax) - 1e-9)));
    const double left = 90, right = 40, top = 50, bottom = 70;
    const double pw = width - left - right, ph = height - top - bottom;
    auto X = [&](double x) { return left + pw * (std::log10(x) - dx0) / (dx1 - dx0); };
    auto Y = [&](double y) { return top + ph * (1 - (std::log10(y) - dy0) / (dy1 - dy0)); };

    std::ostringstream os;
    os.precision(5);
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
       << "\" viewBox=\"0 0 " << width << " " << height << "\" font-family=\"sans-serif\">\n"
       << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    // grid: minor lines first so that the decade lines stay on top
    for(int d = dx0; d < dx1; ++d)
      for(int m = 2; m <= 9; ++m)
        vline(os, X(m * std::pow(10., d)), top, top + ph, "#eeeeee");
    for(int d = dy0; d < dy1; ++d)
      for(int m = 2; m <= 9; ++m)
        hline(os, Y(m * std::pow(10., d)), left, left + pw, "#eeeeee");
    for(int d = dx0; d <= dx1; ++d) {
      const double x = X(std::pow(10., d));
      vline(os, x, top, top + ph, "#bbbbbb");
      os << "<text x=\"" << x << "\" y=\"" << top + ph + 24 << "\" text-anchor=\"middle\" font-size=\"15\">10"
         << "<tspan dy=\"-7\" font-size=\"11\">" << d << "</tspan></text>\n";
    }
    for(int d = dy0; d <= dy1; ++d) {
      const double y = Y(std::pow(10., d));
      hline(os, y, left, left + pw, "#bbbbbb");
      os << "<text x=\"" << left - 10 << "\" y=\"" << y + 5 << "\" text-anchor=\"end\" font-size=\"15\">10"
         << "<tspan dy=\"-7\" font-size=\"11\">" << d << "</tspan></text>\n";
    }
    os << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
       << "\" fill=\"none\" stroke=\"black\" stroke-width=\"1.2\"/>\n";
    os << "<text x=\"" << left + pw / 2 << "\" y=\"" << top - 18 << "\" text-anchor=\"middle\" font-size=\"18\">"
       << escape(title) << "</text>\n";
    os << "<text x=\"" << left + pw / 2 << "\" y=\"" << height - 18 << "\" text-anchor=\"middle\" font-size=\"16\">"
       << escape(x_label) << "</text>\n";
    os << "<text transform=\"translate(" << 24 << "," << top + ph / 2 << ") rotate(-90)\" text-anchor=\"middle\""
       << " font-size=\"16\">" << escape(y_label) << "</text>\n";
    // series
    for(const Plot_series& s : series) {
      std::vector<std::pair<double, double> > pts;
      for(const auto& p : s.points)
        if(p.first > 0 && p.second > 0) pts.push_back(p);
      std::sort(pts.begin(), pts.end());
      if(pts.empty()) continue;
      os << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"2\""
         << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << " points=\"";
      for(const auto& p : pts) os << X(p.first) << "," << Y(p.second) << " ";
      os << "\"/>\n";
      for(const auto& p : pts) marker(os, s.marker, X(p.first), Y(p.second), s.color);
    }
    // legend in the upper left corner of the plot area, which log-log
    // plots of costs growing with size leave empty
    const double lx = left + 14, ly0 = top + 14, row = 24;
    std::size_t longest = 0;
    for(const Plot_series& s : series) longest = (std::max)(longest, s.name.size());
    os << "<rect x=\"" << lx << "\" y=\"" << ly0 << "\" width=\"" << 62 + 7.6 * double(longest) << "\" height=\""
       << row * double(series.size()) + 10 << "\" fill=\"white\" fill-opacity=\"0.9\" stroke=\"#888888\"/>\n";
    double ly = ly0 + 17;
    for(const Plot_series& s : series) {
      os << "<line x1=\"" << lx + 8 << "\" y1=\"" << ly << "\" x2=\"" << lx + 44 << "\" y2=\"" << ly << "\" stroke=\""
         << s.color << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << "/>\n";
      marker(os, s.marker, lx + 26, ly, s.color);
      os << "<text x=\"" << lx + 52 << "\" y=\"" << ly + 5 << "\" font-size=\"14\">" << escape(s.name) << "</text>\n";
      ly += row;
    }
    os << "</svg>\n";
    std::ofstream f(file);
    f << os.str();
    return bool(f);
  }

private:
  static void vline(std::ostream& os, double x, double y0, double y1, const char* color)
  {
    os << "<line x1=\"" << x << "\" y1=\"" << y0 << "\" x2=\"" << x << "\" y2=\"" << y1 << "\" stroke=\"" << color
       << "\" stroke-width=\"1\"/>\n";
  }
  static void hline(std::ostream& os, double y, double x0, double x1, const char* color)
  {
    os << "<line x1=\"" << x0 << "\" y1=\"" << y << "\" x2=\"" << x1 << "\" y2=\"" << y << "\" stroke=\"" << color
       << "\" stroke-width=\"1\"/>\n";
  }
  static void marker(std::ostream& os, const std::string& shape, double x, double y, const std::string& color)
  {
    const double r = 5;
    if(shape == "square") {
      os << "<rect x=\"" << x - r << "\" y=\"" << y - r << "\" width=\"" << 2 * r << "\" height=\"" << 2 * r
         << "\" fill=\"" << color << "\"/>\n";
    } else if(shape == "triangle") {
      os << "<polygon points=\"" << x << "," << y - 1.2 * r << " " << x - 1.1 * r << "," << y + 0.8 * r << " "
         << x + 1.1 * r << "," << y + 0.8 * r << "\" fill=\"" << color << "\"/>\n";
    } else if(shape == "diamond") {
      os << "<polygon points=\"" << x << "," << y - 1.3 * r << " " << x + 1.3 * r << "," << y << " " << x << ","
         << y + 1.3 * r << " " << x - 1.3 * r << "," << y << "\" fill=\"" << color << "\"/>\n";
    } else {
      os << "<circle cx=\"" << x << "\" cy=\"" << y << "\" r=\"" << r << "\" fill=\"" << color << "\"/>\n";
    }
  }
  static std::string escape(const std::string& s)
  {
    std::string r;
    for(char c : s) {
      if(c == '<') r += "&lt;";
      else if(c == '>') r += "&gt;";
      else if(c == '&') r += "&amp;";
      else r += c;
    }
    return r;
  }
};

} // namespace afm_bench

#endif // AFM_BENCHMARK_SVG_PLOT_H
