// report.html: a run's results as one self-contained page (tables and inline SVG figures), read
// in a browser without network or a plotting program.
#pragma once

#include <string>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "hpcontact/driver/contact_table.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::driver {

/// What the page is made of: the same data summary.json and contact.csv are written from.
struct RunReport {
  const model::ProblemSpec& spec;
  const nlohmann::json& summary;  ///< summary.json's content (post::to_json)
  const ContactTable& contact;    ///< contact.csv's rows
  const model::Discretization& discretization;
  const Eigen::VectorXd& u;  ///< all dofs
};

/// The page: the status (a failed run's last converged state under a banner that says so and
/// why), the problem (bodies, materials, loads, supports, contact pairs), the key numbers and
/// the error measures, the warnings and singular points, the pressure (and with friction the
/// shear) along each pair, von Mises on the deformed mesh, and an hp or rp loop's history.
/// Every number that summary.json holds is printed to 10 digits in an element whose data-key
/// attribute is its path there ("contact_pairs.0.pressure_max"; array items by index). Every
/// string of the input or the run is escaped.
std::string run_report_html(const RunReport& report);

/// Writes folder/report.html (IoError on failure).
void write_run_report(const std::string& folder, const RunReport& report);

}  // namespace hpcontact::driver
