// Contact points as VTK polylines, and .pvd collections, in ASCII (no VTK dependency).
#include "hpcontact/post/contact_vtu.hpp"

#include <fstream>
#include <functional>
#include <iomanip>

#include "hpcontact/core/error.hpp"

namespace hpcontact::post {

namespace {

int state_code(const contact::PointState& s) {
  switch (s.stick_slip) {
    case contact::StickSlip::stick: return 2;
    case contact::StickSlip::slip: return 3;
    case contact::StickSlip::open: break;
  }
  return s.pressure > 0 ? 1 : 0;
}

}  // namespace

void write_contact_vtu(const std::string& path, const std::vector<model::ContactPair>& pairs,
                       const std::vector<model::ContactResult>& results) {
  HPC_REQUIRE(pairs.size() == results.size(), IoError, path, ": ", pairs.size(), " pairs but ",
              results.size(), " results");
  std::size_t n_points = 0;
  for (const auto& r : results) n_points += r.states.size();
  std::ofstream out(path);
  HPC_REQUIRE(out, IoError, path, ": cannot open for writing");
  out << std::setprecision(12);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\"" << pairs.size() << "\">\n";
  // Visits every point: f(pair, index in the pair).
  auto each = [&](const std::function<void(std::size_t, std::size_t)>& f) {
    for (std::size_t k = 0; k < pairs.size(); ++k)
      for (std::size_t i = 0; i < results[k].states.size(); ++i) f(k, i);
  };
  out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  each([&](std::size_t k, std::size_t i) {
    const Vec2& X = pairs[k].points[i].X;
    out << X.x() << ' ' << X.y() << " 0\n";
  });
  out << "</DataArray>\n</Points>\n<Cells>\n"
      << "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  std::size_t next = 0;
  for (const auto& r : results)
    for (std::size_t i = 0; i < r.states.size(); ++i) out << next++ << (i + 1 < r.states.size() ? ' ' : '\n');
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  next = 0;
  for (const auto& r : results) out << (next += r.states.size()) << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < pairs.size(); ++k) out << "4\n";  // VTK_POLY_LINE
  out << "</DataArray>\n</Cells>\n";

  out << "<PointData Vectors=\"traction\" Scalars=\"pressure\">\n";
  auto vector = [&](const char* name, const std::function<Vec2(std::size_t, std::size_t)>& v) {
    out << "<DataArray type=\"Float64\" Name=\"" << name
        << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    each([&](std::size_t k, std::size_t i) {
      const Vec2 a = v(k, i);
      out << a.x() << ' ' << a.y() << " 0\n";
    });
    out << "</DataArray>\n";
  };
  auto scalar = [&](const char* name, const char* type,
                    const std::function<double(std::size_t, std::size_t)>& v) {
    out << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
    each([&](std::size_t k, std::size_t i) { out << v(k, i) << '\n'; });
    out << "</DataArray>\n";
  };
  const auto& R = results;
  vector("displacement", [&](auto k, auto i) { return Vec2(R[k].states[i].x - pairs[k].points[i].X); });
  vector("traction", [&](auto k, auto i) { return R[k].states[i].traction; });
  scalar("gap", "Float64", [&](auto k, auto i) { return R[k].states[i].gap; });
  scalar("pressure", "Float64", [&](auto k, auto i) { return R[k].states[i].pressure; });
  scalar("pressure_from_stress", "Float64", [&](auto k, auto i) {
    return i < R[k].stress_pressure.size() ? R[k].stress_pressure[i] : 0.0;
  });
  scalar("tangential_traction", "Float64", [&](auto k, auto i) { return R[k].states[i].t_t; });
  scalar("slip", "Float64", [&](auto k, auto i) { return R[k].states[i].slip; });
  scalar("state", "Int32", [&](auto k, auto i) { return double(state_code(R[k].states[i])); });
  out << "</PointData>\n<CellData Scalars=\"pair\">\n"
      << "<DataArray type=\"Int32\" Name=\"pair\" format=\"ascii\">\n";
  for (std::size_t k = 0; k < pairs.size(); ++k) out << k << '\n';
  out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  HPC_REQUIRE(out.good(), IoError, path, ": write failed");
}

void write_pvd(const std::string& path, const std::vector<std::string>& files,
               const std::vector<double>& times) {
  std::ofstream out(path);
  HPC_REQUIRE(out, IoError, path, ": cannot open for writing");
  out << std::setprecision(12);
  out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (std::size_t i = 0; i < files.size(); ++i)
    out << "<DataSet timestep=\"" << times[i] << "\" part=\"0\" file=\"" << files[i] << "\"/>\n";
  out << "</Collection>\n</VTKFile>\n";
  HPC_REQUIRE(out.good(), IoError, path, ": write failed");
}

}  // namespace hpcontact::post
