// VTU (ParaView) output of the contact interfaces: the contact Gauss points of every pair.
#pragma once

#include <string>
#include <vector>

#include "hpcontact/model/contact_solve.hpp"

namespace hpcontact::post {

/// Writes the contact points of every pair as one polyline per pair through its Gauss points,
/// at their undeformed positions (like solution.vtu, so "Warp By Vector" with `displacement`
/// puts both on the deformed configuration). Point data: displacement, traction (the contact
/// traction on the body), gap, pressure and pressure_from_stress (force per unit length along the
/// obstacle), traction_normal (multiplier or penalty), minus_sigma_nn, tangential_traction,
/// slip, state (contact::ContactState: 0 open, 1 contact without friction, 2 stick, 3 slip);
/// cell data: pair.
/// Throws IoError if the file cannot be written.
void write_contact_vtu(const std::string& path, const std::vector<model::ContactPair>& pairs,
                       const std::vector<model::ContactResult>& results);

/// A ParaView collection of the files of a load path: `files[i]` (relative to the .pvd's
/// folder) at time `times[i]`. Throws IoError if it cannot be written.
void write_pvd(const std::string& path, const std::vector<std::string>& files,
               const std::vector<double>& times);

}  // namespace hpcontact::post
