// Figures as inline SVG for the HTML report (no script, no external resource): line plots with
// axes, ticks, labels and a legend, and a field coloured over the deformed mesh with a colour bar.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::post {

/// One curve of a line plot. A point with a value that is not finite (or not > 0 on a
/// logarithmic axis) is left out and breaks the line there.
struct PlotSeries {
  std::string name;           ///< the legend's text
  std::string role;           ///< its polylines' data-series attribute (a test finds them by it)
  std::vector<double> x, y;   ///< the same length
  bool markers = false;       ///< a dot at every point
  bool dashed = false;
  /// Whether the axes' ranges take in this series; a series that does not is clipped at the
  /// frame (a curve with a spike that would flatten the others).
  bool sets_range = true;
};

struct LinePlot {
  std::string figure;  ///< the <svg>'s data-figure attribute
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
  std::vector<PlotSeries> series;
  int width = 540, height = 320;  ///< of the plot without its legend [px]
};

/// The plot as an <svg> element: a frame with ticks and their values, the axis labels, the
/// title above, a polyline per series (class "series", data-series = role, one point per
/// drawn point; clipped at the frame) and the legend below the axes, a line per series. The
/// axes span the series that set the range (all if none does).
std::string line_plot_svg(const LinePlot& plot);

/// A scalar field on quadrilateral cells of the deformed mesh.
struct FieldPlot {
  std::string figure;  ///< the <svg>'s data-figure attribute
  std::string title, value_label;
  std::vector<std::array<Vec2, 4>> cells;  ///< corners counter-clockwise
  std::vector<double> values;              ///< one per cell
  std::vector<std::vector<Vec2>> outlines;  ///< closed polylines drawn over the cells (elements)
  double value_min = 0, value_max = 1;     ///< the colour bar's range (values outside it clipped)
  /// The part of the plane shown {x_min, x_max, y_min, y_max}; none: every cell.
  std::optional<std::array<double, 4>> window;
  int width = 540, max_height = 480;  ///< [px]; lengths are drawn to one scale in x and y
};

/// The field as an <svg> element: cells filled by a perceptually uniform colour map (dark blue
/// at value_min to yellow at value_max; polygons of class "cell", only those that reach into
/// the window; the count in data-cells), the outlines, axes with ticks and a colour bar. The
/// figure is `width` wide at most (narrower for a tall window).
std::string field_plot_svg(const FieldPlot& plot);

/// The colour of t ∈ [0, 1] (clamped) on the field plot's map, as "#rrggbb".
std::string field_colour(double t);

/// Tick positions for an axis over [lo, hi]: steps of 1, 2 or 5 times a power of ten, 4 to 10
/// of them, within [lo, hi] (to 1e-9 of a step); a range of round-off (1e-12 relative, a uniform
/// field's): its middle alone; logarithmic (lo > 0): the powers of ten inside, with 2 and 5 times
/// them when fewer than three powers fall inside.
std::vector<double> axis_ticks(double lo, double hi, bool logarithmic);

}  // namespace hpcontact::post
