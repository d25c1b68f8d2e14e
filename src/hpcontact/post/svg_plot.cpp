// SVG line plots and field plots for the HTML report.
#include "hpcontact/post/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "hpcontact/post/html_text.hpp"

namespace hpcontact::post {

namespace {

const char* const kSeriesColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                                      "#9467bd", "#8c564b", "#e377c2", "#17becf"};

/// A pixel coordinate: two decimals are a hundredth of a pixel.
std::string px(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v + 0.0);
  return buffer;
}

/// A pixel coordinate of a field's cell or outline: a tenth of a pixel (the page stays small).
std::string px1(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v + 0.0);
  return buffer;
}

/// An axis: the data interval [lo, hi] (log10 of it on a logarithmic axis) onto [p0, p1] px.
struct Axis {
  double lo = 0, hi = 1;
  bool logarithmic = false;
  double p0 = 0, p1 = 1;
  double value(double v) const { return logarithmic ? std::log10(v) : v; }
  double to_px(double v) const { return p0 + (value(v) - lo) / (hi - lo) * (p1 - p0); }
  bool accepts(double v) const { return std::isfinite(v) && (!logarithmic || v > 0); }
};

/// The interval an axis shows for these values (in its own scale: log10 on a log axis), padded
/// by 4 % each side; a single value is widened.
std::array<double, 2> axis_range(const std::vector<double>& values, bool logarithmic) {
  double lo = INFINITY, hi = -INFINITY;
  for (const double v : values) {
    const double w = logarithmic ? std::log10(v) : v;
    lo = std::min(lo, w);
    hi = std::max(hi, w);
  }
  if (!(lo <= hi)) return {0, 1};
  if (hi - lo <= 1e-12 * std::max(1.0, std::abs(hi))) {
    const double half = logarithmic ? 0.5 : std::max(std::abs(hi) * 0.1, 1e-300);
    return {lo - half, hi + half};
  }
  const double pad = 0.04 * (hi - lo);
  return {lo - pad, hi + pad};
}

/// The tick values (data values) of an axis.
std::vector<double> ticks_of(const Axis& a) {
  return a.logarithmic ? axis_ticks(std::pow(10.0, a.lo), std::pow(10.0, a.hi), true)
                       : axis_ticks(a.lo, a.hi, false);
}

/// The frame of a plot area, the ticks and their values, and the axis labels.
void draw_axes(std::ostringstream& svg, const Axis& x, const Axis& y, const std::string& x_label,
               const std::string& y_label) {
  svg << "<rect x=\"" << px(x.p0) << "\" y=\"" << px(y.p1) << "\" width=\"" << px(x.p1 - x.p0)
      << "\" height=\"" << px(y.p0 - y.p1) << "\" fill=\"none\" stroke=\"#444\"/>\n";
  for (const double t : ticks_of(x)) {
    const double p = x.to_px(t);
    svg << "<line x1=\"" << px(p) << "\" y1=\"" << px(y.p0) << "\" x2=\"" << px(p) << "\" y2=\""
        << px(y.p0 + 5) << "\" stroke=\"#444\"/><text x=\"" << px(p) << "\" y=\"" << px(y.p0 + 18)
        << "\" text-anchor=\"middle\" class=\"tick\">" << escape_html(short_number(t)) << "</text>\n";
  }
  for (const double t : ticks_of(y)) {
    const double p = y.to_px(t);
    svg << "<line x1=\"" << px(x.p0 - 5) << "\" y1=\"" << px(p) << "\" x2=\"" << px(x.p0)
        << "\" y2=\"" << px(p) << "\" stroke=\"#444\"/><text x=\"" << px(x.p0 - 8) << "\" y=\""
        << px(p + 4) << "\" text-anchor=\"end\" class=\"tick\">" << escape_html(short_number(t))
        << "</text>\n";
  }
  svg << "<text x=\"" << px(0.5 * (x.p0 + x.p1)) << "\" y=\"" << px(y.p0 + 38)
      << "\" text-anchor=\"middle\" class=\"label\">" << escape_html(x_label) << "</text>\n";
  svg << "<text transform=\"translate(14," << px(0.5 * (y.p0 + y.p1))
      << ") rotate(-90)\" text-anchor=\"middle\" class=\"label\">" << escape_html(y_label)
      << "</text>\n";
}

/// The pieces of a series between the points an axis cannot show, in px.
std::vector<std::vector<std::array<double, 2>>> pieces(const PlotSeries& s, const Axis& x,
                                                        const Axis& y) {
  std::vector<std::vector<std::array<double, 2>>> all(1);
  for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (x.accepts(s.x[i]) && y.accepts(s.y[i])) {
      all.back().push_back({x.to_px(s.x[i]), y.to_px(s.y[i])});
    } else if (!all.back().empty()) {
      all.emplace_back();
    }
  }
  if (all.back().empty()) all.pop_back();
  return all;
}

/// The opening tag of a figure; `attributes` (" name=\"value\"...") added to it.
std::string svg_open(const std::string& figure, int width, int height,
                     const std::string& attributes = "") {
  std::ostringstream os;
  os << "<svg data-figure=\"" << escape_html(figure)
     << "\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << ' '
     << height << "\" font-family=\"sans-serif\" font-size=\"12\"" << attributes << ">\n";
  return os.str();
}

}  // namespace

std::vector<double> axis_ticks(double lo, double hi, bool logarithmic) {
  std::vector<double> ticks;
  if (!(lo < hi) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) return {0.5 * (lo + hi)};
  if (logarithmic) {
    if (!(lo > 0)) return ticks;
    const int k0 = static_cast<int>(std::floor(std::log10(lo))), k1 = static_cast<int>(std::ceil(std::log10(hi)));
    const int every = std::max(1, (k1 - k0 + 7) / 8);  // at most 9 decades labelled
    for (int k = k0; k <= k1; ++k) {
      const double v = std::pow(10.0, k);
      if (v >= lo * (1 - 1e-12) && v <= hi * (1 + 1e-12) && (k - k0) % every == 0) ticks.push_back(v);
    }
    if (ticks.size() < 3) {
      ticks.clear();
      for (int k = k0; k <= k1; ++k)
        for (const double m : {1.0, 2.0, 5.0}) {
          const double v = m * std::pow(10.0, k);
          if (v >= lo * (1 - 1e-12) && v <= hi * (1 + 1e-12)) ticks.push_back(v);
        }
    }
    return ticks;
  }
  // the finest of 1, 2, 5 times a power of ten that gives at most 10 ticks: the one before gave
  // more than 10 with a step at most 2.5 times finer, so this one gives at least 4
  const double power = std::pow(10.0, std::floor(std::log10((hi - lo) / 10)));
  auto count = [&](double step) { return std::floor(hi / step + 1e-9) - std::ceil(lo / step - 1e-9) + 1; };
  double step = 20 * power;  // (hi - lo) / power is below 100: 20 gives at most 6
  for (const double m : {1.0, 2.0, 5.0, 10.0, 20.0})
    if (count(m * power) <= 10) {
      step = m * power;
      break;
    }
  // k counted in integers: for a range of a few ulps (a uniform field's round-off) k * step
  // would be beyond 2^53, where k + 1 == k
  const double k0 = std::ceil(lo / step - 1e-9);
  for (int i = 0; i < 10 && (k0 + i) * step <= hi + 1e-9 * step; ++i) {
    const double v = (k0 + i) * step;
    ticks.push_back(std::abs(v) < 1e-9 * step ? 0.0 : v);
  }
  return ticks;
}

std::string line_plot_svg(const LinePlot& plot) {
  const double left = 84, right = 20, top = 30, bottom = 52;
  std::vector<double> xs, ys;
  const bool any_sets = std::any_of(plot.series.begin(), plot.series.end(),
                                    [](const PlotSeries& s) { return s.sets_range; });
  for (const auto& s : plot.series) {
    if (any_sets && !s.sets_range) continue;
    for (size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      const bool x_ok = std::isfinite(s.x[i]) && (!plot.log_x || s.x[i] > 0);
      const bool y_ok = std::isfinite(s.y[i]) && (!plot.log_y || s.y[i] > 0);
      if (x_ok && y_ok) {
        xs.push_back(s.x[i]);
        ys.push_back(s.y[i]);
      }
    }
  }
  const auto xr = axis_range(xs, plot.log_x), yr = axis_range(ys, plot.log_y);
  const Axis x{xr[0], xr[1], plot.log_x, left, plot.width - right};
  const Axis y{yr[0], yr[1], plot.log_y, plot.height - bottom, top};
  const int legend_rows = static_cast<int>(plot.series.size());
  const int height = plot.height + 18 * legend_rows + 6;
  std::ostringstream svg;
  svg << svg_open(plot.figure, plot.width, height);
  svg << "<text x=\"" << px(0.5 * (x.p0 + x.p1)) << "\" y=\"18\" text-anchor=\"middle\" "
      << "font-weight=\"bold\">" << escape_html(plot.title) << "</text>\n";
  draw_axes(svg, x, y, plot.x_label, plot.y_label);
  const std::string clip = "clip-" + escape_html(plot.figure);
  svg << "<defs><clipPath id=\"" << clip << "\"><rect x=\"" << px(x.p0) << "\" y=\"" << px(y.p1)
      << "\" width=\"" << px(x.p1 - x.p0) << "\" height=\"" << px(y.p0 - y.p1)
      << "\"/></clipPath></defs>\n";
  if (xs.empty())
    svg << "<text x=\"" << px(0.5 * (x.p0 + x.p1)) << "\" y=\"" << px(0.5 * (y.p0 + y.p1))
        << "\" text-anchor=\"middle\">no values to plot</text>\n";
  for (size_t k = 0; k < plot.series.size(); ++k) {
    const auto& s = plot.series[k];
    const std::string colour = kSeriesColours[k % std::size(kSeriesColours)];
    const std::string dash = s.dashed ? " stroke-dasharray=\"6 3\"" : "";
    for (const auto& piece : pieces(s, x, y)) {
      svg << "<polyline clip-path=\"url(#" << clip << ")\" class=\"series\" data-series=\"" << escape_html(s.role)
          << "\" fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.6\"" << dash
          << " points=\"";
      for (size_t i = 0; i < piece.size(); ++i)
        svg << (i ? " " : "") << px(piece[i][0]) << ',' << px(piece[i][1]);
      svg << "\"/>\n";
      if (s.markers)
        for (const auto& p : piece)
          svg << "<circle clip-path=\"url(#" << clip << ")\" cx=\"" << px(p[0]) << "\" cy=\"" << px(p[1]) << "\" r=\"2.5\" fill=\""
              << colour << "\"/>\n";
    }
    const double row = plot.height + 18.0 * k + 10;
    svg << "<line x1=\"" << px(left) << "\" y1=\"" << px(row) << "\" x2=\"" << px(left + 28)
        << "\" y2=\"" << px(row) << "\" stroke=\"" << colour << "\" stroke-width=\"2\"" << dash
        << "/><text x=\"" << px(left + 36) << "\" y=\"" << px(row + 4) << "\">"
        << escape_html(s.name) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

std::string field_colour(double t) {
  // viridis at five stops, linear in between
  static const double stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
  const double f = t * 4;
  const int i = std::min(3, static_cast<int>(f));
  const double w = f - i;
  char buffer[8];
  int rgb[3];
  for (int c = 0; c < 3; ++c) rgb[c] = static_cast<int>(std::lround(stops[i][c] * (1 - w) + stops[i + 1][c] * w));
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return buffer;
}

namespace {

/// The window of a field plot: the given one, or the cells' bounding box.
std::array<double, 4> field_window(const FieldPlot& plot) {
  if (plot.window) return *plot.window;
  std::array<double, 4> w{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const auto& cell : plot.cells)
    for (const Vec2& p : cell) {
      w[0] = std::min(w[0], p.x());
      w[1] = std::max(w[1], p.x());
      w[2] = std::min(w[2], p.y());
      w[3] = std::max(w[3], p.y());
    }
  if (!(w[0] <= w[1])) return {0, 1, 0, 1};
  const double size = std::max({w[1] - w[0], w[3] - w[2], 1e-300});
  const double pad = 0.02 * size;
  return {w[0] - pad, w[1] + pad, w[2] - pad, w[3] + pad};
}

bool reaches_into(const std::array<Vec2, 4>& cell, const std::array<double, 4>& w) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const Vec2& p : cell) {
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }
  return x1 >= w[0] && x0 <= w[1] && y1 >= w[2] && y0 <= w[3];
}

/// The colour bar right of the plot area: a gradient from value_min (bottom) to value_max.
void draw_colour_bar(std::ostringstream& svg, const FieldPlot& plot, double x0, double top,
                     double bottom) {
  const std::string id = "bar-" + escape_html(plot.figure);
  svg << "<defs><linearGradient id=\"" << id << "\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">";
  for (int i = 0; i <= 8; ++i)
    svg << "<stop offset=\"" << i / 8.0 << "\" stop-color=\"" << field_colour(i / 8.0) << "\"/>";
  svg << "</linearGradient></defs>\n";
  svg << "<rect x=\"" << px(x0) << "\" y=\"" << px(top) << "\" width=\"16\" height=\""
      << px(bottom - top) << "\" fill=\"url(#" << id << ")\" stroke=\"#444\"/>\n";
  const Axis bar{plot.value_min, plot.value_max, false, bottom, top};
  if (!(plot.value_max > plot.value_min)) return;
  for (const double t : axis_ticks(plot.value_min, plot.value_max, false)) {
    const double p = bar.to_px(t);
    svg << "<line x1=\"" << px(x0 + 16) << "\" y1=\"" << px(p) << "\" x2=\"" << px(x0 + 21)
        << "\" y2=\"" << px(p) << "\" stroke=\"#444\"/><text x=\"" << px(x0 + 24) << "\" y=\""
        << px(p + 4) << "\" class=\"tick\">" << escape_html(short_number(t)) << "</text>\n";
  }
}

}  // namespace

std::string field_plot_svg(const FieldPlot& plot) {
  const double left = 84, right = 110, top = 30, bottom = 52;
  const auto w = field_window(plot);
  const double area_w = plot.width - left - right;
  const double scale = std::min(area_w / (w[1] - w[0]), (plot.max_height - top - bottom) / (w[3] - w[2]));
  const double area_h = scale * (w[3] - w[2]);
  const int height = static_cast<int>(std::ceil(top + area_h + bottom));
  const double drawn_w = scale * (w[1] - w[0]);
  const int width = static_cast<int>(std::ceil(left + drawn_w + right));
  const Axis x{w[0], w[1], false, left, left + drawn_w};
  const Axis y{w[2], w[3], false, top + area_h, top};
  std::ostringstream svg;
  std::ostringstream cells;
  int n_drawn = 0;
  const double range = plot.value_max - plot.value_min;
  for (size_t c = 0; c < plot.cells.size(); ++c) {
    if (!reaches_into(plot.cells[c], w)) continue;
    ++n_drawn;
    const double t = range > 0 ? (plot.values[c] - plot.value_min) / range : 0.5;
    const std::string colour = field_colour(t);
    cells << "<polygon class=\"cell\" fill=\"" << colour << "\" stroke=\"" << colour << "\" points=\"";
    for (int k = 0; k < 4; ++k)
      cells << (k ? " " : "") << px1(x.to_px(plot.cells[c][k].x())) << ','
            << px1(y.to_px(plot.cells[c][k].y()));
    cells << "\"/>\n";
  }
  svg << svg_open(plot.figure, width, height, " data-cells=\"" + std::to_string(n_drawn) + "\"");
  svg << "<text x=\"" << px(0.5 * (x.p0 + x.p1)) << "\" y=\"18\" text-anchor=\"middle\" "
      << "font-weight=\"bold\">" << escape_html(plot.title) << "</text>\n";
  const std::string clip = "clip-" + escape_html(plot.figure);
  svg << "<defs><clipPath id=\"" << clip << "\"><rect x=\"" << px(x.p0) << "\" y=\"" << px(y.p1)
      << "\" width=\"" << px(x.p1 - x.p0) << "\" height=\"" << px(y.p0 - y.p1)
      << "\"/></clipPath></defs>\n<g clip-path=\"url(#" << clip << ")\" stroke-width=\"0.4\">\n"
      << cells.str();
  for (const auto& outline : plot.outlines) {
    svg << "<polygon class=\"outline\" fill=\"none\" stroke=\"#222\" stroke-width=\"0.6\" points=\"";
    for (size_t i = 0; i < outline.size(); ++i)
      svg << (i ? " " : "") << px1(x.to_px(outline[i].x())) << ',' << px1(y.to_px(outline[i].y()));
    svg << "\"/>\n";
  }
  svg << "</g>\n";
  draw_axes(svg, x, y, "x", "y");
  draw_colour_bar(svg, plot, left + drawn_w + 18, top, top + area_h);
  svg << "<text transform=\"translate(" << px(width - 8) << ',' << px(top + 0.5 * area_h)
      << ") rotate(-90)\" text-anchor=\"middle\" class=\"label\">" << escape_html(plot.value_label)
      << "</text>\n</svg>\n";
  return svg.str();
}

}  // namespace hpcontact::post
