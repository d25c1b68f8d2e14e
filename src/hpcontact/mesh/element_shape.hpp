// How far an element is from a square: its stretch (aspect ratio) and its distortion (Jacobian
// ratio), and the warnings a mesh's worst elements give.
#pragma once

#include <string>
#include <vector>

#include "hpcontact/mesh/element_map.hpp"
#include "hpcontact/mesh/mesh.hpp"

namespace hpcontact::mesh {

/// Shape measures of one element over an n×n Gauss grid of the reference square:
/// - aspect_ratio: the largest σ_max / σ_min of the map's Jacobian J = [dx/dξ, dx/dη] (1 for a
///   square, a / b for an a × b rectangle, larger for a skewed one): a needle;
/// - jacobian_ratio: max det J / min det J (1 for a parallelogram): a distorted element, whose
///   polynomials map to functions of lower order in x, y.
/// - area: ∫ det J over the element.
struct ElementShape {
  double aspect_ratio = 1;
  double jacobian_ratio = 1;
  double area = 0;
};
ElementShape element_shape(const ElementMap& map, int n_points);

/// The length of local edge `le` of the element (n_points Gauss points along it).
double edge_length(const ElementMap& map, int le, int n_points);

/// Beyond these `check` and `run` warn (docs/input.md, "Mesh quality"). A p-element resolves a
/// field along its long side and across its short one with the same degree: stretched elements
/// are right where the field is smooth along them (boundary layers, a graded mesh's far field:
/// the seed's h-meshes reach 190), so the aspect and Jacobian ratios warn only at values no
/// designed mesh has. On a contact edge the pressure changes fastest along the edge: an
/// element whose contact edge is more than 10 times its depth (L² / area) resolves the
/// pressure as a mesh 10 times coarser would (elements graded towards a point along the edge,
/// short along it, are not counted).
constexpr double kAspectRatioLimit = 300;
constexpr double kJacobianRatioLimit = 20;
constexpr double kContactStretchLimit = 10;

/// Warnings about the elements of `mesh` (maps: per element) beyond the limits, one per measure:
/// the worst element, its value, how many exceed the limit, and whether any of them touches
/// one of `contact_edges` (mesh edges), where the contact pressure is resolved. Each begins with
/// `context` (the file and the body).
std::vector<std::string> shape_warnings(const Mesh& mesh, const std::vector<ElementMap>& maps,
                                        const std::vector<int>& contact_edges,
                                        const std::string& context);

}  // namespace hpcontact::mesh
