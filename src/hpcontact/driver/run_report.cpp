// The sections of report.html, each from summary.json's data, the contact rows or the input.
#include "hpcontact/driver/run_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <sstream>

#include "hpcontact/post/field_cells.hpp"
#include "hpcontact/post/html_text.hpp"
#include "hpcontact/post/output_file.hpp"
#include "hpcontact/post/svg_plot.hpp"

namespace hpcontact::driver {

namespace {

using nlohmann::json;
using post::escape_html;

/// The value at a dotted path of summary.json ("contact_pairs.0.zone.from"; an array's items by
/// index), or null.
const json* at_key(const json& root, const std::string& key) {
  const json* node = &root;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (node->is_object()) {
      if (!node->contains(part)) return nullptr;
      node = &(*node)[part];
    } else if (node->is_array() && !part.empty() &&
               std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      const std::size_t i = std::stoul(part);
      if (i >= node->size()) return nullptr;
      node = &(*node)[i];
    } else {
      return nullptr;
    }
    if (dot == std::string::npos) return node;
    start = dot + 1;
  }
}

/// A JSON value as the page shows it: numbers to 10 digits, strings escaped.
std::string value_text(const json& v) {
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (v.is_number()) return post::number_text(v.get<double>());
  if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
  if (v.is_string()) return escape_html(v.get<std::string>());
  if (v.is_null()) return "none";
  return escape_html(v.dump());
}

/// A table cell of summary.json's value at `key`, marked with the key; "—" if there is none.
std::string key_cell(const json& summary, const std::string& key) {
  const json* v = at_key(summary, key);
  if (!v) return "<td>—</td>";
  const bool number = v->is_number();
  return std::string("<td") + (number ? " class=\"num\"" : "") + " data-key=\"" + escape_html(key) +
         "\">" + value_text(*v) + "</td>";
}

/// The units of the quantities shown: the input's (hpcontact has none of its own), by name as
/// docs/input.md gives them; an axisymmetric problem's forces and energy are the whole solid's.
struct Units {
  bool axisymmetric = false;
  std::string of(const std::string& kind) const {
    if (kind == "force") return axisymmetric ? "force" : "force/length";
    if (kind == "energy") return axisymmetric ? "force·length" : "force·length/length";
    if (kind == "stress") return "force/length²";
    return kind;
  }
};

struct Quantity {
  const char* key;   ///< below the row's prefix
  const char* label;
  const char* unit;  ///< a kind Units::of knows, or a unit as written
};

/// Rows of a table of numbers: the quantities summary.json has under `prefix`.
std::string quantity_rows(const json& summary, const std::string& prefix,
                          const std::vector<Quantity>& quantities, const Units& units,
                          const std::string& first_cell = "") {
  std::ostringstream os;
  for (const auto& q : quantities) {
    const std::string key = prefix + q.key;
    if (!at_key(summary, key)) continue;
    os << "<tr>" << first_cell << "<td>" << escape_html(q.label) << "</td>" << key_cell(summary, key)
       << "<td>" << escape_html(units.of(q.unit)) << "</td></tr>\n";
  }
  return os.str();
}

std::string status_section(const json& summary) {
  if (summary.value("converged", false))
    return "<p class=\"banner converged\" data-status=\"converged\">The run converged.</p>\n";
  std::string cause = summary.value("message", "");
  if (cause.empty() && summary.contains("adapt")) cause = summary["adapt"].value("message", "");
  if (cause.empty()) cause = "it did not converge";
  return "<p class=\"banner failed\" data-status=\"failed\">The run failed: " + escape_html(cause) +
         "; this is the last converged state, not a result.</p>\n";
}

const char* plane_name(model::PlaneMode p) {
  switch (p) {
    case model::PlaneMode::plane_strain: return "plane strain";
    case model::PlaneMode::plane_stress: return "plane stress";
    case model::PlaneMode::axisymmetric: return "axisymmetric";
  }
  return "";
}

std::string material_text(const model::MaterialSpec& m, const Units& units) {
  std::ostringstream os;
  os << escape_html(m.model) << ": ";
  if (m.C10 != 0 || m.C01 != 0 || m.C20 != 0 || m.C30 != 0) {
    os << "C10 = " << post::number_text(m.C10);
    if (m.C01 != 0) os << ", C01 = " << post::number_text(m.C01);
    if (m.C20 != 0) os << ", C20 = " << post::number_text(m.C20);
    if (m.C30 != 0) os << ", C30 = " << post::number_text(m.C30);
    os << ", K = " << post::number_text(m.K);
  } else {
    os << "E = " << post::number_text(m.youngs_modulus) << ", ν = " << post::number_text(m.poisson_ratio);
  }
  os << " (" << escape_html(units.of("stress")) << ")";
  return os.str();
}

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return escape_html(s);
}

const char* shape_name(model::LoadShape s) {
  switch (s) {
    case model::LoadShape::constant: return "constant";
    case model::LoadShape::linear: return "linear";
    case model::LoadShape::bspline1: return "bspline1";
    case model::LoadShape::bspline2: return "bspline2";
    case model::LoadShape::hermite: return "hermite";
    case model::LoadShape::expression: return "expression";
  }
  return "";
}

std::string bodies_table(const model::ProblemSpec& spec, const Units& units) {
  std::ostringstream os;
  os << "<table data-table=\"bodies\"><tr><th>body</th><th>material</th><th>plane</th>"
        "<th>thickness</th><th>nodes</th><th>elements</th><th>degree</th></tr>\n";
  for (const auto& b : spec.bodies) {
    const auto degree = b.degree.value_or(spec.discretization.degree);
    os << "<tr><td data-body>" << escape_html(b.name) << "</td><td>" << material_text(b.material, units)
       << (b.regions.empty() ? "" : " and " + std::to_string(b.regions.size()) + " region(s)")
       << "</td><td>" << plane_name(b.material.plane) << "</td><td class=\"num\">"
       << post::number_text(b.material.thickness) << "</td><td class=\"num\">" << b.nodes.size()
       << "</td><td class=\"num\">" << b.elements.size() << "</td><td>" << degree[0] << " × "
       << degree[1] << (b.element_degrees.empty() ? "" : ", per element") << "</td></tr>\n";
  }
  os << "</table>\n";
  return os.str();
}

std::string loads_table(const model::ProblemSpec& spec, const Units& units) {
  std::ostringstream os;
  int n = 0;
  os << "<table data-table=\"loads\"><tr><th>body</th><th>load</th><th>where</th><th>value</th></tr>\n";
  for (const auto& b : spec.bodies) {
    const std::string body = "<tr><td>" + escape_html(b.name) + "</td>";
    for (const auto& l : b.edge_loads) {
      ++n;
      os << body << "<td>" << (l.kind == model::LoadKind::pressure ? "pressure" : "traction") << ", "
         << shape_name(l.shape);
      if (!l.expression.empty()) os << ' ' << escape_html(l.expression);
      os << "</td><td>edges " << joined(l.edge_sets) << "</td><td>";
      if (l.kind == model::LoadKind::pressure) os << post::number_text(l.value[0]);
      else os << "(" << post::number_text(l.value[0]) << ", " << post::number_text(l.value[1]) << ")";
      os << " " << escape_html(units.of("stress"));
      if (l.resultant) os << ", scaled to a resultant " << post::number_text(*l.resultant) << " " << escape_html(units.of("force"));
      os << "</td></tr>\n";
    }
    for (const auto& f : b.nodal_forces) {
      ++n;
      os << body << "<td>nodal force</td><td>node " << f.node << "</td><td>("
         << post::number_text(f.force[0]) << ", " << post::number_text(f.force[1]) << ") force</td></tr>\n";
    }
    if (b.body_force[0] != 0 || b.body_force[1] != 0) {
      ++n;
      os << body << "<td>body force</td><td>every element</td><td>(" << post::number_text(b.body_force[0])
         << ", " << post::number_text(b.body_force[1]) << ") force/length³</td></tr>\n";
    }
    for (const auto& c : b.constraints) {
      ++n;
      os << body << "<td>prescribed displacement</td><td>";
      if (!c.edge_sets.empty()) os << "edges " << joined(c.edge_sets);
      if (!c.nodes.empty()) {
        os << (c.edge_sets.empty() ? "" : "; ") << "nodes";
        for (const int id : c.nodes) os << ' ' << id;
      }
      os << "</td><td>u<sub>x</sub> = " << escape_html(c.ux.value_or("free")) << ", u<sub>y</sub> = "
         << escape_html(c.uy.value_or("free")) << " (length)</td></tr>\n";
    }
  }
  os << "</table>\n";
  return n ? os.str() : "<p>No loads or supports.</p>\n";
}

std::string pairs_table(const model::ProblemSpec& spec, const json& summary) {
  if (spec.contact.empty()) return "<p>No contact pairs.</p>\n";
  std::ostringstream os;
  os << "<table data-table=\"pairs\"><tr><th>pair</th><th>body</th><th>against</th><th>enforcement</th>"
        "<th>surface</th><th>friction</th></tr>\n";
  for (size_t k = 0; k < spec.contact.size(); ++k) {
    const std::string p = "contact_pairs." + std::to_string(k) + ".";
    const auto& f = spec.contact[k].friction;
    os << "<tr><td class=\"num\">" << k << "</td>" << key_cell(summary, p + "body")
       << key_cell(summary, p + "obstacle") << key_cell(summary, p + "enforcement")
       << key_cell(summary, p + "surface") << "<td>" << escape_html(f.law)
       << (f.law == "coulomb" ? ", μ = " + post::number_text(f.mu) : "") << "</td></tr>\n";
  }
  os << "</table>\n";
  return os.str();
}

std::string problem_section(const RunReport& r, const Units& units) {
  const auto& spec = r.spec;
  std::ostringstream os;
  os << "<h2>The problem</h2>\n<p>Problem file <code data-file>" << escape_html(spec.file)
     << "</code>; method " << value_text(r.summary.value("method", json("")))
     << ", " << r.discretization.bodies.size() << " body(ies).</p>\n";
  os << "<h3>Bodies and materials</h3>\n" << bodies_table(spec, units);
  os << "<h3>Loads and supports</h3>\n" << loads_table(spec, units);
  os << "<h3>Contact pairs</h3>\n" << pairs_table(spec, r.summary);
  return os.str();
}

const std::vector<Quantity> kRunQuantities = {
    {"dofs", "degrees of freedom", ""},
    {"strain_energy", "strain energy", "energy"},
    {"load_factor", "load factor (displacements)", ""},
    {"loads_factor", "load factor (loads)", ""},
    {"load_steps", "load steps", ""},
    {"newton_iterations", "Newton iterations of the result's solve", ""},
    {"newton_iterations_total", "Newton iterations in all", ""},
    {"equilibrium_residual", "equilibrium residual (relative)", ""},
    {"wall_time_s", "wall time", "s"}};

const std::vector<Quantity> kPairQuantities = {
    {"normal_force", "normal force", "force"},
    {"tangential_force", "tangential force", "force"},
    {"resultant.0", "resultant, x", "force"},
    {"resultant.1", "resultant, y", "force"},
    {"pressure_max", "largest pressure", "stress"},
    {"traction_max", "largest traction", "stress"},
    {"half_width", "half-width", "length"},
    {"contact_length", "contact length", "length"},
    {"zone.from", "zone from", "length"},
    {"zone.to", "zone to", "length"},
    {"max_penetration", "largest penetration", "length"},
    {"hertz_half_width", "Hertz half-width", "length"},
    {"hertz_peak_pressure", "Hertz peak pressure", "stress"},
    {"friction.tangential_traction_integral", "∫ t_T dS", "force"},
    {"friction.tangential_force_ratio", "|∫ t_T dS| / (μ ∫ p dS)", ""},
    {"friction.stick_points", "sticking points", ""},
    {"friction.slip_points", "slipping points", ""}};

std::string numbers_section(const json& summary, const Units& units) {
  std::ostringstream os;
  os << "<h2>Key numbers</h2>\n<div class=\"row\">\n<div><h3>The run</h3>\n<table data-table=\"numbers\">"
        "<tr><th>quantity</th><th>value</th><th>unit</th></tr>\n"
     << quantity_rows(summary, "", kRunQuantities, units) << "</table></div>\n";
  const json* pairs = at_key(summary, "contact_pairs");
  if (pairs && pairs->is_array())
    for (size_t k = 0; k < pairs->size(); ++k) {
      os << "<div><h3>Pair " << k << " (body " << value_text((*pairs)[k].value("body", json(""))) << ")</h3>\n"
         << "<table data-table=\"pair-numbers\"><tr><th>quantity</th><th>value</th><th>unit</th></tr>\n"
         << quantity_rows(summary, "contact_pairs." + std::to_string(k) + ".", kPairQuantities, units)
         << "</table></div>\n";
    }
  os << "</div>\n";
  return os.str();
}

const std::vector<Quantity> kPressureErrors = {
    {"e_L2_hertz_percent", "pressure error against Hertz, L2", "%"},
    {"e_L2_shtayerman_percent", "pressure error against Shtayerman, L2", "%"},
    {"e_L2_reference_percent", "pressure error against the reference curve, L2", "%"},
    {"e_seed_hertz_percent", "pressure error against Hertz, the seed's measure", "%"},
    {"e_seed_shtayerman_percent", "pressure error against Shtayerman, the seed's measure", "%"},
    {"e_seed_reference_percent", "pressure error against the reference, the seed's measure", "%"}};

std::string errors_section(const json& summary, const Units& units) {
  std::ostringstream rows;
  rows << quantity_rows(summary, "error.",
                        {{"energy_rel_percent", "energy error (relative, seed eq. 4.3)", "%"},
                         {"energy_norm_rel_percent", "error in the energy norm (relative)", "%"}},
                        units, "<td>exact solution</td>");
  rows << quantity_rows(summary, "adapt.estimated_error.",
                        {{"pressure_rel_L2", "estimated pressure error (relative L2)", ""},
                         {"shear_rel_L2", "estimated shear error (relative L2)", ""},
                         {"energy_rel", "estimated energy error (relative)", ""}},
                        units, "<td>hp estimate: one degree more</td>");
  const json* pairs = at_key(summary, "contact_pairs");
  if (pairs && pairs->is_array())
    for (size_t k = 0; k < pairs->size(); ++k)
      for (const std::string sub : {"", "multiplier.", "penalty_traction."}) {
        const std::string prefix = "contact_pairs." + std::to_string(k) + "." + sub;
        const std::string what = sub.empty() ? "the pressure" : sub == "multiplier." ? "the multiplier" : "the penalty traction";
        rows << quantity_rows(summary, prefix, kPressureErrors, units,
                              "<td>pair " + std::to_string(k) + ", " + what + "</td>");
      }
  const std::string body = rows.str();
  if (body.empty()) return "<h2>Error measures</h2>\n<p>None: no exact solution, comparison or estimate was asked for.</p>\n";
  return "<h2>Error measures</h2>\n<table data-table=\"errors\"><tr><th>of</th><th>measure</th>"
         "<th>value</th><th>unit</th></tr>\n" + body + "</table>\n";
}

std::string warnings_section(const json& summary, const Units& units) {
  std::ostringstream os;
  os << "<h2>Warnings</h2>\n";
  const json* warnings = at_key(summary, "warnings");
  if (warnings && warnings->is_array() && !warnings->empty()) {
    os << "<ul data-list=\"warnings\">\n";
    for (const auto& w : *warnings) os << "<li>" << value_text(w) << "</li>\n";
    os << "</ul>\n";
  } else {
    os << "<p>No warnings.</p>\n";
  }
  const json* pairs = at_key(summary, "contact_pairs");
  if (!pairs || !pairs->is_array()) return os.str();
  for (size_t k = 0; k < pairs->size(); ++k) {
    const json& points = (*pairs)[k].value("singular_points", json::array());
    if (points.empty()) continue;
    os << "<h3>Singular points of pair " << k << "</h3>\n<p class=\"note\">Where the pressure "
          "has no converged peak: the largest pressure beyond the excluded distance and the fitted "
          "strength are the figures to use.</p>\n<table data-table=\"singular-points\"><tr><th>where</th>"
          "<th>at x</th><th>at y</th><th>peak</th><th>excluded within</th><th>largest pressure beyond</th>"
          "<th>fitted exponent</th></tr>\n";
    for (size_t i = 0; i < points.size(); ++i) {
      const std::string p = "contact_pairs." + std::to_string(k) + ".singular_points." + std::to_string(i) + ".";
      os << "<tr>" << key_cell(summary, p + "where") << key_cell(summary, p + "at.0")
         << key_cell(summary, p + "at.1") << key_cell(summary, p + "peak")
         << key_cell(summary, p + "excluded_within") << key_cell(summary, p + "pressure_max_beyond")
         << key_cell(summary, p + "fit.exponent") << "</tr>\n";
    }
    os << "</table>\n<p class=\"note\">Lengths in length, pressures in " << escape_html(units.of("stress")) << ".</p>\n";
  }
  return os.str();
}

post::LinePlot plot_of(const std::string& figure, const std::string& title, const std::string& x_label,
                       const std::string& y_label, bool log_x = false, bool log_y = false) {
  post::LinePlot p;
  p.figure = figure;
  p.title = title;
  p.x_label = x_label;
  p.y_label = y_label;
  p.log_x = log_x;
  p.log_y = log_y;
  return p;
}

/// The rows of pair k on one body, in the order of its boundary (not sorted by s: a boundary
/// may run back along the obstacle's frame, the inside of a ring around a disc).
std::vector<size_t> side_rows(const ContactTable& t, int k, const std::string& body) {
  std::vector<size_t> rows;
  for (size_t i = 0; i < t.size(); ++i)
    if (t.pair[i] == k && t.body[i] == body) rows.push_back(i);
  return rows;
}

/// A column of the rows against s; the one from the stresses (dashed) is clipped at the axes the
/// method's own values set (the stresses' spike at a singular point would flatten them).
post::PlotSeries column_series(const ContactTable& t, const std::vector<size_t>& rows,
                               const std::vector<double>& column, const std::string& name,
                               const std::string& role, bool from_stress) {
  post::PlotSeries s{name, role, {}, {}, false, from_stress, !from_stress};
  for (const size_t i : rows) {
    s.x.push_back(t.s[i]);
    s.y.push_back(column[i]);
  }
  return s;
}

std::string contact_section(const RunReport& r, const Units& units) {
  const ContactTable& t = r.contact;
  if (t.size() == 0) return "";
  std::ostringstream os;
  os << "<h2>Along the contact pairs</h2>\n<p class=\"note\">s: the position along the obstacle "
        "(the pair's surface frame, contact.csv's s). The pressure is the contact force per unit "
        "length along the obstacle; \"from the stresses\" the same taken from the body's stresses "
        "(dashed, cut off where it leaves the frame).</p>\n";
  int n_pairs = 0;
  for (const int k : t.pair) n_pairs = std::max(n_pairs, k + 1);
  for (int k = 0; k < n_pairs; ++k) {
    std::vector<std::string> bodies;
    for (size_t i = 0; i < t.size(); ++i)
      if (t.pair[i] == k && std::find(bodies.begin(), bodies.end(), t.body[i]) == bodies.end())
        bodies.push_back(t.body[i]);
    auto pressure = plot_of("pressure-" + std::to_string(k), "Pair " + std::to_string(k) + ": contact pressure",
                                       "s (length)", "pressure (" + units.of("stress") + ")");
    auto shear = plot_of("shear-" + std::to_string(k), "Pair " + std::to_string(k) + ": tangential traction",
                         "s (length)", "t_T (" + units.of("stress") + ")");
    for (const auto& body : bodies) {
      const auto rows = side_rows(t, k, body);
      pressure.series.push_back(column_series(t, rows, t.pressure, "pressure, " + body, "pressure", false));
      pressure.series.push_back(column_series(t, rows, t.pressure_from_stress,
                                              "pressure from the stresses, " + body, "pressure_from_stress", true));
      shear.series.push_back(column_series(t, rows, t.tangential_traction,
                                           "tangential traction, " + body, "shear", false));
      shear.series.push_back(column_series(t, rows, t.shear_from_stress,
                                           "shear from the stresses, " + body, "shear_from_stress", true));
    }
    os << "<h3>Pair " << k << "</h3>\n<div class=\"row\">\n" << post::line_plot_svg(pressure);
    const bool friction = static_cast<size_t>(k) < r.spec.contact.size() && r.spec.contact[k].friction.law != "none";
    if (friction) os << post::line_plot_svg(shear);
    os << "</div>\n";
  }
  return os.str();
}

/// The bounding box {x_min, x_max, y_min, y_max} of the cells' corners.
std::array<double, 4> cells_box(const post::FieldCells& cells) {
  std::array<double, 4> box{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const auto& cell : cells.corners)
    for (const Vec2& p : cell) {
      box[0] = std::min(box[0], p.x());
      box[1] = std::max(box[1], p.x());
      box[2] = std::min(box[2], p.y());
      box[3] = std::max(box[3], p.y());
    }
  return box;
}

/// The window of the contact zones: a square three times their size around their centre, cut
/// to the model; none where nothing touches or that square is not smaller than the model.
std::optional<std::array<double, 4>> contact_window(const ContactTable& t, const post::FieldCells& cells) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t.state[i] == "open") continue;
    x0 = std::min(x0, t.x[i]);
    x1 = std::max(x1, t.x[i]);
    y0 = std::min(y0, t.y[i]);
    y1 = std::max(y1, t.y[i]);
  }
  const double size = std::max(x1 - x0, y1 - y0);
  const auto model = cells_box(cells);
  if (!(size > 0) || 3 * size > 0.8 * std::max(model[1] - model[0], model[3] - model[2]))
    return std::nullopt;
  const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1), half = 1.5 * size;
  const std::array<double, 4> window{std::max(cx - half, model[0]), std::min(cx + half, model[1]),
                                     std::max(cy - half, model[2]), std::min(cy + half, model[3])};
  if (!(window[1] > window[0] && window[3] > window[2])) return std::nullopt;
  return window;
}

std::string field_section(const RunReport& r, const Units& units) {
  const post::FieldCells cells = post::von_mises_cells(r.discretization, r.u, 12000);
  std::vector<double> finite;
  for (const double v : cells.values)
    if (std::isfinite(v)) finite.push_back(v);
  if (finite.empty()) return "";
  const double lo = *std::min_element(finite.begin(), finite.end());
  const double top = *std::max_element(finite.begin(), finite.end());
  const double p995 = post::percentile(finite, 0.995);
  // a few cells far above the rest (a stress singularity) would leave the others one colour
  const bool clipped = top - lo > 1.5 * (p995 - lo) && p995 > lo;
  post::FieldPlot plot;
  plot.figure = "von-mises";
  plot.title = "von Mises stress on the deformed mesh (true scale)";
  plot.value_label = "von Mises (" + units.of("stress") + ")";
  plot.cells = cells.corners;
  plot.values = cells.values;
  plot.outlines = cells.outlines;
  plot.value_min = lo;
  plot.value_max = clipped ? p995 : top;
  std::ostringstream os;
  os << "<h2>von Mises stress</h2>\n<p class=\"note\">Each element drawn as " << cells.subdivisions
     << " × " << cells.subdivisions << " cells coloured by the value at their centre; range "
     << post::short_number(lo) << " to " << post::short_number(top);
  if (clipped)
    os << "; colours clipped at " << post::short_number(p995) << " (99.5 % of the cells lie below: "
       << "the largest values are a few cells' near a singular point)";
  os << ".</p>\n<div class=\"row\">\n" << post::field_plot_svg(plot);
  if (const auto window = contact_window(r.contact, cells)) {
    plot.figure = "von-mises-contact";
    plot.title = "von Mises stress near the contact zone";
    plot.window = window;
    os << post::field_plot_svg(plot);
  }
  os << "</div>\n";
  return os.str();
}

struct HistoryColumn {
  const char* key;
  const char* label;
  double to_percent;  ///< > 0: an error measure plotted as this times the value (in %)
};

const std::vector<HistoryColumn> kHistoryColumns = {
    {"step", "step", 0},
    {"iteration", "iteration", 0},
    {"dofs", "DOF", 0},
    {"elements", "elements", 0},
    {"degree_range.0", "lowest degree", 0},
    {"degree_range.1", "highest degree", 0},
    {"strain_energy", "strain energy", 0},
    {"newton_iterations", "Newton iterations", 0},
    {"half_width", "half-width", 0},
    {"distance", "node to Γ* distance", 0},
    {"e_L2_hertz_percent", "e_L2 vs Hertz (%)", 1},
    {"e_L2_shtayerman_percent", "e_L2 vs Shtayerman (%)", 1},
    {"e_L2_reference_percent", "e_L2 vs reference (%)", 1},
    {"estimated_error.pressure_rel_L2", "estimated pressure error", 100},
    {"estimated_error.shear_rel_L2", "estimated shear error", 100},
    {"estimated_error.energy_rel", "estimated energy error", 100}};

/// A column of the loop's history against DOF (hp) or the iteration (rp), times `factor`.
post::PlotSeries history_series(const json& history, const std::string& key, const std::string& name,
                                bool hp, double factor) {
  post::PlotSeries s{name, key, {}, {}, true, false, true};
  for (const auto& entry : history) {
    const json* x = at_key(entry, hp ? "dofs" : "iteration");
    const json* y = at_key(entry, key);
    s.x.push_back(x && x->is_number() ? x->get<double>() : NAN);
    s.y.push_back(y && y->is_number() ? y->get<double>() * factor : NAN);
  }
  return s;
}

/// hp: the errors against DOF, log-log; rp: against the iteration (the DOF do not change), with
/// the nodes' distance to Γ*; without an error measure, the strain energy.
std::string history_plot(const json& history, const std::vector<const HistoryColumn*>& columns, bool hp) {
  auto plot = plot_of("history", hp ? "Errors against DOF" : "Errors and distance by iteration",
                      hp ? "DOF" : "iteration", hp ? "error (%)" : "error (%), distance (length)", hp, true);
  for (const auto* c : columns) {
    const bool distance = std::string(c->key) == "distance";
    if (c->to_percent <= 0 && !distance) continue;
    const std::string name = c->to_percent == 100 ? std::string(c->label) + " × 100 (%)" : c->label;
    plot.series.push_back(history_series(history, c->key, name, hp, distance ? 1 : c->to_percent));
  }
  if (plot.series.empty()) {
    plot.title = hp ? "Strain energy against DOF" : "Strain energy by iteration";
    plot.y_label = "strain energy";
    plot.log_y = false;
    plot.series.push_back(history_series(history, "strain_energy", "strain energy", hp, 1));
  }
  return post::line_plot_svg(plot);
}

std::string history_section(const json& summary) {
  const json* history = at_key(summary, "adapt.history");
  if (!history || !history->is_array() || history->empty()) return "";
  const std::string method = summary["adapt"].value("method", "");
  const int result_step = summary["adapt"].value("result_step", -1);
  std::vector<const HistoryColumn*> columns;
  for (const auto& c : kHistoryColumns)
    for (size_t i = 0; i < history->size(); ++i)
      if (at_key((*history)[i], c.key)) {
        columns.push_back(&c);
        break;
      }
  std::ostringstream os;
  os << "<h2>The " << escape_html(method) << " loop</h2>\n<p>Stopped: "
     << value_text(summary["adapt"].value("stopped", json("—"))) << ".</p>\n"
     << "<div class=\"wide\"><table data-table=\"history\"><tr>";
  for (const auto* c : columns) os << "<th>" << escape_html(c->label) << "</th>";
  os << "</tr>\n";
  for (size_t i = 0; i < history->size(); ++i) {
    os << (static_cast<int>(i) == result_step ? "<tr class=\"result\">" : "<tr>");
    for (const auto* c : columns) os << key_cell(summary, "adapt.history." + std::to_string(i) + "." + c->key);
    os << "</tr>\n";
  }
  os << "</table></div>\n";
  if (result_step >= 0) os << "<p class=\"note\">In bold: the step kept as the result.</p>\n";
  os << "<p class=\"note\">The lines join the " << (method == "hp" ? "steps" : "iterations")
     << " in their order (the first on the input's mesh).</p>\n"
     << history_plot(*history, columns, method == "hp");
  return os.str();
}

}  // namespace

std::string run_report_html(const RunReport& r) {
  Units units;
  units.axisymmetric = r.summary.contains("units") && r.summary["units"].contains("axisymmetric");
  const std::string name = r.summary.value("case", "");
  std::ostringstream body;
  body << "<h1>hpcontact: <span data-case>" << escape_html(name) << "</span></h1>\n"
       << status_section(r.summary) << problem_section(r, units) << numbers_section(r.summary, units)
       << errors_section(r.summary, units) << warnings_section(r.summary, units)
       << contact_section(r, units) << field_section(r, units) << history_section(r.summary);
  if (const json* note = at_key(r.summary, "units.note"))
    body << "<h2>Units</h2>\n<p class=\"note\">" << value_text(*note) << "</p>\n";
  body << "<p class=\"note\">Written by hpcontact with summary.json; every number marked there "
          "is summary.json's.</p>\n";
  return post::html_document("hpcontact report: " + name, body.str());
}

void write_run_report(const std::string& folder, const RunReport& report) {
  post::write_text_file((std::filesystem::path(folder) / "report.html").string(), run_report_html(report));
}

}  // namespace hpcontact::driver
