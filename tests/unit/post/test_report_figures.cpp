// The pieces of report.html against values known by hand: von Mises cells of a uniform strain,
// axis ticks, escaping, numbers to 10 digits, and where a line plot puts its points.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <regex>
#include <sstream>
#include <string>

#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/post/field_cells.hpp"
#include "hpcontact/post/html_text.hpp"
#include "hpcontact/post/svg_plot.hpp"

using namespace hpcontact;

namespace {

constexpr double kE = 1000, kNu = 0.3, kA = 2e-3, kB = -5e-4;

/// [0, 2] × [0, 1] in two elements with a skewed middle edge, p = 2, plane strain, its whole
/// boundary held at u = (a x, b y): the solution is that uniform strain (ε = (a, b, 0)).
model::Discretization stretched_block() {
  model::ProblemSpec spec;
  spec.file = spec.case_name = "report-figures";
  model::BodySpec b;
  b.name = "block";
  b.material.youngs_modulus = kE;
  b.material.poisson_ratio = kNu;
  b.node_ids = {1, 2, 3, 4, 5, 6};
  b.nodes = {{0, 0}, {0.8, 0}, {2, 0}, {0, 1}, {1.2, 1}, {2, 1}};
  b.element_ids = {1, 2};
  b.elements = {{1, 2, 5, 4}, {2, 3, 6, 5}};
  b.edge_sets = {{"boundary", {{1, 2}, {2, 3}, {3, 6}, {6, 5}, {5, 4}, {4, 1}}, {}}};
  model::ConstraintSpec all;
  all.edge_sets = {"boundary"};
  all.ux = std::to_string(kA) + "*x";
  all.uy = std::to_string(kB) + "*y";
  b.constraints = {all};
  spec.bodies.push_back(b);
  spec.discretization.degree = {2, 2};
  return model::discretize(spec);
}

/// von Mises of the uniform strain in plane strain, from Lamé's constants.
double uniform_von_mises() {
  const double lambda = kE * kNu / ((1 + kNu) * (1 - 2 * kNu)), mu = kE / (2 * (1 + kNu));
  const double sxx = (lambda + 2 * mu) * kA + lambda * kB, syy = lambda * kA + (lambda + 2 * mu) * kB;
  const double szz = lambda * (kA + kB);
  return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)));
}

}  // namespace

// The cells of a uniform strain shall split each element into n × n (n = 8 when the cells are
// few, fewer when max_cells asks), lie on the deformed body (every corner X + (a X, b Y) of a
// point X of the element, the cells of an element tiling its deformed area), and each carry the
// von Mises stress of that strain (to 1e-10 relative); an element's outline shall run through
// its deformed corners.
TEST(FieldCells, UniformStrainOnTheDeformedBlock) {
  const model::Discretization d = stretched_block();
  const auto sol = model::solve_linear(d, {});
  for (const int max_cells : {20000, 2 * 9, 1}) {
    const post::FieldCells cells = post::von_mises_cells(d, sol.u, max_cells);
    const int n = max_cells == 20000 ? 8 : max_cells == 18 ? 3 : 1;
    ASSERT_EQ(cells.subdivisions, n);
    ASSERT_EQ(cells.corners.size(), 2u * n * n);
    ASSERT_EQ(cells.values.size(), cells.corners.size());
    ASSERT_EQ(cells.outlines.size(), 2u);
    const double vm = uniform_von_mises();
    double area = 0;
    for (size_t c = 0; c < cells.corners.size(); ++c) {
      EXPECT_NEAR(cells.values[c], vm, 1e-10 * vm) << c;
      const auto& q = cells.corners[c];
      for (int k = 0; k < 4; ++k) {
        // undeformed position: x / (1 + a), y / (1 + b), inside the block
        const double X = q[k].x() / (1 + kA), Y = q[k].y() / (1 + kB);
        EXPECT_GE(X, -1e-12);
        EXPECT_LE(X, 2 + 1e-12);
        EXPECT_GE(Y, -1e-12);
        EXPECT_LE(Y, 1 + 1e-12);
      }
      for (int k = 0; k < 4; ++k) {
        const Vec2 &p = q[k], &r = q[(k + 1) % 4];
        area += 0.5 * (p.x() * r.y() - r.x() * p.y());  // counter-clockwise: positive
      }
    }
    EXPECT_NEAR(area, 2 * (1 + kA) * (1 + kB), 1e-12);
    EXPECT_NEAR(cells.outlines[0][0].x(), 0, 1e-14);
    EXPECT_NEAR(cells.outlines[1][0].x(), 0.8 * (1 + kA), 1e-14);
    EXPECT_NEAR(cells.outlines[1][n].x(), 2 * (1 + kA), 1e-14);  // the element's second corner
    EXPECT_EQ(cells.outlines[0].size(), 4u * n);
  }
}

// The ticks of an axis shall lie in its range, be evenly spaced by 1, 2 or 5 times a power of
// ten, and number 4 to 10 (a range of round-off: one, its middle); on a logarithmic axis they shall be the powers of ten inside it, or
// 1, 2, 5 times them when fewer than three powers are.
TEST(AxisTicks, NiceStepsInsideTheRange) {
  for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{
           {0, 1}, {-3.7, 12.2}, {1e-7, 3.3e-7}, {22675, 22838}, {-1e5, -2e4}, {1e20, 1e20 + 1e9}}) {
    const auto t = post::axis_ticks(lo, hi, false);
    ASSERT_GE(t.size(), 4u) << lo;
    ASSERT_LE(t.size(), 10u) << lo;
    const double step = t[1] - t[0];
    // the spacing of ticks far from zero is a difference of rounded values
    const double slack = 1e-9 + 4 * std::numeric_limits<double>::epsilon() * std::abs(hi) / step;
    const double mantissa = step / std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    EXPECT_TRUE(std::abs(mantissa - 1) < 5 * slack || std::abs(mantissa - 2) < 5 * slack ||
                std::abs(mantissa - 5) < 5 * slack) << mantissa;
    for (size_t i = 0; i < t.size(); ++i) {
      EXPECT_GE(t[i], lo - slack * step);
      EXPECT_LE(t[i], hi + slack * step);
      if (i) EXPECT_NEAR(t[i] - t[i - 1], step, 2 * slack * step);
    }
  }
  // a uniform field's colour bar: a range of a few ulps has one tick, its middle
  const double one = 1.0, ulps = std::nextafter(std::nextafter(one, 2.0), 2.0);
  EXPECT_EQ(post::axis_ticks(one, ulps, false).size(), 1u);
  EXPECT_EQ(post::axis_ticks(0.02, 3000, true), (std::vector<double>{0.1, 1, 10, 100, 1000}));
  EXPECT_LE(post::axis_ticks(1e-12, 50, true).size(), 10u);  // 14 decades: every second
  const auto few = post::axis_ticks(0.3, 40, true);
  EXPECT_EQ(few, (std::vector<double>{0.5, 1, 2, 5, 10, 20}));
}

// A user's string shall come out of escape_html with no character that starts markup, and a
// number printed for the page shall read back to 5e-10 relative (the test's 1e-9 of the page
// against summary.json).
TEST(HtmlText, EscapedAndTenDigits) {
  EXPECT_EQ(post::escape_html("<b>&\"x's"), "&lt;b&gt;&amp;&quot;x&#39;s");
  EXPECT_EQ(post::escape_html("plain name"), "plain name");
  for (const double v : {22838.467730381315, 6.123233995736766e-16, -1.0 / 3, 1e300, 7696.564829108864}) {
    const double back = std::stod(post::number_text(v));
    EXPECT_LE(std::abs(back - v), 5e-10 * std::abs(v)) << v;
  }
  EXPECT_EQ(post::number_text(-0.0), "0");
  EXPECT_EQ(post::number_text(NAN), "nan");
}

// A line plot shall draw a point per finite value, its pixel coordinates affine in the data
// (log10 of it on a logarithmic axis), larger values higher up; a value that is not finite
// breaks the line in two; a series that does not set the range leaves the axes to the others.
TEST(LinePlot, PointsWhereTheDataSay) {
  post::LinePlot plot;
  plot.figure = "test";
  plot.series.push_back({"a", "a", {1, 2, 3, 4, 5}, {10, 20, NAN, 40, 30}});
  plot.series.push_back({"spike", "spike", {1, 5}, {0, 1e9}, false, true, false});
  const std::string svg = post::line_plot_svg(plot);
  const std::regex polyline("data-series=\"a\"[^>]* points=\"([^\"]*)\"");
  std::vector<std::vector<std::pair<double, double>>> lines;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), polyline); it != std::sregex_iterator(); ++it) {
    lines.emplace_back();
    std::istringstream points((*it)[1].str());
    double x, y;
    char comma;
    while (points >> x >> comma >> y) lines.back().push_back({x, y});
  }
  ASSERT_EQ(lines.size(), 2u);
  ASSERT_EQ(lines[0].size(), 2u);
  ASSERT_EQ(lines[1].size(), 2u);
  const double dx = lines[0][1].first - lines[0][0].first, dy = lines[0][1].second - lines[0][0].second;
  EXPECT_GT(dx, 0);
  EXPECT_LT(dy, 0);
  // x = 4 and 5, y = 40 and 30 on the same affine maps
  EXPECT_NEAR(lines[1][0].first, lines[0][0].first + 3 * dx, 0.05);
  EXPECT_NEAR(lines[1][1].first, lines[0][0].first + 4 * dx, 0.05);
  EXPECT_NEAR(lines[1][0].second, lines[0][0].second + 3 * dy, 0.05);
  EXPECT_NEAR(lines[1][1].second, lines[0][0].second + 2 * dy, 0.05);
  // the axes span 10..40 padded by 4 %: 30 of data over the frame's height less 8 %
  EXPECT_NEAR(-dy * 30 / 10, (plot.height - 30 - 52) / 1.08, 0.05);
}
