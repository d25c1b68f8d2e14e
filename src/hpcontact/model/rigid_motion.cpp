// Rigid-body motions left free by prescribed displacements: the null space of the map from the
// motion (a, b, θ) to the prescribed components, u_x = a - θ (y - c_y), u_y = b + θ (x - c_x).
#include "hpcontact/model/rigid_motion.hpp"

#include <algorithm>

#include <cmath>
#include <iomanip>
#include <sstream>

#include <Eigen/SVD>

#include "hpcontact/core/error.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

namespace {

std::string number(double v) {
  std::ostringstream os;
  os << std::setprecision(4) << (std::abs(v) < 1e-12 ? 0.0 : v);
  return os.str();
}

/// A translation direction in words: "in x", "in y" or "along (dx, dy)".
std::string translation(Vec2 t) {
  t.normalize();
  if (std::abs(t.y()) < 1e-8) return "translation in x";
  if (std::abs(t.x()) < 1e-8) return "translation in y";
  if (t.x() < 0) t = -t;
  return "translation along (" + number(t.x()) + ", " + number(t.y()) + ")";
}

/// "translation in x and rotation about (0, 0)": the free motions joined for a message.
std::string joined(const std::vector<std::string>& motions) {
  std::string out;
  for (const auto& m : motions) out += (out.empty() ? "" : " and ") + m;
  return out;
}

}  // namespace

std::vector<std::string> free_rigid_motions(const std::vector<PointConstraint>& constraints,
                                            double size) {
  if (constraints.empty()) return {"every rigid-body motion (nothing is prescribed)"};
  if (!(size > 0)) size = 1;
  Vec2 c = Vec2::Zero();
  for (const auto& pc : constraints) c += pc.at;
  c /= static_cast<double>(constraints.size());
  // Columns: a, b, θ·size; so all three are of one scale.
  Eigen::MatrixXd C(constraints.size(), 3);
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const Vec2 r = (constraints[i].at - c) / size;
    if (constraints[i].component == 0) C.row(i) << 1, 0, -r.y();
    else C.row(i) << 0, 1, r.x();
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullV);
  const auto& s = svd.singularValues();
  int rank = 0;
  for (int i = 0; i < s.size(); ++i)
    if (s(i) > 1e-8 * s(0)) ++rank;
  if (rank == 3) return {};
  const Eigen::MatrixXd N = svd.matrixV().rightCols(3 - rank);  // the free motions
  if (N.cols() == 1) {
    const Eigen::Vector3d v = N.col(0);
    if (std::abs(v(2)) < 1e-8 * v.norm()) return {translation(Vec2(v(0), v(1)))};
    const double theta = v(2) / size;  // rotation about the point where u = 0
    const Vec2 centre(c.x() - v(1) / theta, c.y() + v(0) / theta);
    return {"rotation about (" + number(centre.x()) + ", " + number(centre.y()) + ")"};
  }
  // Two free motions: the translation among them (θ = 0), and a rotation.
  const Eigen::Vector3d t = N * Eigen::Vector2d(N(2, 1), -N(2, 0));
  return {translation(Vec2(t(0), t(1))), "rotation"};
}

std::vector<PointConstraint> prescribed_vertices(const Discretization& d, int b) {
  const Body& body = d.bodies[b];
  std::vector<PointConstraint> out;
  for (int v = 0; v < body.mesh.n_nodes(); ++v) {
    const int mode = body.dofs.vertex_mode(v);
    if (mode < 0) continue;  // a node of no element
    for (int comp = 0; comp < 2; ++comp)
      if (d.free_index[body.dof_offset + 2 * mode + comp] < 0)
        out.push_back({body.mesh.node(v), comp});
  }
  return out;
}

std::string describe_dof(const Discretization& d, int dof) {
  for (const Body& body : d.bodies) {
    if (body.mixed && dof >= body.pressure_first.front() && dof < body.pressure_first.back()) {
      const int q = static_cast<int>(std::upper_bound(body.pressure_first.begin(), body.pressure_first.end(), dof) -
                                     body.pressure_first.begin()) - 1;
      std::ostringstream os;
      os << "body '" << body.name << "', element " << body.mesh.quad_id(q) << ", pressure mode "
         << dof - body.pressure_first[q]
         << (body.inverse_bulk == 0 ? " (an incompressible body needs a free or loaded boundary "
                                      "somewhere: prescribed all round, its mean pressure is not "
                                      "determined)"
                                    : "");
      return os.str();
    }
    if (dof < body.dof_offset || dof >= body.dof_offset + body.dofs.n_dofs()) continue;
    const int mode = (dof - body.dof_offset) / 2;
    const char* comp = (dof - body.dof_offset) % 2 == 0 ? "ux" : "uy";
    std::ostringstream os;
    os << "body '" << body.name << "', ";
    for (int v = 0; v < body.mesh.n_nodes(); ++v)
      if (body.dofs.vertex_mode(v) == mode) {
        os << "node " << body.mesh.node_id(v) << ", " << comp;
        return os.str();
      }
    for (int e = 0; e < body.mesh.n_edges(); ++e)
      for (int k = 2; k <= body.dofs.edge_degree(e); ++k)
        if (body.dofs.edge_mode(e, k) == mode) {
          const auto& edge = body.mesh.edge(e);
          os << "edge [" << body.mesh.node_id(edge.v0) << ", " << body.mesh.node_id(edge.v1)
             << "] mode " << k << ", " << comp;
          return os.str();
        }
    os << "an internal mode, " << comp;
    return os.str();
  }
  return "dof " + std::to_string(dof);
}

void require_held(const ProblemSpec& spec, const Discretization& d) {
  for (size_t b = 0; b < spec.bodies.size(); ++b) {
    const BodySpec& bs = spec.bodies[b];
    const auto& motions = d.bodies[b].free_rigid_motions;
    if (motions.empty()) continue;
    bool in_contact = false;
    for (const auto& c : spec.contact)
      in_contact = in_contact || c.body == bs.name || c.obstacle.body == bs.name;
    if (in_contact) continue;
    throw InputError(bs.where.str() + ": body '" + bs.name +
                     "' is not held against rigid-body motion: its constraints leave " + joined(motions) +
                     " free, and no contact pair holds it (prescribe ux or uy at more nodes or "
                     "edges)");
  }
}

std::string explain_singular(const Discretization& d, int row, const std::vector<char>& frictional) {
  std::string out;
  if (row >= 0)
    for (int dof = 0; dof < d.n_dofs; ++dof)
      if (d.free_index[dof] == row) out = "at " + describe_dof(d, dof);
  for (size_t b = 0; b < d.bodies.size(); ++b) {
    const Body& body = d.bodies[b];
    if (body.free_rigid_motions.empty()) continue;
    out += std::string(out.empty() ? "" : "; ") + "body '" + body.name +
           "' is held only by contact against " + joined(body.free_rigid_motions) +
           (b < frictional.size() && frictional[b]
                ? " (contact with friction holds it where points touch: normal to the contact "
                  "where they press, tangentially where they stick or press; a body that touches "
                  "nowhere, or only at points that slip without pressure, is free; and where every "
                  "point slips — a tangential load above the friction's capacity, mu times the "
                  "normal force — nothing holds it tangentially and there is no equilibrium)"
                : " (frictionless contact holds only where it presses, and only normal to the "
                  "contact)");
  }
  return out;
}

}  // namespace hpcontact::model
