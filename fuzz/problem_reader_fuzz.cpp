// libFuzzer target: the YAML problem reader, and the discretisation of what it accepts.
// Any input may be refused with an hpcontact::Error (that is the reader doing its job); a crash,
// a sanitizer report, an uncaught exception of another type or a hang is a finding.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hpcontact/core/error.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/rigid_motion.hpp"

using namespace hpcontact;

namespace {

/// Discretising is bounded by the size of the problem, not of the input: a few lines can ask
/// for 10⁶ elements of degree 30. Only small problems are discretised.
bool small(const model::ProblemSpec& spec) {
  std::size_t elements = 0;
  for (const auto& b : spec.bodies) {
    elements += b.elements.size();
    if (b.degree && ((*b.degree)[0] > 10 || (*b.degree)[1] > 10)) return false;
    for (const auto& [id, p] : b.element_degrees)
      if (p[0] > 10 || p[1] > 10) return false;
  }
  const auto& p = spec.discretization.degree;
  return elements <= 64 && p[0] <= 10 && p[1] <= 10;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // A `gmsh` key would read files named by the input (the Gmsh reader has its own target).
  if (text.find("gmsh") != std::string::npos) return 0;
  try {
    const auto spec = io::parse_problem(text, "fuzz.yaml");
    if (small(spec)) {
      const auto d = model::discretize(spec);
      model::require_held(spec, d);
    }
  } catch (const Error&) {
    // refused with a message: fine
  }
  return 0;
}
