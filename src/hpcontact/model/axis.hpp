// An axisymmetric body's section against its axis x = r = 0: the nodes on it, what may be
// prescribed there, contact edges on it, a deformed section that crosses it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/geometry/vec2.hpp"
#include "hpcontact/mesh/mesh.hpp"

namespace hpcontact::model {

struct Body;

/// Nodes within this share of the section's size of x = 0 lie on the axis: what fitting a node
/// onto an arc centred on the axis leaves of an exact 0 (±4e-16 seen).
constexpr double kAxisTolerance = 1e-12;

/// Puts nodes within kAxisTolerance × (the size of `xy`) of x = 0 on it exactly: a node on the
/// axis moved to x = −4e-16 by round-off is not outside the section, and an axis node holds no
/// ring.
void snap_to_axis(std::vector<Vec2>& xy);

/// Whether mesh edge `e` lies on the axis: both its vertices at x = 0 and its middle too (a
/// curved edge between two axis nodes does not).
bool edge_on_axis(const mesh::Mesh& mesh, int e);

/// The indices of the mesh's nodes on the axis (x = 0 exactly, after snap_to_axis).
std::vector<int> axis_nodes(const mesh::Mesh& mesh);

/// A body's section crossed by its deformed shape: the node off the axis whose x + u_x is most
/// negative, if any is below −kAxisTolerance × the section's size: "node N at r = ... is
/// displaced to r + u_r = ...".
std::optional<std::string> crosses_axis(const Body& body, const Eigen::VectorXd& u);

}  // namespace hpcontact::model
