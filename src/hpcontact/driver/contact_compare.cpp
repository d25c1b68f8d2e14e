// Pressure comparison: sample the FE pressure along the obstacle and integrate the differences.
#include "hpcontact/driver/contact_compare.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "hpcontact/analytic/hertz.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/io/text_file.hpp"
#include "hpcontact/model/boundary_pressure.hpp"
#include "hpcontact/post/pressure_error.hpp"
#include "hpcontact/post/output_file.hpp"

namespace hpcontact::driver {

double ReferenceCurve::operator()(double s) const {
  if (x.empty() || s < x.front() || s > x.back()) return 0.0;
  const auto it = std::upper_bound(x.begin(), x.end(), s);
  const size_t i = std::min<size_t>(std::max<long>(it - x.begin(), 1), x.size() - 1);
  const double w = (s - x[i - 1]) / (x[i] - x[i - 1]);
  const double a = p[i - 1], b = p[i];
  // A contact pressure ends like the square root of the distance to the zone end, so p² is
  // the smooth one there: interpolated linearly it keeps the end's shape, where p itself would
  // be off by a quarter of the last sample (an error of the order of the spacing).
  if (a >= 0 && b >= 0 && (a > 0 || b > 0)) return std::sqrt((1 - w) * a * a + w * b * b);
  return (1 - w) * a + w * b;
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
  // The pressure of an exact-contact reference (its multiplier per unit length along the
  // obstacle: a pressure.csv with a pressure_multiplier column) is its cleanest, zero past the
  // zone end, where the stresses are only to the discretisation error; otherwise the pressure
  // from the stresses (a penalty's pressure is its penetration's).
  const int n = static_cast<int>(cols.size());
  int ip = col("pressure_multiplier") < n ? col("pressure") : col("pressure_from_stress");
  if (ip == n) ip = col("pressure");
  HPC_REQUIRE(ix < static_cast<int>(cols.size()) && ip < static_cast<int>(cols.size()), InputError,
              where, ".reference: '", path, "' needs columns x and pressure_multiplier, "
              "pressure_from_stress or pressure");
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
      HPC_REQUIRE(std::isfinite(v.back()), InputError, where, ".reference: '", path, "' line ", row,
                  ", column ", v.size(), ": '", c, "' is not a finite number (a reference curve "
                  "is a pressure at each x)");
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
                                       const model::PressureCompareSpec& cmp, HertzInputs inputs)
    : in_(std::move(inputs)), reference_name_(cmp.reference) {
  if (!cmp.reference.empty()) reference_ = read_reference(reference_path(spec, cmp), cmp.where.str());
  if (in_.force) check_reference_force(*in_.force);
}

void PressureComparison::check_reference_force(double force) const {
  if (!reference_) return;
  // ∫ p dx over x >= 0 by the trapezoidal rule: the half of F it carries.
  const auto& x = reference_->x;
  const auto& p = reference_->p;
  // The force it carries: twice ∫ p dx over x >= 0 (a cylinder), or ∫ p 2π r dr (a sphere).
  double carried = 0;
  for (size_t i = 0; i + 1 < x.size(); ++i)
    if (x[i + 1] > 0) {
      const double a = std::max(x[i], 0.0);
      const double wa = in_.axisymmetric ? std::numbers::pi * a : 1.0;
      const double wb = in_.axisymmetric ? std::numbers::pi * x[i + 1] : 1.0;
      carried += (x[i + 1] - a) * 0.5 * (wa * (*reference_)(a) + wb * p[i + 1]);
    }
  HPC_REQUIRE(std::abs(2 * carried - force) <= 1e-2 * force, InputError, in_.where, ".reference: '",
              reference_name_, "' carries F = ", 2 * carried,
              in_.axisymmetric ? " (its integral over 2 pi r dr)" : " (twice its integral over x >= 0)",
              " but the closed forms are computed for F = ", force,
              ": a reference of another load (or of the pressure on the body's own normal, "
              "pressure.csv of hpcontact before force per unit length along the obstacle)");
}

const PressureComparison::ClosedForms& PressureComparison::closed_forms(
    const model::ContactPair& pair, const model::ContactResult& result) const {
  const double F = comparison_force(in_, pair, result);
  if (closed_forms_ && closed_forms_->force == F) return *closed_forms_;
  if (!in_.force) check_reference_force(F);
  shtayerman_at_.clear();
  if (in_.axisymmetric)
    closed_forms_.emplace(ClosedForms{
        F, analytic::Hertz::spheres(in_.effective_radius, F, in_.effective_modulus), std::nullopt});
  else
    closed_forms_.emplace(ClosedForms{
        F, analytic::Hertz::pair(in_.effective_radius, F, in_.effective_modulus),
        analytic::Shtayerman::two_circles(in_.radius, in_.other_radius, F, in_.effective_modulus)});
  return *closed_forms_;
}

double PressureComparison::shtayerman_pressure(double x) const {
  if (const auto it = shtayerman_at_.find(x); it != shtayerman_at_.end()) return it->second;
  return shtayerman_at_[x] = closed_forms_->shtayerman->pressure(x);
}

nlohmann::json PressureComparison::measure(const model::Discretization& d,
                                           const model::ContactPair& pair,
                                           const model::ContactResult& result,
                                           const Eigen::VectorXd& u, const std::string& csv_path,
                                           const Eigen::VectorXd* multipliers) const {
  const ClosedForms& cf = closed_forms(pair, result);
  const auto& hertz = cf.hertz;
  const auto& shtayerman = cf.shtayerman;
  // Hertz and the reference are integrated on the same points: locate each point only once.
  const model::BoundaryPressureProbe probe(d, pair, u, multipliers);
  std::unordered_map<double, std::pair<double, double>> located;  // x -> (from stress, method)
  auto at = [&](double x) {
    if (auto it = located.find(x); it != located.end()) return it->second;
    const auto bp = probe(in_.side * x);
    return located[x] = bp ? std::pair(bp->pressure_from_stress, bp->pressure) : std::pair(0.0, 0.0);
  };
  const double b = hertz.half_width(), p0 = hertz.peak_pressure();
  const std::function<double(double)> hertz_p = [&](double x) { return hertz.pressure(x); };
  const std::function<double(double)> shtayerman_p = [&](double x) { return shtayerman_pressure(x); };
  // The errors of one FE pressure (from the stresses or the method's), keys of summary.json.
  // The integrals' pieces end where the functions are not smooth: at the contact edges' ends
  // (the FE pressure's kinks) and at the reference's samples; smooth pieces need few points.
  // Hertz's integrals take the reference's breaks too, so that both stay on the same points.
  std::vector<double> fe_breaks;
  for (const double s : probe.edge_ends()) fe_breaks.push_back(in_.side * s);
  std::vector<double> breaks = fe_breaks;
  if (reference_) breaks.insert(breaks.end(), reference_->x.begin(), reference_->x.end());
  constexpr int kPoints = 8;
  auto errors = [&](const std::function<double(double)>& fe) {
    nlohmann::json e;
    const auto eh = post::pressure_errors(fe, hertz_p, b, p0, breaks, kPoints);
    if (shtayerman) {
      const auto es = post::pressure_errors(fe, shtayerman_p, shtayerman->half_width(), p0,
                                            fe_breaks, kPoints);
      e["e_L2_shtayerman_percent"] = es.e_L2;
      e["e_seed_shtayerman_percent"] = es.e_seed;
    }
    e["e_L2_hertz_percent"] = eh.e_L2;
    e["e_seed_hertz_percent"] = eh.e_seed;
    if (reference_) {
      const auto er = post::pressure_errors(fe, *reference_, b, p0, breaks, kPoints);
      e["e_L2_reference_percent"] = er.e_L2;
      e["e_seed_reference_percent"] = er.e_seed;
    }
    return e;
  };
  nlohmann::json j = errors([&](double x) { return at(x).first; });
  j["hertz_half_width"] = b;
  j["hertz_peak_pressure"] = p0;
  if (shtayerman) j["shtayerman_half_width"] = shtayerman->half_width();
  j["closed_form"] = in_.axisymmetric ? "Hertz, spheres (3-D)" : "Hertz and Shtayerman, cylinders (plane)";
  j["pressure_measured_from"] = "stress";
  j["pressure_measured_as"] = "force per unit length along the obstacle";
  // What the closed forms are computed for (docs/input.md, contact[].compare).
  j["compared_for"] = {{"force", cf.force},
                       {"force_from", in_.force_given ? "compare.force"
                                      : in_.force     ? "solver.target_resultant"
                                                      : "resultant"},
                       {"force_carried", carried_force(in_, pair, result)},
                       {"model_fraction", 1 / in_.models_of_whole},
                       {"radius", in_.radius},
                       {"other_radius", std::isinf(in_.other_radius) ? nlohmann::json("infinite")
                                                                     : nlohmann::json(in_.other_radius)},
                       {"effective_radius", in_.effective_radius},
                       {"modulus", in_.modulus},
                       {"other_modulus", std::isinf(in_.other_modulus) ? nlohmann::json("rigid")
                                                                       : nlohmann::json(in_.other_modulus)},
                       {"effective_modulus", in_.effective_modulus}};
  // The same measures of the contact pressure the method itself carries: the penalty traction
  // eps_N <-g_N> (oscillating while Γ* lies inside an element, clean once a node sits on it), or
  // the multiplier of exact enforcement, as force per unit length along the obstacle.
  j[pair.constraints ? "multiplier" : "penalty_traction"] = errors([&](double x) { return at(x).second; });
  const double carried = carried_force(in_, pair, result);
  const double mismatch = 100 * (carried - cf.force) / cf.force;
  j["compared_for"]["force_mismatch_percent"] = mismatch;
  if (std::abs(mismatch) > 1)
    j["compared_for"]["warning"] =
        "the closed forms are computed for compare.force = " + std::to_string(cf.force) +
        " but the pair carries F = " + std::to_string(carried) +
        ": leave compare.force out to compare at the force applied";
  if (reference_) j["reference"] = reference_name_;
  if (!csv_path.empty())
    post::write_text_file(csv_path, pressure_csv(curve(d, pair, result, u, multipliers)));
  return j;
}

PressureCurve PressureComparison::curve(const model::Discretization& d,
                                        const model::ContactPair& pair,
                                        const model::ContactResult& result,
                                        const Eigen::VectorXd& u,
                                        const Eigen::VectorXd* multipliers) const {
  const ClosedForms& cf = closed_forms(pair, result);
  const model::BoundaryPressureProbe probe(d, pair, u, multipliers);
  const double b = cf.hertz.half_width();
  PressureCurve c;
  c.multiplier = pair.constraints != nullptr;
  for (int i = 0; i <= 1000; ++i) c.x.push_back(1.5 * b * i / 1000);
  for (const Vec2& g : result.gamma_star)
    if (const double z = in_.side * pair.coordinate(g); z > 0 && z < 1.5 * b) c.x.push_back(z);
  std::sort(c.x.begin(), c.x.end());
  for (const double x : c.x) {
    const auto bp = probe(in_.side * x);
    c.pressure.push_back(bp ? bp->pressure : 0.0);
    c.pressure_from_stress.push_back(bp ? bp->pressure_from_stress : 0.0);
    c.traction.push_back(bp ? bp->traction : 0.0);
    c.minus_sigma_nn.push_back(bp ? bp->minus_sigma_nn : 0.0);
    c.hertz.push_back(cf.hertz.pressure(x));
    c.shtayerman.push_back(cf.shtayerman ? shtayerman_pressure(x)
                                         : std::numeric_limits<double>::quiet_NaN());
    if (reference_) c.reference.push_back((*reference_)(x));
  }
  return c;
}

std::string pressure_csv(const PressureCurve& c) {
  std::ostringstream csv;
  csv.precision(12);
  csv << "x,pressure_from_stress," << (c.multiplier ? "pressure_multiplier" : "pressure_penalty")
      << ",hertz,shtayerman,pressure,minus_sigma_nn\n";
  for (size_t i = 0; i < c.x.size(); ++i)
    csv << c.x[i] << ',' << c.pressure_from_stress[i] << ',' << c.traction[i] << ',' << c.hertz[i]
        << ',' << c.shtayerman[i] << ',' << c.pressure[i] << ',' << c.minus_sigma_nn[i] << '\n';
  return csv.str();
}

std::vector<std::optional<PressureComparison>> make_comparisons(
    const model::ProblemSpec& spec, const model::Discretization& d,
    const std::vector<model::ContactPair>& pairs) {
  std::vector<std::optional<PressureComparison>> out(pairs.size());
  for (size_t k = 0; k < pairs.size() && k < spec.contact.size(); ++k)
    if (const auto& cmp = spec.contact[k].compare)
      out[k].emplace(spec, *cmp, hertz_inputs(spec, d, pairs, k));
  return out;
}

}  // namespace hpcontact::driver
