// Contact points as VTK polylines, and .pvd collections, in ASCII (no VTK dependency).
#include "hpcontact/post/contact_vtu.hpp"

#include <iomanip>
#include <utility>

#include "hpcontact/core/error.hpp"
#include "hpcontact/post/output_file.hpp"
#include "hpcontact/post/vtk_grid.hpp"

namespace hpcontact::post {

void write_contact_vtu(const std::string& path, const std::vector<model::ContactPair>& pairs,
                       const std::vector<model::ContactResult>& results) {
  HPC_REQUIRE(pairs.size() == results.size(), IoError, path, ": ", pairs.size(), " pairs but ",
              results.size(), " results");
  // Every point as (pair, index in the pair); one polyline per pair.
  std::vector<std::pair<std::size_t, std::size_t>> at;
  std::vector<Vec2> X;
  std::vector<std::vector<int>> lines(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k)
    for (std::size_t i = 0; i < results[k].states.size(); ++i) {
      lines[k].push_back(static_cast<int>(at.size()));
      at.emplace_back(k, i);
      X.push_back(results[k].X[i]);
    }
  auto state = [&](std::size_t n) -> const contact::PointState& {
    return results[at[n].first].states[at[n].second];
  };
  VtkGrid grid(path, X, lines, 4 /* VTK_POLY_LINE */, 12);
  grid.begin_point_data("traction", "pressure");
  grid.point_vector("displacement", [&](std::size_t n) { return Vec2(state(n).x - X[n]); });
  grid.point_vector("traction", [&](std::size_t n) { return state(n).traction; });
  grid.point_scalar("gap", [&](std::size_t n) { return state(n).gap; });
  // Per point of a pair's own side: a column of its ContactResult.
  auto column = [&](const char* name, std::vector<double> model::ContactResult::*field) {
    grid.point_scalar(name, [&, field](std::size_t n) {
      const auto& v = results[at[n].first].*field;
      return at[n].second < v.size() ? v[at[n].second] : 0.0;
    });
  };
  column("pressure", &model::ContactResult::pressure);
  column("pressure_from_stress", &model::ContactResult::pressure_from_stress);
  grid.point_scalar("traction_normal", [&](std::size_t n) { return state(n).pressure; });
  column("minus_sigma_nn", &model::ContactResult::minus_sigma_nn);
  column("shear_from_stress", &model::ContactResult::shear_from_stress);
  grid.point_vector("tangent", [&](std::size_t n) { return state(n).tau; });
  grid.point_scalar("tangential_traction", [&](std::size_t n) { return state(n).t_t; });
  grid.point_scalar("slip", [&](std::size_t n) { return state(n).slip; });
  grid.point_scalar(
      "state", [&](std::size_t n) { return static_cast<int>(contact::contact_state(state(n))); },
      "Int32");
  grid.begin_cell_data("pair");
  grid.cell_scalar("pair", [](std::size_t k) { return static_cast<double>(k); });
  grid.finish();
}

void write_pvd(const std::string& path, const std::vector<std::string>& files,
               const std::vector<double>& times) {
  OutputFile file(path);
  std::ostream& out = file.stream();
  out << std::setprecision(12);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (std::size_t i = 0; i < files.size(); ++i)
    out << "<DataSet timestep=\"" << times[i] << "\" part=\"0\" file=\"" << files[i] << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  file.close();
}

}  // namespace hpcontact::post
