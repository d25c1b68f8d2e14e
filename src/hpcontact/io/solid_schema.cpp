// The 3D problem-file schema table.
#include "hpcontact/io/solid_schema.hpp"

namespace hpcontact::io {

namespace {
using T = ValueType;
}  // namespace

// Sections follow the pipeline, as in input_schema.cpp: case, the body (mesh, material,
// constraints, loads), discretization, exact solution, output.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
const Schema& solid_schema() {
  // clang-format off
  static const Schema table{
      {.path = "case", .type = T::string, .required = true,
       .doc = "Short name of the case, repeated in summary.json and in messages."},
      {.path = "description", .type = T::string, .doc = "Free text describing the case."},
      {.path = "dimension", .type = T::integer, .required = true,
       .doc = "3: a 3D problem, whose keys this table lists (without it a file is a 2D problem).",
       .lower = at_least(3), .upper = at_most(3)},
      {.path = "bodies", .type = T::section_list, .required = true,
       .doc = "The body: one, meshed with hexahedra (3D contact between bodies is not yet "
              "available).", .min_items = 1},

      {.path = "bodies[].name", .type = T::string, .required = true, .doc = "Name of the body."},
      {.path = "bodies[].material", .type = T::section, .required = true,
       .doc = "Isotropic linear elasticity."},
      {.path = "bodies[].material.E", .type = T::number, .required = true,
       .unit = "force/length²", .doc = "Young's modulus.", .lower = greater_than(0)},
      {.path = "bodies[].material.nu", .type = T::number, .required = true,
       .doc = "Poisson's ratio.", .lower = greater_than(-1), .upper = less_than(0.5)},

      {.path = "bodies[].box", .type = T::section,
       .doc = "The mesh: a box of equal hexahedra (give one of box, shell_octant, gmsh). Its face "
              "sets: "
              "x0, x1 (the faces x = from.x and x = to.x), y0, y1, z0, z1."},
      {.path = "bodies[].box.from", .type = T::point3, .required = true, .unit = "length",
       .doc = "The corner with the smallest coordinates, [x, y, z]."},
      {.path = "bodies[].box.to", .type = T::point3, .required = true, .unit = "length",
       .doc = "The opposite corner; each coordinate larger than from's."},
      {.path = "bodies[].box.elements", .type = T::count3, .default_yaml = "1",
       .doc = "Elements along x, y and z.", .lower = at_least(1), .upper = at_most(200),
       .upper_why = "more elements than a 200³ grid need more memory than a 3D p-version run "
                    "should: raise the degree instead"},
      {.path = "bodies[].shell_octant", .type = T::section,
       .doc = "The mesh: the octant x, y, z >= 0 of a thick spherical shell centred at the "
              "origin, 3 blending hexahedra per layer with exact spherical faces. Its face "
              "sets: inner, outer (the spheres), x0, y0, z0 (the coordinate planes)."},
      {.path = "bodies[].shell_octant.inner_radius", .type = T::number, .required = true,
       .unit = "length", .doc = "Inner radius.", .lower = greater_than(0)},
      {.path = "bodies[].shell_octant.outer_radius", .type = T::number, .required = true,
       .unit = "length", .doc = "Outer radius, > inner_radius.", .lower = greater_than(0)},
      {.path = "bodies[].shell_octant.layers", .type = T::integer, .default_yaml = "1",
       .doc = "Element layers through the wall.", .lower = at_least(1), .upper = at_most(50),
       .upper_why = "a p-version shell needs a few layers; more is an h-version mesh"},

      {.path = "bodies[].gmsh", .type = T::section,
       .doc = "The mesh from a Gmsh file (MSH 4.1 ASCII, gmsh -3 -format msh41): its hexahedra "
              "of 8, 20 or 27 nodes (-order 2: curved faces as quadratic surfaces; 20-node ones "
              "completed by their serendipity map), its physical surfaces on the body's boundary "
              "as face sets. Tetrahedra, prisms and pyramids are refused with their counts."},
      {.path = "bodies[].gmsh.file", .type = T::string, .required = true,
       .doc = "The .msh file, relative to the problem file's folder (the effective input gives "
              "it as an absolute path, so that input.yaml runs from anywhere)."},
      {.path = "bodies[].gmsh.volumes", .type = T::string_list,
       .doc = "Physical volumes whose hexahedra make the body; absent: every volume element.",
       .min_items = 1},

      {.path = "bodies[].surfaces", .type = T::section_list,
       .doc = "Exact geometry of curved boundary faces: every element with a face in the named "
              "sets gets the blending map that puts that face (and its edges) on the surface, "
              "instead of the mesh's straight or quadratic face. Each element's vertices must lie "
              "on the surface (to 1e-10 of its size); an element that touches a surface with an "
              "edge but no face in the sets is refused."},
      {.path = "bodies[].surfaces[].faces", .type = T::string_list, .required = true,
       .doc = "Names of face sets on the surface.", .min_items = 1},
      {.path = "bodies[].surfaces[].cylinder", .type = T::section,
       .doc = "A circular cylinder (give one of cylinder, sphere)."},
      {.path = "bodies[].surfaces[].cylinder.point", .type = T::point3, .required = true,
       .unit = "length", .doc = "A point of its axis."},
      {.path = "bodies[].surfaces[].cylinder.axis", .type = T::point3, .required = true,
       .doc = "The axis direction (any length but zero)."},
      {.path = "bodies[].surfaces[].cylinder.radius", .type = T::number, .required = true,
       .unit = "length", .doc = "Radius.", .lower = greater_than(0)},
      {.path = "bodies[].surfaces[].sphere", .type = T::section, .doc = "A sphere."},
      {.path = "bodies[].surfaces[].sphere.centre", .type = T::point3, .required = true,
       .unit = "length", .doc = "Centre."},
      {.path = "bodies[].surfaces[].sphere.radius", .type = T::number, .required = true,
       .unit = "length", .doc = "Radius.", .lower = greater_than(0)},

      {.path = "bodies[].constraints", .type = T::section_list,
       .doc = "Prescribed displacements on face sets (the component's value on every mode of "
              "the faces: constant over them)."},
      {.path = "bodies[].constraints[].faces", .type = T::string_list, .required = true,
       .doc = "Names of face sets of the body's mesh.", .min_items = 1},
      {.path = "bodies[].constraints[].ux", .type = T::number, .unit = "length",
       .doc = "Prescribed x-displacement; absent: free."},
      {.path = "bodies[].constraints[].uy", .type = T::number, .unit = "length",
       .doc = "Prescribed y-displacement; absent: free."},
      {.path = "bodies[].constraints[].uz", .type = T::number, .unit = "length",
       .doc = "Prescribed z-displacement; absent: free."},

      {.path = "bodies[].loads", .type = T::section_list,
       .doc = "Surface loads on face sets; give traction or pressure."},
      {.path = "bodies[].loads[].faces", .type = T::string_list, .required = true,
       .doc = "Names of face sets of the body's mesh.", .min_items = 1},
      {.path = "bodies[].loads[].traction", .type = T::point3, .unit = "force/length²",
       .doc = "Traction vector [tx, ty, tz], constant over the faces."},
      {.path = "bodies[].loads[].pressure", .type = T::number, .unit = "force/length²",
       .doc = "Pressure, positive pushing into the body (against the outward normal), constant."},
      {.path = "bodies[].loads[].resultant", .type = T::number, .unit = "force",
       .doc = "If given, the load is scaled so that the magnitude of its integral over the faces "
              "equals this (a force on a face set: e.g. traction [0, -1, 0], resultant 500). "
              "Refused for a load whose integral vanishes (a pressure on a closed surface).",
       .lower = greater_than(0)},
      {.path = "bodies[].body_force", .type = T::point3, .default_yaml = "[0, 0, 0]",
       .unit = "force/length³", .doc = "Force per volume, [bx, by, bz]."},

      {.path = "discretization", .type = T::section, .default_yaml = "{}",
       .doc = "How the body is discretised: hierarchic hexahedra (integrated Legendre modes)."},
      {.path = "discretization.degree", .type = T::degree3, .default_yaml = "4",
       .doc = "Polynomial degree, p or [p_xi, p_eta, p_zeta] along every element's local axes "
              "(anisotropic: e.g. a low degree through a thin wall's thickness).",
       .lower = at_least(1), .upper = at_most(kMaxHexDegree),
       .upper_why = "a tensor hexahedron of degree 12 has 6591 dofs; beyond it the condensation "
                    "of one element costs seconds"},
      {.path = "discretization.space", .type = T::choice, .default_yaml = "trunk",
       .doc = "Shape space: trunk (serendipity: fewer internal modes, the same convergence "
              "rate) or the full tensor product.", .choices = {"trunk", "tensor"}},

      {.path = "exact", .type = T::section,
       .doc = "A known answer to measure the error against; absent: none."},
      {.path = "exact.strain_energy", .type = T::number, .required = true, .unit = "force·length",
       .doc = "The exact strain energy of the model (of the meshed part): summary.json's "
              "`error` is the relative energy-norm error sqrt(|U_exact − U| / U_exact) of a "
              "problem with prescribed displacements zero.", .lower = greater_than(0)},

      {.path = "output", .type = T::section, .default_yaml = "{}",
       .doc = "What is written next to the results."},
      {.path = "output.vtu", .type = T::boolean, .default_yaml = "true",
       .doc = "Write solution.vtu for ParaView: every element subdivided into hexahedral cells; "
              "displacement, stresses, von Mises, element degree."},
      {.path = "output.vtu_subdivisions", .type = T::integer, .default_yaml = "0",
       .doc = "Sub-cells per element edge in solution.vtu; 0: the element's largest degree.",
       .lower = at_least(0), .upper = at_most(30),
       .upper_why = "the file holds (this + 1)³ points per element"},
      {.path = "output.effective_input", .type = T::boolean, .default_yaml = "true",
       .doc = "Write the effective input (defaults filled, --set applied) to reproduce the run."},
  };
  // clang-format on
  return table;
}
#pragma GCC diagnostic pop

}  // namespace hpcontact::io
