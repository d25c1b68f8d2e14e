// Pressure comparison: sample the FE pressure along the obstacle and integrate the differences.
#include "hpcontact/driver/contact_compare.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "hpcontact/analytic/hertz.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/io/text_file.hpp"
#include "hpcontact/post/pressure_error.hpp"
#include "hpcontact/post/output_file.hpp"

namespace hpcontact::driver {

double ReferenceCurve::operator()(double s) const {
  if (x.empty() || s < x.front() || s > x.back()) return 0.0;
  const auto it = std::upper_bound(x.begin(), x.end(), s);
  const size_t i = std::min<size_t>(std::max<long>(it - x.begin(), 1), x.size() - 1);
  const double w = (s - x[i - 1]) / (x[i] - x[i - 1]);
  return (1 - w) * p[i - 1] + w * p[i];
}

namespace {

ReferenceCurve read_reference(const std::string& path, const std::string& where) {
  std::string text;
  try {
    text = io::read_bounded_file(path, "reference file", io::kMaxReferenceBytes);
  } catch (const IoError& e) {
    throw InputError(where + ".reference: " + e.what());
  }
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> cols;
  {
    std::stringstream ss(line);
    std::string c;
    while (std::getline(ss, c, ',')) cols.push_back(c);
  }
  auto col = [&](const std::string& name) {
    return static_cast<int>(std::find(cols.begin(), cols.end(), name) - cols.begin());
  };
  const int ix = col("x");
  int ip = col("pressure_from_stress");
  if (ip == static_cast<int>(cols.size())) ip = col("pressure");
  HPC_REQUIRE(ix < static_cast<int>(cols.size()) && ip < static_cast<int>(cols.size()), InputError,
              where, ".reference: '", path, "' needs columns x and pressure_from_stress");
  ReferenceCurve r;
  int row = 1;
  while (std::getline(in, line)) {
    ++row;
    std::vector<double> v;
    std::stringstream ss(line);
    std::string c;
    while (std::getline(ss, c, ',')) {
      char* end = nullptr;
      v.push_back(std::strtod(c.c_str(), &end));
      HPC_REQUIRE(end != c.c_str(), InputError, where, ".reference: '", path, "' line ", row,
                  ": not a number: '", c, "'");
    }
    HPC_REQUIRE(static_cast<int>(v.size()) > std::max(ix, ip), InputError, where, ".reference: '",
                path, "' line ", row, ": too few columns");
    r.x.push_back(v[ix]);
    r.p.push_back(v[ip]);
  }
  HPC_REQUIRE(r.x.size() >= 2 && std::is_sorted(r.x.begin(), r.x.end()), InputError, where,
              ".reference: '", path, "' needs at least two rows sorted by x");
  return r;
}

}  // namespace

std::string reference_path(const model::ProblemSpec& spec, const model::PressureCompareSpec& cmp) {
  namespace fs = std::filesystem;
  fs::path path(cmp.reference);
  if (path.is_relative()) path = fs::path(spec.file).parent_path() / path;
  return path.string();
}

void require_references(const model::ProblemSpec& spec) {
  for (const auto& pair : spec.contact)
    if (pair.compare && !pair.compare->reference.empty())
      (void)read_reference(reference_path(spec, *pair.compare), pair.compare->where.str());
}

PressureComparison::PressureComparison(const model::ProblemSpec& spec,
                                       const model::PressureCompareSpec& cmp,
                                       const material::LinearElastic& mat)
    : hertz_{cmp.radius, cmp.force, mat.youngs_modulus, mat.poisson_ratio},
      shtayerman_(analytic::Shtayerman::circle(cmp.radius, cmp.force, mat.youngs_modulus,
                                               mat.poisson_ratio)),
      reference_name_(cmp.reference) {
  HPC_REQUIRE(mat.plane == material::Plane::strain, InputError, cmp.where.str(),
              ": Hertz and Shtayerman are implemented for plane strain");
  if (!cmp.reference.empty()) reference_ = read_reference(reference_path(spec, cmp), cmp.where.str());
}

nlohmann::json PressureComparison::measure(const model::Discretization& d,
                                           const model::ContactPair& pair,
                                           const Eigen::VectorXd& u,
                                           const std::vector<double>& zone_ends,
                                           const std::string& csv_path,
                                           const Eigen::VectorXd* multipliers) const {
  // Hertz and the reference are integrated on the same points: locate each point only once.
  const model::BoundaryPressureProbe probe(d, pair, u, multipliers);
  std::unordered_map<double, std::pair<double, double>> located;  // x -> (from stress, penalty)
  auto at = [&](double x) {
    if (auto it = located.find(x); it != located.end()) return it->second;
    const auto bp = probe(x);
    return located[x] = bp ? std::pair(bp->from_stress, bp->penalty) : std::pair(0.0, 0.0);
  };
  const double b = hertz_.half_width(), p0 = hertz_.peak_pressure();
  const std::function<double(double)> hertz_p = [&](double x) { return hertz_.pressure(x); };
  const std::function<double(double)> shtayerman_p = [&](double x) { return shtayerman_.pressure(x); };
  // The errors of one FE pressure (from the stresses or the penalty traction), keys of summary.json (docs/tutorial.md §8).
  auto errors = [&](const std::function<double(double)>& fe) {
    nlohmann::json e;
    const auto eh = post::pressure_errors(fe, hertz_p, b, p0);
    const auto es = post::pressure_errors(fe, shtayerman_p, shtayerman_.half_width(), p0);
    e["e_L2_hertz_percent"] = eh.e_L2;
    e["e_seed_hertz_percent"] = eh.e_seed;
    e["e_L2_shtayerman_percent"] = es.e_L2;
    e["e_seed_shtayerman_percent"] = es.e_seed;
    if (reference_) {
      const auto er = post::pressure_errors(fe, *reference_, b, p0);
      e["e_L2_reference_percent"] = er.e_L2;
      e["e_seed_reference_percent"] = er.e_seed;
    }
    return e;
  };
  nlohmann::json j = errors([&](double x) { return at(x).first; });
  j["hertz_half_width"] = b;
  j["hertz_peak_pressure"] = p0;
  j["shtayerman_half_width"] = shtayerman_.half_width();
  j["pressure_measured_from"] = "stress";
  // The same measures of the contact pressure the method itself carries: the penalty traction
  // eps_N <-g_N> (oscillating while Γ* lies inside an element, clean once a node sits on it), or
  // the multiplier of exact enforcement.
  j[pair.constraints ? "multiplier" : "penalty_traction"] = errors([&](double x) { return at(x).second; });
  if (reference_) j["reference"] = reference_name_;
  if (!csv_path.empty())
    post::write_text_file(csv_path, pressure_csv(curve(d, pair, u, zone_ends, multipliers)));
  return j;
}

PressureCurve PressureComparison::curve(const model::Discretization& d,
                                        const model::ContactPair& pair, const Eigen::VectorXd& u,
                                        const std::vector<double>& zone_ends,
                                        const Eigen::VectorXd* multipliers) const {
  const model::BoundaryPressureProbe probe(d, pair, u, multipliers);
  const double b = hertz_.half_width();
  PressureCurve c;
  c.multiplier = pair.constraints != nullptr;
  for (int i = 0; i <= 1000; ++i) c.x.push_back(1.5 * b * i / 1000);
  for (double z : zone_ends)
    if (z > 0 && z < 1.5 * b) c.x.push_back(z);
  std::sort(c.x.begin(), c.x.end());
  for (const double x : c.x) {
    const auto bp = probe(x);
    c.from_stress.push_back(bp ? bp->from_stress : 0.0);
    c.penalty.push_back(bp ? bp->penalty : 0.0);
    c.hertz.push_back(hertz_.pressure(x));
    c.shtayerman.push_back(shtayerman_.pressure(x));
    if (reference_) c.reference.push_back((*reference_)(x));
  }
  return c;
}

std::string pressure_csv(const PressureCurve& c) {
  std::ostringstream csv;
  csv.precision(12);
  csv << "x,pressure_from_stress," << (c.multiplier ? "pressure_multiplier" : "pressure_penalty")
      << ",hertz,shtayerman\n";
  for (size_t i = 0; i < c.x.size(); ++i)
    csv << c.x[i] << ',' << c.from_stress[i] << ',' << c.penalty[i] << ',' << c.hertz[i] << ','
        << c.shtayerman[i] << '\n';
  return csv.str();
}

}  // namespace hpcontact::driver
