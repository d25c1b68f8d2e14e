// Sampling von Mises on a grid of cells per element, on the deformed mesh.
#include "hpcontact/post/field_cells.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/post/fields.hpp"

namespace hpcontact::post {

namespace {

/// Element q's n × n cells and its outline into `cells`.
void add_element(const model::Body& body, int q, int n, const Eigen::VectorXd& u, FieldCells& cells) {
  // the deformed grid points, (n + 1)² of them, row by row in eta
  std::vector<Vec2> grid((n + 1) * (n + 1));
  auto at = [n](int i, int j) { return j * (n + 1) + i; };
  auto reference = [n](int i) { return -1.0 + 2.0 * i / n; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const PointResult r = evaluate(body, q, reference(i), reference(j), u);
      grid[at(i, j)] = r.x + r.u;
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      cells.corners.push_back({grid[at(i, j)], grid[at(i + 1, j)], grid[at(i + 1, j + 1)], grid[at(i, j + 1)]});
      const double h = 1.0 / n;
      cells.values.push_back(evaluate(body, q, reference(i) + h, reference(j) + h, u).von_mises);
    }
  std::vector<Vec2> outline;
  for (int i = 0; i < n; ++i) outline.push_back(grid[at(i, 0)]);
  for (int j = 0; j < n; ++j) outline.push_back(grid[at(n, j)]);
  for (int i = n; i > 0; --i) outline.push_back(grid[at(i, n)]);
  for (int j = n; j > 0; --j) outline.push_back(grid[at(0, j)]);
  cells.outlines.push_back(std::move(outline));
}

}  // namespace

FieldCells von_mises_cells(const model::Discretization& d, const Eigen::VectorXd& u, int max_cells) {
  int n_elements = 0;
  for (const auto& body : d.bodies) n_elements += body.mesh.n_quads();
  FieldCells cells;
  int n = 8;
  while (n > 1 && n * n * n_elements > max_cells) --n;
  cells.subdivisions = n;
  for (const auto& body : d.bodies)
    for (int q = 0; q < body.mesh.n_quads(); ++q) add_element(body, q, n, u, cells);
  return cells;
}

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 0;
  const size_t k = std::min(values.size() - 1,
                            static_cast<size_t>(std::ceil(fraction * values.size())) - (fraction > 0 ? 1 : 0));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

}  // namespace hpcontact::post
