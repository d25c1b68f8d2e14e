// The problem-file schema table and its Markdown rendering.
#include "hpcontact/io/input_schema.hpp"

#include <sstream>

#include "hpcontact/io/gmsh_reader.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/io/solid_schema.hpp"
#include "hpcontact/io/text_file.hpp"
#include "hpcontact/io/yaml_limits.hpp"

namespace hpcontact::io {

namespace {

using T = ValueType;

constexpr double max_degree = model::kMaxDegree;

}  // namespace

// Sections follow the pipeline: case, bodies (mesh, material, constraints and loads),
// discretization, solver, contact, exact solution, output. A key with a default is filled in when
// absent, so the effective input lists it; an optional key without a default stays absent.
// GCC's -Wextra warns about members left out of a designated initializer even when they have
// default initializers; leaving them out is the point of the table's layout.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
const std::vector<KeySpec>& input_schema() {
  // One entry per key, laid out by hand to read as a table.
  // clang-format off
  static const std::vector<KeySpec> table{
      {.path = "case", .type = T::string, .required = true,
       .doc = "Short name of the case, repeated in summary.json and in messages (the output "
              "folder is named after the problem file, unless --out says otherwise)."},
      {.path = "description", .type = T::string, .doc = "Free text describing the case."},
      {.path = "bodies", .type = T::section_list, .required = true,
       .doc = "The elastic bodies, each with its own mesh, material, constraints and loads.",
       .min_items = 1},

      {.path = "bodies[].name", .type = T::string, .required = true,
       .doc = "Name of the body, unique in the file."},
      {.path = "bodies[].material", .type = T::section, .required = true,
       .doc = "Material law of the body."},
      {.path = "bodies[].nodes", .type = T::node_table, .unit = "length",
       .doc = "Mesh nodes by user id; the ids need not be contiguous. Give nodes and elements, or "
              "gmsh.", .min_items = 1},
      {.path = "bodies[].elements", .type = T::element_table,
       .doc = "Quadrilaterals by user id: four distinct existing node ids, counter-clockwise. Give "
              "nodes and elements, or gmsh.",
       .min_items = 1},
      {.path = "bodies[].gmsh", .type = T::section,
       .doc = "The mesh from a Gmsh file instead of nodes and elements (MSH 4.1 ASCII: gmsh "
              "-format msh41; quadrilaterals of order 1 or 2: Mesh.RecombineAll = 1, -order 2). "
              "Expanded when read into nodes (the corner nodes, ids = gmsh node tags), elements "
              "(ids = gmsh element tags, turned counter-clockwise where needed), curves (the arcs "
              "below) and edge_sets (one per 1D physical group, named as the group, holding its "
              "lines that are edges of the body); the effective input lists these instead of this "
              "key. curves and edge_sets may be given as well; a hand-given curve replaces a "
              "recovered arc, an edge set may not share a group's name. The mesh counts towards "
              "the problem's YAML values (see Limits)."},
      {.path = "bodies[].gmsh.file", .type = T::string, .required = true,
       .doc = "Path of the .msh file, relative to the problem file's folder."},
      {.path = "bodies[].gmsh.surface", .type = T::string,
       .doc = "Name of a 2D physical group: only its quadrilaterals form the body (one file can "
              "hold several bodies); absent: every quadrilateral of the file."},
      {.path = "bodies[].gmsh.arcs", .type = T::section_list,
       .doc = "Circular arcs named by 1D physical groups: every edge of the group becomes an exact "
              "arc (for first-order meshes, whose edges carry no midside node)."},
      {.path = "bodies[].gmsh.arc_tolerance", .type = T::number, .default_yaml = "1e-8",
       .doc = "Second-order meshes: an edge whose midside node lies off the straight line between "
              "its ends by more than this fraction of the body size (bounding-box diagonal) "
              "becomes the circular arc through its three nodes; arcs of neighbouring edges on one "
              "circle are fitted to one circle through all their nodes.",
       .lower = greater_than(0)},
      {.path = "bodies[].gmsh.arcs[].edges", .type = T::string, .required = true,
       .doc = "Name of a 1D physical group of the file."},
      {.path = "bodies[].gmsh.arcs[].center", .type = T::point, .required = true,
       .unit = "length", .doc = "Centre of the circle, [x, y]."},
      {.path = "bodies[].gmsh.arcs[].radius", .type = T::number, .required = true,
       .unit = "length",
       .doc = "Radius of the circle; the group's nodes must lie on it (to 1e-6 of it).",
       .lower = greater_than(0)},
      {.path = "bodies[].curves", .type = T::section_list,
       .doc = "Exact geometry of mesh edges; edges not listed are straight."},
      {.path = "bodies[].degree", .type = T::degree,
       .doc = "Polynomial degree of every element of this body; default: discretization.degree.",
       .lower = at_least(1), .upper = at_most(max_degree)},
      {.path = "bodies[].degrees", .type = T::degree_table,
       .doc = "Polynomial degree of single elements, by element id; overrides degree.",
       .lower = at_least(1), .upper = at_most(max_degree)},
      {.path = "bodies[].edge_sets", .type = T::edge_set_table,
       .doc = "Named sets of element edges, each edge given by its two end nodes, for constraints "
              "and loads."},
      {.path = "bodies[].constraints", .type = T::section_list,
       .doc = "Prescribed displacements on edge sets and nodes."},
      {.path = "bodies[].loads", .type = T::section_list,
       .doc = "Distributed loads on edge sets."},
      {.path = "bodies[].nodal_forces", .type = T::section_list,
       .doc = "Concentrated forces at nodes."},
      {.path = "bodies[].body_force", .type = T::point, .default_yaml = "[0, 0]",
       .unit = "force/length³", .doc = "Force per unit volume, [bx, by]."},

      {.path = "bodies[].regions", .type = T::section_list,
       .doc = "Elements with their own elastic constants (a body of several materials, e.g. a "
              "monolithic reference of two bodies in contact); the other elements take "
              "bodies[].material."},
      {.path = "bodies[].regions[].elements", .type = T::integer_list, .required = true,
       .doc = "Element ids of the region (each in one region at most).", .min_items = 1},
      {.path = "bodies[].regions[].material", .type = T::section, .required = true,
       .doc = "The region's material: the keys of bodies[].material; model and plane must be "
              "the body's."},
      {.path = "bodies[].regions[].material.model", .type = T::choice, .default_yaml = "linear-elastic",
       .doc = "As bodies[].material.model.",
       .choices = {"linear-elastic", "saint-venant-kirchhoff", "neo-hooke"}},
      {.path = "bodies[].regions[].material.E", .type = T::number, .required = true,
       .unit = "force/length²", .doc = "Young's modulus.", .lower = greater_than(0)},
      {.path = "bodies[].regions[].material.nu", .type = T::number, .required = true,
       .doc = "Poisson's ratio.", .lower = greater_than(-1), .upper = less_than(0.5)},
      {.path = "bodies[].regions[].material.plane", .type = T::choice, .default_yaml = "strain",
       .doc = "As bodies[].material.plane.", .choices = {"strain", "stress", "axisymmetric"}},
      {.path = "bodies[].regions[].material.thickness", .type = T::number,
       .unit = "length", .doc = "Ignored: the thickness is the body's.", .lower = greater_than(0)},
      {.path = "bodies[].material.model", .type = T::choice, .default_yaml = "linear-elastic",
       .doc = "Material law. `linear-elastic`: small strain. `saint-venant-kirchhoff` and "
              "`neo-hooke` (compressible, W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2, plane "
              "strain or axisymmetric, not plane stress): finite strain, total Lagrangian, solved by Newton in load steps; "
              "stresses reported are Cauchy stresses on the deformed body, strains Green-Lagrange. "
              "These three take E and nu. The rubber laws, finite strain in plane strain or "
              "axisymmetric, W = W_iso(I1bar, I2bar) + K/2 (J - 1)^2 on the invariants of "
              "J^(-2/3) C, take C10.. and K instead: `neo-hooke-split` (C10, K: "
              "W_iso = C10 (I1bar - 3)), `mooney-rivlin` (C10, C01, K: + C01 (I2bar - 3)), "
              "`yeoh` (C10, C20, C30, K: C10 (I1bar - 3) + C20 (I1bar - 3)^2 + C30 (I1bar - 3)^3); "
              "their small-strain shear modulus is 2 (C10 + C01), bulk modulus K.",
       .choices = {"linear-elastic", "saint-venant-kirchhoff", "neo-hooke", "neo-hooke-split",
                   "mooney-rivlin", "yeoh"}},
      {.path = "bodies[].material.E", .type = T::number,
       .unit = "force/length²",
       .doc = "Young's modulus; required by linear-elastic, saint-venant-kirchhoff and "
              "neo-hooke, not taken by a rubber law.",
       .lower = greater_than(0)},
      {.path = "bodies[].material.nu", .type = T::number,
       .doc = "Poisson's ratio; required with E, not taken by a rubber law.",
       .lower = greater_than(-1), .upper = less_than(0.5)},
      {.path = "bodies[].material.C10", .type = T::number, .unit = "force/length²",
       .doc = "Coefficient of (I1bar - 3) of a rubber law (required by each; half the "
              "small-strain shear modulus of neo-hooke-split and yeoh).",
       .lower = greater_than(0)},
      {.path = "bodies[].material.C01", .type = T::number, .unit = "force/length²",
       .doc = "Coefficient of (I2bar - 3): mooney-rivlin only (required there).",
       .lower = at_least(0)},
      {.path = "bodies[].material.C20", .type = T::number, .unit = "force/length²",
       .doc = "Coefficient of (I1bar - 3)^2: yeoh only (required there).", .lower = at_least(0)},
      {.path = "bodies[].material.C30", .type = T::number, .unit = "force/length²",
       .doc = "Coefficient of (I1bar - 3)^3: yeoh only (required there).", .lower = at_least(0)},
      {.path = "bodies[].material.K", .type = T::number, .unit = "force/length²",
       .doc = "Bulk modulus of a rubber law (required by each): U(J) = K/2 (J - 1)^2. Rubber's "
              "K is ~1000 times its shear modulus 2 (C10 + C01); the displacement elements "
              "stiffen (lock) as that ratio grows, less so at high p (formulation: mixed does "
              "not). Not with incompressible: true.",
       .lower = greater_than(0)},
      {.path = "bodies[].material.incompressible", .type = T::boolean, .default_yaml = "false",
       .doc = "A rubber law with 1/K = 0 (nu = 0.5 exactly): J = 1, held weakly by the mixed "
              "element's pressure; give it instead of K. Needs formulation: mixed (its default "
              "then)."},
      {.path = "bodies[].material.formulation", .type = T::choice,
       .doc = "A rubber law's element. `displacement`: W of the displacement alone (locks as "
              "K / mu grows). `mixed`: displacement of degree p and a pressure discontinuous "
              "between elements, of total degree p - 1 (P_{p-1}; p the element's lowest degree, "
              "its edges' included, where hp grades the degrees), in Pi = int W_iso + p (J - 1) "
              "- p^2 / (2K) dV: no locking at any K, incompressible allowed; its pressure is "
              "the VTU field pressure_mixed (positive in tension) and enters the Cauchy stress "
              "reported. Absent: mixed when incompressible, else displacement (the answers of "
              "inputs written before it unchanged).",
       .choices = {"displacement", "mixed"}},
      {.path = "bodies[].material.plane", .type = T::choice, .default_yaml = "strain",
       .doc = "Plane strain, plane stress, or axisymmetric: the body is the meridian section "
              "of a solid of revolution about the axis x = 0 (x the radius r >= 0, y the axial "
              "coordinate z; ux = u_r, uy = u_z), with the hoop strain u_r / r; its integrals are "
              "over the whole circle (dV = 2 pi r dA), so forces, resultants and energies are "
              "totals of the solid (compare: 3-D Hertz of spheres). Linear or finite strain (the "
              "hoop stretch 1 + u_r / r in the deformation gradient); u_r = 0 "
              "on the axis is the user's constraint (the quadrature never evaluates 1/r at r = "
              "0); a multiplier node on the axis carries no share of the boundary, its pressure "
              "is the even extension of its neighbours'.",
       .choices = {"strain", "stress", "axisymmetric"}},
      {.path = "bodies[].material.thickness", .type = T::number,
       .unit = "length", .doc = "Out-of-plane thickness (absent: 1); not for an axisymmetric body.",
       .lower = greater_than(0)},

      {.path = "bodies[].curves[].nodes", .type = T::node_pair, .required = true,
       .doc = "The edge [a, b] of an element that the curve replaces, oriented from a to b."},
      {.path = "bodies[].curves[].arc", .type = T::section,
       .doc = "Circular arc; give exactly one of arc and parametric."},
      {.path = "bodies[].curves[].arc.center", .type = T::point, .required = true,
       .unit = "length", .doc = "Centre of the circle, [x, y]."},
      {.path = "bodies[].curves[].arc.radius", .type = T::number, .required = true,
       .unit = "length", .doc = "Radius of the circle.", .lower = greater_than(0)},
      {.path = "bodies[].curves[].arc.ccw", .type = T::boolean,
       .doc = "true: counter-clockwise from a to b; false: clockwise; absent: the shorter arc."},
      {.path = "bodies[].curves[].parametric", .type = T::section,
       .doc = "Parametric curve; give exactly one of arc and parametric."},
      {.path = "bodies[].curves[].parametric.x", .type = T::string, .required = true,
       .unit = "length", .doc = "x(s) for s in [0, 1] from node a to node b (muparser formula)."},
      {.path = "bodies[].curves[].parametric.y", .type = T::string, .required = true,
       .unit = "length", .doc = "y(s) for s in [0, 1] from node a to node b (muparser formula)."},

      {.path = "bodies[].constraints[].edges", .type = T::string_list,
       .doc = "Names of edge sets; give edges, nodes or both.", .min_items = 1},
      {.path = "bodies[].constraints[].nodes", .type = T::integer_list,
       .doc = "Node ids; give edges, nodes or both.", .min_items = 1},
      {.path = "bodies[].constraints[].ux", .type = T::scalar_text, .unit = "length",
       .doc = "Prescribed x displacement: a number or a formula in x, y; absent: free. Give ux, "
              "uy or both."},
      {.path = "bodies[].constraints[].uy", .type = T::scalar_text, .unit = "length",
       .doc = "Prescribed y displacement: a number or a formula in x, y; absent: free."},

      {.path = "bodies[].loads[].edges", .type = T::string_list, .required = true,
       .doc = "Names of the loaded edge sets.", .min_items = 1},
      {.path = "bodies[].loads[].pressure", .type = T::number, .unit = "force/length²",
       .doc = "Normal pressure, positive pushing into the body; give exactly one of pressure and "
              "traction."},
      {.path = "bodies[].loads[].traction", .type = T::point, .unit = "force/length²",
       .doc = "Traction vector [tx, ty]; give exactly one of pressure and traction."},
      {.path = "bodies[].loads[].resultant", .type = T::number, .unit = "force/length",
       .doc = "If given, the load is scaled so that the magnitude of its integral over the edges "
              "equals this (per unit thickness; for an axisymmetric body the total over the "
              "surface of revolution).",
       .lower = greater_than(0)},
      {.path = "bodies[].loads[].shape", .type = T::choice, .default_yaml = "constant",
       .doc = "Profile along the loaded part, t in [0, 1] from its start to its end: constant 1, "
              "linear 1 - t, bspline1 (1 - t)² (seed: ½(1 - t)²), bspline2 1 - 3t² up to t = ⅓ and "
              "1.5(1 - t)² beyond (the seed's eq. 4.9: the right half of a quadratic B-spline), "
              "hermite 1 - 3t² + 2t³ (eq. 4.10), or a formula (expression; not split at its "
              "kinks). All scaled to 1 at t = 0.",
       .choices = {"constant", "linear", "bspline1", "bspline2", "hermite", "expression"}},
      {.path = "bodies[].loads[].expression", .type = T::string,
       .doc = "Formula in x, y multiplying the load; required if and only if shape is expression."},
      {.path = "bodies[].loads[].along", .type = T::choice, .default_yaml = "x",
       .doc = "Coordinate along which t runs.", .choices = {"x", "y"}},
      {.path = "bodies[].loads[].interval", .type = T::point, .unit = "length",
       .doc = "[start, end] of t in the along coordinate, start != end; absent: the whole edges."},
      {.path = "bodies[].loads[].follower", .type = T::boolean, .default_yaml = "false",
       .doc = "A pressure that follows the deformation: it acts normal to the deformed boundary "
              "per unit deformed length (and deformed circle 2 pi r of an axisymmetric body), "
              "its shape taken at the undeformed points; only with pressure. In the residual "
              "and tangent of a finite-strain body (the load stiffness); in the linear theory a "
              "follower pressure is the dead pressure. Scaled by the load factor like every load."},
      {.path = "bodies[].loads[].penetration", .type = T::section,
       .doc = "Pressure penetration (a seal's system pressure): the follower pressure acts only "
              "from one end of its edges (one chain) up to the first point in contact of a "
              "contact pair pressing harder than the pressure, nothing beyond (the sealed side); "
              "the stop is held through each Newton solve and moved between solves of a load step "
              "to where the converged state puts it, until it stays (docs/theory.md §12). Only "
              "with follower: true; the pair's edges on this body "
              "must overlap the load's. summary.json reports where the pressure stops and "
              "whether it reached the far end (the seal leaks: a warning)."},
      {.path = "bodies[].loads[].penetration.contact", .type = T::integer, .required = true,
       .doc = "Index of the contact pair (contact[K]) whose contact stops the pressure.",
       .lower = at_least(0)},
      {.path = "bodies[].loads[].penetration.from", .type = T::choice, .default_yaml = "start",
       .doc = "The pressurised end of the loaded edges' chain: start (its first vertex, in the "
              "order the edge sets list the edges) or end.",
       .choices = {"start", "end"}},

      {.path = "bodies[].nodal_forces[].node", .type = T::integer, .required = true,
       .doc = "Node id."},
      {.path = "bodies[].nodal_forces[].force", .type = T::point, .required = true,
       .unit = "force", .doc = "Force [fx, fy]."},

      {.path = "discretization", .type = T::section, .default_yaml = "{}",
       .doc = "How the bodies are discretised."},
      {.path = "discretization.method", .type = T::choice, .default_yaml = "p",
       .doc = "p: hierarchic p-elements; h: Lagrange h-elements.", .choices = {"p", "h"}},
      {.path = "discretization.degree", .type = T::degree, .default_yaml = "4",
       .doc = "Polynomial degree of the p-version, p or [p_xi, p_eta].", .lower = at_least(1),
       .upper = at_most(max_degree)},
      {.path = "discretization.space", .type = T::choice,
       .doc = "p-version shape space: full tensor product or trunk (serendipity). Absent: trunk "
              "for hp with goal-oriented degrees (adapt.degree goal, the default with "
              "adapt.tolerance: fewer dofs for an accuracy, examples/hertz/CONVERGENCE.md) "
              "without axisymmetric bodies and friction, else tensor (with friction the trunk "
              "loop was 5-12 times slower, its active set settling slowly: docs/theory.md).",
       .choices = {"tensor", "trunk"}},
      {.path = "discretization.element", .type = T::choice, .default_yaml = "Q8",
       .doc = "h-version element (ignored by the p-version).", .choices = {"Q4", "Q8", "Q9"}},
      {.path = "discretization.quadrature_extra", .type = T::integer, .default_yaml = "2",
       .doc = "Gauss points per direction = max(p_xi, p_eta) + this.", .lower = at_least(0),
       .upper = at_most(50),
       .upper_why = "an element's quadrature points grow as the square of this, and beyond p + 50 "
                    "points per direction the integrals of these polynomial and smooth integrands "
                    "change by round-off only"},
      {.path = "discretization.condense", .type = T::boolean, .default_yaml = "false",
       .doc = "Static condensation of the internal modes."},

      {.path = "solver", .type = T::section, .default_yaml = "{}",
       .doc = "How the equations are solved."},
      {.path = "solver.linear", .type = T::choice, .default_yaml = "cholmod",
       .doc = "Sparse direct solver: CHOLMOD (in a contact solve it gives way to LU from the first "
              "tangent that is not positive definite, or with finite strain not symmetric to "
              "round-off), Eigen's SimplicialLDLT, or UMFPACK's LU (used whatever is set with "
              "tangent: finite-difference, and with friction at small strain; with ldlt for finite "
              "strain too: those tangents can be indefinite or unsymmetric).",
       .choices = {"cholmod", "ldlt", "lu"}},
      {.path = "solver.tangent", .type = T::choice, .default_yaml = "analytic",
       .doc = "Newton tangent: analytic (consistent), or the seed's central finite differences of "
              "the whole residual, column by column, normals of the undisturbed state kept (eq. "
              "3.35-3.36; slow, for comparison).",
       .choices = {"analytic", "finite-difference"}},
      {.path = "solver.load_steps", .type = T::integer, .default_yaml = "1",
       .doc = "Number of equal load steps.", .lower = at_least(1), .upper = at_most(10000),
       .upper_why = "each step is at least one solve of the whole system; a path that needs more "
                    "is one for solver.control: arc-length"},
      {.path = "solver.max_iterations", .type = T::integer, .default_yaml = "30",
       .doc = "Newton iterations per load step.", .lower = at_least(1), .upper = at_most(1000),
       .upper_why = "Newton converges in tens of iterations or not at all; load steps or line "
                    "search help where more iterations do not"},
      {.path = "solver.tolerance", .type = T::number, .default_yaml = "1e-10",
       .doc = "Newton convergence: relative residual norm.",
       .lower = greater_than(0)},
      {.path = "solver.max_cuts", .type = T::integer, .default_yaml = "5",
       .doc = "Halvings of a load step that does not converge: a step is never shorter than "
              "the nominal one halved max_cuts times (it doubles again, up to the nominal one, "
              "after two converged steps). A step of that length that does not converge ends "
              "the run: the load cannot be carried beyond the last converged step. A halved step "
              "that fails with the same residuals as the longer one ends it at once: what does "
              "not converge does not change with the load (bodies overlapping in the input).",
       .lower = at_least(0), .upper = at_most(50),
       .upper_why = "a step halved 50 times is 1e-15 of its length, below what double precision "
                    "resolves of the load factor"},
      {.path = "solver.line_search", .type = T::choice, .default_yaml = "auto",
       .doc = "Backtracking line search on the residual norm (a Newton correction that does not "
              "reduce |R| is halved, up to 10 times): auto = on with friction (its stick/slip "
              "switches make plain Newton cycle with a large tangential penalty) and with contact "
              "between two bodies (large trial corrections project points onto far parts of the "
              "other boundary), on, off.",
       .choices = {"auto", "on", "off"}},
      {.path = "solver.control", .type = T::choice, .default_yaml = "load",
       .doc = "load: load steps with prescribed factors (Newton in each, cut and regrown). "
              "arc-length: the cylindrical arc-length method (Crisfield) on the factor of the "
              "loads, which passes limit points (snap-through): prescribed displacements are "
              "applied first in load steps with the loads at 0, then each step advances a fixed "
              "length of the displacement increment with the load factor unknown, the length "
              "scaled by sqrt(5 / iterations) after each step and halved when a step fails; the "
              "path to load factor 1 is written to path.csv. The first length is that of a "
              "load step of 1/load_steps.",
       .choices = {"load", "arc-length"}},
      {.path = "solver.monitor", .type = T::section,
       .doc = "A node whose displacement path.csv records at every step (e.g. the top of a "
              "ring), besides the load factor and the contact resultant."},
      {.path = "solver.monitor.body", .type = T::string, .required = true,
       .doc = "Name of the body."},
      {.path = "solver.monitor.node", .type = T::integer, .required = true,
       .doc = "Node id in that body."},
      {.path = "solver.stages", .type = T::section_list,
       .doc = "The load path, stage by stage: the factors on the prescribed displacements and on "
              "the loads go linearly from the previous stage's values (0 and 0 at the start) to "
              "the stage's, in its steps. Absent: one stage to 1 and 1. With friction the path "
              "matters (e.g. press first, then push sideways)."},
      {.path = "solver.stages[].displacements", .type = T::number,
       .doc = "Factor on every prescribed displacement (and obstacle displacement) at the end of "
              "the stage; absent: 1 (for the directions displacements_x and displacements_y do "
              "not give). Under solver.target_resultant: the share of the target force the stage "
              "reaches (the factor is found), the last stage's 1."},
      {.path = "solver.stages[].displacements_x", .type = T::number,
       .doc = "Factor on the x components of the prescribed displacements (ux, and an obstacle "
              "displacement's x) at the end of the stage, where it differs from displacements: "
              "e.g. 0 in a stage that presses in y, 1 in the next that pushes sideways with the "
              "press held (a displacement-driven tangential stage). Path files then carry "
              "displacement_factor_x and displacement_factor_y (displacement_factor is y's)."},
      {.path = "solver.stages[].displacements_y", .type = T::number,
       .doc = "Factor on the y components of the prescribed displacements at the end of the "
              "stage, where it differs from displacements."},
      {.path = "solver.stages[].loads", .type = T::number, .default_yaml = "1",
       .doc = "Factor on every load (edge loads, nodal forces, body force) at the end of the stage."},
      {.path = "solver.stages[].steps", .type = T::integer,
       .doc = "Load steps of the stage; absent: solver.load_steps.", .lower = at_least(1),
       .upper = at_most(10000),
       .upper_why = "each step is at least one solve of the whole system"},
      {.path = "solver.target_resultant", .type = T::section,
       .doc = "Load control by force: the prescribed displacements are scaled until the contact "
              "resultant's component equals value. With exact contact the factor is one more "
              "unknown of Newton's system; with friction (whose answer depends on the path) in "
              "solver.load_steps force-controlled steps, each to its share of value. With "
              "solver.stages (exact contact) each stage's displacements is the share of value it "
              "reaches and its loads go as given, the factor found in every step: press to a "
              "force, then shear with that force held (stages [{displacements: 1, loads: 0}, "
              "{displacements: 1, loads: 1}])."},
      {.path = "solver.target_resultant.value", .type = T::number, .required = true,
       .unit = "force", .doc = "The contact resultant's component to reach.",
       .lower = greater_than(0)},
      {.path = "solver.target_resultant.component", .type = T::choice, .default_yaml = "y",
       .doc = "Which component of the contact resultant is controlled.", .choices = {"x", "y"}},
      {.path = "solver.target_resultant.tolerance", .type = T::number, .default_yaml = "1e-9",
       .doc = "Relative tolerance on reaching value.", .lower = greater_than(0)},

      {.path = "contact", .type = T::section_list,
       .doc = "Contact boundaries of bodies against rigid obstacles or each other, enforced by a "
              "normal penalty; absent: no contact."},
      {.path = "contact[].body", .type = T::string, .required = true,
       .doc = "Name of the body in contact."},
      {.path = "contact[].edges", .type = T::string_list, .required = true,
       .doc = "Names of the body's edge sets that may come into contact.", .min_items = 1},
      {.path = "contact[].obstacle", .type = T::section, .required = true,
       .doc = "What the body's edges touch: a rigid obstacle or another body."},
      {.path = "contact[].enforcement", .type = T::choice, .default_yaml = "augmented-lagrangian",
       .doc = "augmented-lagrangian: the contact condition exactly (g_N >= 0, pressure >= 0, "
              "pressure × g_N = 0), the pressure an unknown at the multiplier nodes (the p + 1 "
              "Gauss-Lobatto points of each contact edge of trace degree p), found with the "
              "active set by a semi-smooth Newton method; penalty: the seed's normal penalty at "
              "the Gauss points (eq. 3.19), whose pressure eps_N <-g_N> needs a penetration.",
       .choices = {"augmented-lagrangian", "penalty"}},
      {.path = "contact[].constraint", .type = T::choice, .default_yaml = "auto",
       .doc = "augmented-lagrangian: where the non-penetration condition is imposed. collocation: "
              "the gap at each node (no penetration at the nodes; between two bodies it cannot "
              "carry a uniform pressure across non-matching meshes). mortar: the gap weighted by "
              "each node's Lagrange polynomial over its edges, integrated with the pair's "
              "quadrature, between two bodies on segments split where the other body's vertices "
              "project (the contact patch test to round-off). auto: collocation against a rigid "
              "obstacle (more accurate on coarse meshes: Hertz p = 8 energy error 3.7e-4 against "
              "mortar's 1.2e-3), mortar against another body.",
       .choices = {"auto", "mortar", "collocation"}},
      {.path = "contact[].normal", .type = T::choice, .default_yaml = "auto",
       .doc = "augmented-lagrangian between two bodies: the direction the gap is measured and "
              "the pressure acts along. other: the other body's outward normal at the closest "
              "point (one-sided). mean: the mean of both boundaries' normals there, "
              "(n_other - n_own)/|n_other - n_own| (two-sided: both bodies treated alike, so "
              "that two mirror-image bodies press along the mirror's normal, equal one body on "
              "the mirror plane even where the discrete surfaces cross, "
              "examples/hertz/bilateral.yaml, and hold each other by friction without a "
              "tangential traction where the mirror says there is none; the tangent is solved "
              "by LU). auto: mean for a pair with friction between two bodies under the mortar "
              "rule, other otherwise. "
              "Against a rigid obstacle only other applies.",
       .choices = {"auto", "other", "mean"}},
      {.path = "contact[].carrier", .type = T::choice, .default_yaml = "as-written",
       .doc = "augmented-lagrangian between two bodies: which body carries the multipliers "
              "(the one-sided constraint is posed on its surface). as-written: `body`. auto: "
              "chosen by a rule symmetric in the two bodies, the first of these that tells them "
              "apart: the body whose contact boundary lies within the other's (the larger share "
              "of its contact length faces the other's boundary, by more than 1e-3: its "
              "multipliers end where the other surface does, and a zone ending there ends at a "
              "node — a shaft in a shorter hub: the hub); the finer contact mesh (more "
              "multiplier nodes per unit length where they face each other, by more than 1 %); "
              "the softer body (E' at the first contact edge); the body named first under "
              "`bodies`. summary.json's `carrier` says which and why; `body`, the pair's rows "
              "and its forces are then the chosen body's. Not with `compare`, whose closed forms "
              "are measured along the obstacle as written.",
       .choices = {"as-written", "auto"}},
      {.path = "contact[].interference", .type = T::choice, .default_yaml = "initial",
       .doc = "augmented-lagrangian: what an overlap of the bodies in the input (an interference "
              "fit: a shaft meshed larger than its bore) does. initial: it is there from the "
              "first load step on. ramp: it is relieved in proportion to the factor on the "
              "prescribed displacements (displacements_y where displacements_x and _y differ), "
              "closed at factor 1 — the bodies are pressed together step by step, as a shrink fit "
              "cools, e.g. with friction, whose path matters, or an interference too large for "
              "one step; each multiplier node's weighted overlap at the undeformed state is "
              "added to its gap times (1 - factor). The answer at factor 1 is initial's.",
       .choices = {"initial", "ramp"}},
      {.path = "contact[].penalty", .type = T::number, .unit = "force/length³",
       .doc = "penalty: the normal penalty eps_N (seed eq. 3.19; the seed uses 1000·E), "
              "required. augmented-lagrangian: the augmentation of the active-set test and of "
              "the factorised tangent, a parameter of convergence speed and conditioning, not "
              "of the answer; absent: E/(1 - nu²) p²/h at each node (E of the body, p and h of "
              "the node's contact edge).",
       .lower = greater_than(0)},
      {.path = "contact[].normal_direction", .type = T::point,
       .doc = "The direction the pair's normal force (summary.json normal_force) is measured "
              "along, [dx, dy], non-zero (normalised when read): the component of the contact "
              "resultant on the body along it, positive when the force pushes the body along "
              "it; tangential_force is the component along it turned clockwise (dy, −dx). Default: "
              "the normal of the surface the pair is reported along when that is a line (a "
              "plane obstacle; another body's straight edges; the common tangent of two bodies "
              "that touch over a zone small against their radii, a cylinder on a cylinder; a "
              "curve obstacle's tangent at its point); on a circle (a pin in a hole, a shaft in a "
              "hub: conforming surfaces) the resultant's own direction, normal_force then being "
              "its magnitude, with no tangential force."},
      {.path = "contact[].quadrature", .type = T::integer, .default_yaml = "50",
       .doc = "Gauss points per contact edge, independent of p (seed: 50).",
       .lower = at_least(1), .upper = at_most(200)},
      {.path = "contact[].friction", .type = T::section,
       .doc = "Friction (seed §3.3), Coulomb's law; absent: frictionless. augmented-lagrangian: "
              "a tangential multiplier at each multiplier node against the weighted slip since "
              "the last converged load step (stick rows, or slip at mu times the normal "
              "multiplier: a primal-dual active set); penalty: the seed's tangential penalty with "
              "a return mapping at every contact Gauss point, a point anchored to the other side "
              "at the end of the first load step in which it is in contact, its tangential gap "
              "measured along the tangent at the anchor (frozen). Either way the result depends "
              "on the load path (see solver.stages), and the tangent is not symmetric: solved by "
              "LU."},
      {.path = "contact[].friction.law", .type = T::choice, .required = true,
       .doc = "stick: no slip whatever the traction (exact: no relative tangential motion at the "
              "nodes; penalty: the tangential penalty only); coulomb: slip where |t_T| would "
              "exceed mu p_N; none: frictionless.",
       .choices = {"none", "stick", "coulomb"}},
      {.path = "contact[].friction.mu", .type = T::number,
       .doc = "Coulomb friction coefficient; required by law: coulomb.", .lower = at_least(0)},
      {.path = "contact[].friction.penalty", .type = T::number, .unit = "force/length³",
       .doc = "enforcement: penalty: the tangential penalty eps_T (seed eq. 3.19), required "
              "unless law is none. augmented-lagrangian: the augmentation of the stick test (a "
              "parameter of convergence, not of the answer); absent: the normal one.",
       .lower = greater_than(0)},
      {.path = "contact[].compare", .type = T::section,
       .doc = "Measure the contact pressure against Hertz and Shtayerman and, optionally, a "
              "reference curve; absent: no comparison. The closed forms are those of the pair: "
              "the contact modulus E* (1/E* = 1/E'_1 + 1/E'_2, E' = E/(1 - nu²) in plane "
              "strain, E in plane stress, 1/E'_2 = 0 for a rigid obstacle; E and nu of the "
              "element at the first contact edge) and radius R* (1/R* = 1/radius + "
              "1/other_radius). They are measured on force per unit length along the obstacle "
              "(contact.csv's pressure), over [0, 1.5 b] from obstacle.point. Checked before "
              "the solve: the materials, the radii, the force against the load and the "
              "reference curve's force. A force given under displacement control is a nominal "
              "value: summary.json's compared_for reports the force the pair carries and the "
              "difference (a warning beyond 1 %)."},
      {.path = "contact[].compare.radius", .type = T::number, .unit = "length",
       .doc = "Radius R_1 of the body's surface at the contact; absent: that of its contact "
              "edges' arcs (all arcs of one circle), else required. A value that contradicts "
              "those arcs is refused.",
       .lower = greater_than(0)},
      {.path = "contact[].compare.other_radius", .type = T::number, .unit = "length",
       .doc = "Radius R_2 of the obstacle's surface, negative where it is concave (a hole); "
              "absent: derived — a plane: infinite; a rigid circle: its radius (negative with "
              "inside); another body: the arc of its contact edges (all arcs of one circle; "
              "infinite if they are straight), else required; a curve: infinite. A value that "
              "contradicts a plane or a circle is refused; not 0."},
      {.path = "contact[].compare.force", .type = T::number, .unit = "force/length",
       .doc = "Force F on the whole cylinder per unit thickness (axisymmetric: the total force on "
              "the sphere), which the closed forms are "
              "computed for; absent: derived from the load — under solver.target_resultant "
              "(pair 0 with its normal along the controlled component) before the solve, else "
              "from the pair's resultant after it. A model whose contact boundary lies on one "
              "side of obstacle.point (a symmetric half) carries F/2, a whole model F. A value "
              "that contradicts the target is refused before the solve.",
       .lower = greater_than(0)},
      {.path = "contact[].compare.reference", .type = T::string,
       .doc = "CSV with columns x (undeformed, along the obstacle) and a pressure (force per unit "
              "length along the obstacle): the pressure.csv of an overkill run of the same model, "
              "relative to this file; absent: none. Of an exact-contact run (a "
              "pressure_multiplier column) its `pressure` is read, else pressure_from_stress (or "
              "pressure); between samples p² is interpolated linearly (the square-root end of "
              "the zone kept). Refused when its force, ∫ pressure dx over x >= 0 (∫ p 2 pi r dr "
              "for an axisymmetric body), differs from F/2 (F) by more than 1 %."},

      {.path = "contact[].obstacle.type", .type = T::choice, .required = true,
       .doc = "plane: a straight line; circle: a disc (or a hole with inside); curve: a smooth "
              "curve through points; profile: straight segments through points with sharp or "
              "filleted corners (grooves, chamfers, housings); body: another deformable body "
              "(bilateral contact; exact: "
              "the pair's own body carries the multiplier nodes and its gap is measured against "
              "the other's deformed boundary, one-sided; penalty: the points of both sides are "
              "evaluated, each with half weight, and the penalty acts on the gap between the "
              "bodies).",
       .choices = {"plane", "circle", "curve", "profile", "body"}},
      {.path = "contact[].obstacle.body", .type = T::string,
       .doc = "body: name of the other body; required if and only if type is body."},
      {.path = "contact[].obstacle.edges", .type = T::string_list,
       .doc = "body: names of the other body's edge sets that may come into contact.",
       .min_items = 1},
      {.path = "contact[].obstacle.point", .type = T::point, .default_yaml = "[0, 0]",
       .unit = "length",
       .doc = "plane: a point of the line, [x, y]; curve, profile: the origin of positions along "
              "it (half width, pressure curves). curve: they are measured along its tangent at "
              "the point of the curve nearest to this one (the common tangent of the linear "
              "theory; not the chord, which an asymmetric point list tilts); profile: as the arc "
              "length along the profile from the point of it nearest to this one (one segment: "
              "along it, as a plane's), and the normal force is measured along the profile's "
              "normal there."},
      {.path = "contact[].obstacle.normal", .type = T::point, .default_yaml = "[0, 1]",
       .doc = "plane: normal pointing away from the obstacle towards the body, [nx, ny], non-zero "
              "(normalised when read)."},
      {.path = "contact[].obstacle.center", .type = T::point, .default_yaml = "[0, 0]",
       .unit = "length", .doc = "circle: centre, [x, y]."},
      {.path = "contact[].obstacle.radius", .type = T::number, .unit = "length",
       .doc = "circle: radius; required if and only if type is circle.", .lower = greater_than(0)},
      {.path = "contact[].obstacle.points", .type = T::point_list, .unit = "length",
       .doc = "curve, profile: the points the obstacle's boundary passes through, in order, [[x, "
              "y], ...]; required if and only if type is curve or profile. The body lies to the "
              "boundary's left walking from the first point to the last. curve: the natural cubic "
              "spline through them (chord-length parameter; two points: a straight line), "
              "continued straight along its end tangents. profile: the straight segments between "
              "them, continued straight beyond the first and last point (closed: the last joined "
              "to the first instead); a point must not repeat the one before it (nor, closed, the "
              "last the first), and the chain must not turn back on itself, cross or touch "
              "itself. The gap is the signed distance to the closest point of the boundary; at a "
              "sharp corner the closest point of a point in its fan of normals is the corner, "
              "and the normal the direction from the corner to the point.", .min_items = 2},
      {.path = "contact[].obstacle.gmsh", .type = T::section,
       .doc = "profile, curve: the points from a Gmsh file instead of points (MSH 4.1 ASCII; a "
              "1D mesh is enough: gmsh -1 -format msh41). The line elements of a 1D physical "
              "group are chained end to end: their vertices and the midside nodes of "
              "second-order lines in order, walking the way the group's first line in the file "
              "runs (Gmsh orients a line along its curve), points where the chain goes straight "
              "on left out (a straight Gmsh line of many elements is one segment; a meshed arc "
              "stays the polygon of its nodes: give a profile's round corners as fillet). A "
              "chain that returns to its start makes a closed profile. Expanded when read: the "
              "effective input lists the points and closed instead of this key, and its header "
              "says how many points came from how many lines."},
      {.path = "contact[].obstacle.gmsh.file", .type = T::string, .required = true,
       .doc = "Path of the .msh file, relative to the problem file's folder."},
      {.path = "contact[].obstacle.gmsh.curve", .type = T::string, .required = true,
       .doc = "Name of a 1D physical group of the file: one chain of lines (no branches, one "
              "piece)."},
      {.path = "contact[].obstacle.gmsh.reverse", .type = T::boolean, .default_yaml = "false",
       .doc = "Walk the chain the other way (the body lies to the boundary's left walking from "
              "the first point to the last)."},
      {.path = "contact[].obstacle.fillet", .type = T::numbers, .default_yaml = "0",
       .unit = "length",
       .doc = "profile: the radii of circular fillets rounding its corners (the interior points of "
              "an open profile, every point of a closed one): one number for all corners, or a "
              "list with one per corner in order; 0: sharp. A fillet is the arc tangent to both "
              "segments, r tan(θ/2) from the corner (θ the turn there); the fillets at the two "
              "ends of a segment must fit on it.", .lower = at_least(0)},
      {.path = "contact[].obstacle.closed", .type = T::boolean, .default_yaml = "false",
       .doc = "profile: true joins the last point to the first (a closed profile: the body "
              "outside it when the points run clockwise, inside when counter-clockwise)."},
      {.path = "contact[].obstacle.inside", .type = T::boolean, .default_yaml = "false",
       .doc = "circle: false: the body stays outside the circle; true: inside it."},
      {.path = "contact[].obstacle.displacement", .type = T::point, .default_yaml = "[0, 0]",
       .unit = "length",
       .doc = "plane, circle, curve, profile: rigid displacement of the obstacle, [dx, dy], applied with the load "
              "factor like the prescribed displacements (a displacement-driven indenter)."},

      {.path = "exact", .type = T::section,
       .doc = "A closed-form solution to measure the error against; absent: none."},
      {.path = "exact.type", .type = T::choice, .required = true,
       .doc = "Which closed form: lame, the thick cylinder (plane bodies); lame_sphere, the thick "
              "sphere centred on the axis (axisymmetric bodies, its meridian section); none "
              "switches it off.",
       .choices = {"lame", "lame_sphere", "none"}},
      {.path = "exact.inner_radius", .type = T::number, .unit = "length",
       .doc = "Inner radius of the thick cylinder or sphere; required.", .lower = greater_than(0)},
      {.path = "exact.outer_radius", .type = T::number, .unit = "length",
       .doc = "Outer radius, > inner_radius; required.", .lower = greater_than(0)},
      {.path = "exact.inner_pressure", .type = T::number, .default_yaml = "0",
       .unit = "force/length²", .doc = "Pressure on the inner surface."},
      {.path = "exact.outer_pressure", .type = T::number, .default_yaml = "0",
       .unit = "force/length²", .doc = "Pressure on the outer surface."},
      {.path = "exact.center", .type = T::point, .default_yaml = "[0, 0]", .unit = "length",
       .doc = "Centre of the cylinder, [x, y]; of the sphere, a point of the axis [0, z]."},

      {.path = "adapt", .type = T::section,
       .doc = "Adaptive changes of the mesh at the ends of the contact zone (Γ*); absent: none."},
      {.path = "adapt.method", .type = T::choice, .required = true,
       .doc = "rp: move the boundary node nearest to each Γ* onto it along the exact boundary "
              "(interior neighbours follow if an element would invert), solve again, until node "
              "and Γ* coincide (seed §4.8). hp: where a zone is narrow against its elements (the "
              "node nearest Γ* would move more than half its shorter edge), first refine towards "
              "the boundary node nearest Γ* until one is near; move that node onto Γ* once, then "
              "refine geometrically around it, one layer per step, the degree rising by one per "
              "layer away from Γ* (seed §4.7, Fig. 4.12-4.13); a step whose Γ* leaves the two "
              "smallest elements is refined again around the new Γ*; with adapt.tolerance, until "
              "the estimated error is below it. hp also refines towards the singular points "
              "(summary.json singular_points: a zone closed up to an end or corner of the contact "
              "edges, examples/flat-punch/coarse-hp.yaml), around the node there (which stays) or "
              "for the other body's corner the node moved onto its foot, a zone end within the "
              "elements touching one being the point's; the estimate leaves those elements out "
              "(the pressure is unbounded there). With a tolerance, when one contact edge holds "
              "most of the estimated error and a zone end there has no refinement following it "
              "(two zone ends at one node of a coarse input mesh), hp refines towards it too from "
              "the next step. none: no adaptivity.",
       .choices = {"rp", "hp", "none"}},
      {.path = "adapt.tolerance", .type = T::number,
       .doc = "hp: the accuracy asked for, the relative L2 error of the contact pressure (with "
              "exact friction also of the shear, the larger of the two; a shear below 1 % of "
              "mu times the pressure, as on a contact pressed only, has its error measured "
              "against the pressure's size instead of its own), in "
              "(0, 1); each step's error is estimated from a solve one degree higher on its mesh "
              "and the loop stops at the first below it (adapt.steps is then the most it may "
              "take); absent: adapt.steps steps. rp: stop when every moved node is within this "
              "fraction of its body's size (bounding-box diagonal) of its Γ*; absent: 1e-10.",
       .lower = greater_than(0)},
      {.path = "adapt.max_dofs", .type = T::integer, .default_yaml = "200000",
       .doc = "hp with a tolerance: a step whose mesh has more free dofs ends the loop (a "
              "failure, the best estimated step kept in last-good/).",
       .lower = at_least(1)},
      {.path = "adapt.max_iterations", .type = T::integer, .default_yaml = "20",
       .doc = "rp: relocations after the first solve; not reaching the tolerance is a failure.",
       .lower = at_least(1), .upper = at_most(200),
       .upper_why = "each relocation is a full solve; rp converges in a few or stalls"},
      {.path = "adapt.factor", .type = T::number,
       .doc = "hp: size of the element at Γ* relative to the one it is cut from, per step; "
              "absent: the seed's 0.5, or 0.15 with adapt.tolerance (fewest DOF per accuracy "
              "measured on Hertz, examples/hertz/CONVERGENCE.md; 0.17 is the classical optimum "
              "for corner singularities).",
       .lower = greater_than(0), .upper = less_than(1)},
      {.path = "adapt.steps", .type = T::integer,
       .doc = "hp: refinement steps (absent: 8), with adapt.tolerance the most it may take "
              "(absent: 12, or fewer where adapt.factor^12 < 1e-11); with adapt.factor, "
              "factor^steps at least 1e-11 (see Limits).",
       .lower = at_least(1), .upper = at_most(40)},
      {.path = "adapt.degree", .type = T::choice,
       .doc = "hp: rising: min_degree at Γ* and one more per layer away from it (elements far "
              "from Γ* get min_degree + steps + 1); constant: discretization.degree everywhere; "
              "goal (needs adapt.tolerance): rising, and after each step an element whose "
              "goal-oriented indicator of the contact traction's error (pressure and, with "
              "friction, shear, each relative to its size) per dof of one degree "
              "more is above 3 times the mean gets one degree more in every later step, one "
              "below 0.1 times the mean one less (docs/theory.md, Goal-oriented degrees). "
              "With rising and goal, facing contact edges of two bodies get the larger of their "
              "elements' two degrees (unequal, they make a stick zone's shear oscillate). "
              "Absent: goal with adapt.tolerance, else rising.",
       .choices = {"rising", "constant", "goal"}},
      {.path = "adapt.min_degree", .type = T::integer, .default_yaml = "1",
       .doc = "hp: degree of the elements at Γ* (rising degree).", .lower = at_least(1),
       .upper = at_most(max_degree)},
      {.path = "adapt.update", .type = T::choice, .default_yaml = "secant",
       .doc = "rp: secant: secant steps on Γ*(node) - node along the boundary (fewer solves); "
              "relocate: put the node onto the last Γ* (the seed's iteration).",
       .choices = {"secant", "relocate"}},
      {.path = "adapt.stick_slip", .type = T::boolean, .default_yaml = "true",
       .doc = "rp and hp: adapt to the stick–slip points of exactly enforced Coulomb pairs as to "
              "the zone ends (a node moved onto each, or a refinement centre at each, on both "
              "bodies): the tangential traction ends there with the square root the pressure "
              "has at Γ*. The points are summary.json's `friction.stick_slip_points`; a node "
              "whose point is gone in a later solve stays where it is."},

      {.path = "output", .type = T::section, .default_yaml = "{}",
       .doc = "What is written next to the results."},
      {.path = "output.vtu", .type = T::boolean, .default_yaml = "true",
       .doc = "Write the solution as VTK unstructured grids for ParaView: solution.vtu (the "
              "bodies: displacement, strains, stresses, von Mises, principal stresses, element "
              "degree) and, with contact, contact.vtu (the contact Gauss points of each pair as a "
              "line: traction, gap, pressure, pressure from the stresses, tangential traction, "
              "slip, state)."},
      {.path = "output.steps", .type = T::boolean, .default_yaml = "false",
       .doc = "Nonlinear runs: also write the bodies (and the contact points) of every converged "
              "load step, steps/step-NNNN.vtu (steps/contact-NNNN.vtu), and solution.pvd "
              "(contact.pvd) that ParaView plays as a time series, time = the step's load "
              "factor (force control: the step number, as the factor goes back and forth)."},
      {.path = "output.vtu_subdivisions", .type = T::integer, .default_yaml = "0",
       .doc = "Sub-cells per element edge in the .vtu file; 0: automatic from the degree.",
       .lower = at_least(0), .upper = at_most(100),
       .upper_why = "the file holds (this + 1)² points per element, and 100² cells per element are "
                    "finer than any plot of it shows"},
      {.path = "output.effective_input", .type = T::boolean, .default_yaml = "true",
       .doc = "Write the effective input (defaults filled, --set applied) to reproduce the run."},
  };
  // clang-format on
  return table;
}
#pragma GCC diagnostic pop

const KeySpec* find_key_spec(std::string_view pattern, const Schema& schema) {
  for (const KeySpec& key : schema)
    if (key.path == pattern) return &key;
  return nullptr;
}

std::vector<const KeySpec*> child_key_specs(std::string_view parent_pattern,
                                            const Schema& schema) {
  std::vector<const KeySpec*> children;
  for (const KeySpec& key : schema) {
    std::string_view p = key.path;
    if (!parent_pattern.empty()) {
      if (p.size() <= parent_pattern.size() + 1 || !p.starts_with(parent_pattern) ||
          p[parent_pattern.size()] != '.')
        continue;
      p.remove_prefix(parent_pattern.size() + 1);
    }
    if (p.find_first_of(".[") == std::string_view::npos) children.push_back(&key);
  }
  return children;
}

namespace {

std::string format_number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

/// "> 0", "in (-1, 0.5)", "in [1, 30]" or "" for unbounded.
std::string describe_bounds(const KeySpec& key) {
  if (key.lower && key.upper)
    return "in " + std::string(key.lower->inclusive ? "[" : "(") + format_number(key.lower->value) +
           ", " + format_number(key.upper->value) + (key.upper->inclusive ? "]" : ")");
  if (key.lower) return (key.lower->inclusive ? ">= " : "> ") + format_number(key.lower->value);
  if (key.upper) return (key.upper->inclusive ? "<= " : "< ") + format_number(key.upper->value);
  return "";
}

std::string with_bounds(std::string type, const KeySpec& key) {
  const std::string bounds = describe_bounds(key);
  return bounds.empty() ? type : type + " " + bounds;
}

std::string escape_cell(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string describe_default(const KeySpec& key) {
  if (key.required) return "required";
  if (key.default_yaml.empty()) return "optional";
  if (key.default_yaml == "{}") return "(all defaults)";
  return std::string("`").append(key.default_yaml).append("`");
}

/// The table of the keys under `parent_pattern`, then those of its sections, depth first.
void render_section(std::ostringstream& md, std::string_view parent_pattern, const Schema& schema) {
  const std::vector<const KeySpec*> children = child_key_specs(parent_pattern, schema);
  md << "| key | type | default | unit | meaning |\n|---|---|---|---|---|\n";
  for (const KeySpec* key : children) {
    std::string doc(key->doc);
    if (!key->upper_why.empty())
      doc += " At most " + format_number(key->upper->value) + ": " + std::string(key->upper_why) + ".";
    md << "| `" << key->path << "` | " << escape_cell(describe_type(*key)) << " | "
       << describe_default(*key) << " | " << key->unit << " | " << escape_cell(doc) << " |\n";
  }
  for (const KeySpec* key : children) {
    if (key->type != T::section && key->type != T::section_list) continue;
    const std::string pattern = std::string(key->path) + (key->type == T::section_list ? "[]" : "");
    md << "\n## `" << pattern << "`\n\n" << key->doc << "\n\n";
    render_section(md, pattern, schema);
  }
}

}  // namespace

std::string describe_type(const KeySpec& key) {
  switch (key.type) {
    case T::section: return "section";
    case T::section_list:
      return key.min_items > 0 ? "list of sections, at least " + std::to_string(key.min_items)
                               : "list of sections";
    case T::string: return "string";
    case T::number: return with_bounds("number", key);
    case T::integer: return with_bounds("integer", key);
    case T::boolean: return "bool";
    case T::choice: {
      std::string s = "one of: ";
      for (std::size_t i = 0; i < key.choices.size(); ++i)
        s += (i ? ", " : "") + std::string(key.choices[i]);
      return s;
    }
    case T::point: return "[number, number]";
    case T::node_pair: return "[node id, node id]";
    case T::degree: return with_bounds("integer or [p_xi, p_eta], each", key);
    case T::point3: return "[number, number, number]";
    case T::degree3: return with_bounds("integer or [p_xi, p_eta, p_zeta], each", key);
    case T::count3: return with_bounds("integer or [n_x, n_y, n_z], each", key);
    case T::scalar_text: return "number or formula";
    case T::string_list: return "list of names";
    case T::point_list: return "list of [x, y], at least " + std::to_string(key.min_items);
    case T::numbers: return with_bounds("number or list of numbers, each", key);
    case T::integer_list: return "list of integers";
    case T::node_table: return "map: node id -> [x, y]";
    case T::element_table: return "map: element id -> [n1, n2, n3, n4]";
    case T::degree_table: return with_bounds("map: element id -> p or [p_xi, p_eta], each", key);
    case T::edge_set_table: return "map: name -> list of [node id, node id]";
  }
  return "";
}

std::string input_schema_markdown() {
  std::ostringstream md;
  md << "# Problem file reference\n\n"
        "A problem file is YAML. Keys are given by their dotted path; `[]` stands for any list "
        "index. Unknown keys are errors. A key with a default is filled in when absent (the "
        "effective input written next to the results lists it); an optional key without a default "
        "stays absent. Any key can be changed from the command line with "
        "`--set path=value`, e.g. `--set bodies[0].material.E=1e5` or "
        "`--set discretization.degree=[6,4]`. \"The seed\" below is the dissertation the "
        "method follows (D. Franke, TU München; references.md), \"seed eq. 3.19\" its "
        "equation.\n\n## Top level\n\n";
  render_section(md, "", input_schema());
  md << "\n## Limits\n\n"
        "What a run may ask for is bounded, so that a mistake is an error at once instead of a "
        "run that never ends or runs out of memory:\n\n"
        "- Files: the problem file and a study file are read only if they are regular files (not "
        "a device such as /dev/zero, a pipe or a folder) of at most "
     << (kMaxYamlBytes >> 20)
     << " MB, as is a problem given to the Python module as text (`Problem.from_yaml`), a "
        "`--set` value (or `set=`) and the effective input a run writes (input.yaml, the problem "
        "with its defaults filled in: it is read back to reproduce the run, so a problem whose "
        "effective input would pass a limit is refused when read); a .msh file of at most "
     << (kMaxMeshFileBytes >> 20) << " MB, with at most " << kMaxMeshNodes << " nodes and "
     << kMaxMeshElements
     << " elements (of every type, as its $Nodes and $Elements headers count them); a "
        "`compare.reference` curve of at most "
     << (kMaxReferenceBytes >> 20) << " MB.\n"
        "- YAML values: the tree of a problem (the file, its `--set` values, the meshes of its "
        "Gmsh files and its defaults) or of a study holds at most "
     << kMaxYamlValues
     << " values: every scalar, list, map and empty value counts one, an alias what it repeats "
        "(an alias inside what it names, a cycle, is refused). The tree takes some 500 bytes "
        "of memory per value, up to 500 per byte of text, so the values are counted before it is "
        "built: the reading stops at the first value beyond the limit and names its line, or, "
        "for a flow list or map (`[...]`, `{...}`, which yaml-cpp reads whole before it reports "
        "any of it), at its bracket. A problem at the limit takes some 600 MB and 5 s of CPU to "
        "read. A mesh takes about 4 values per node and 6 per element, given inline or as a Gmsh "
        "file alike: some 10⁵ elements fit, far more than a p-FEM mesh needs (it gains accuracy "
        "by the degree).\n"
        "- Numbers: every real number of the file (values, node coordinates, numbers given where "
        "a formula may be, and the values formulas take) is 0 or of a magnitude between 1e-100 and 1e100, so that "
        "products of them stay within double precision (1e-308 to 1e308); every result is "
        "checked to be finite before it is reported.\n"
        "- Keys with an upper bound say it and why in the tables above.\n"
        "- Keys that multiply are bounded together, when the problem is read: the elements' modes "
        "(elements × 2(p_xi+1)(p_eta+1)) at most "
     << kMaxUnknowns << ", quadrature points (elements × (p + quadrature_extra)²) at most "
     << kMaxQuadraturePoints << ", contact Gauss points (contact edges × quadrature, twice for "
        "two bodies) at most "
     << kMaxContactPoints << ", points of solution.vtu (elements × (vtu_subdivisions + 1)²) at "
        "most "
     << kMaxVtuPoints << "; hp: the smallest elements, adapt.factor ^ adapt.steps of the first "
        "ones, at least "
     << kMinHpScale << " (at factor 0.5 36 steps, at 0.17 14).\n"
        "- Memory: before the sparse Cholesky factorisation (CHOLMOD) fills its factor, the size "
        "its symbolic analysis gives (the factor, its largest update matrix and the copies of "
        "the matrix) is compared with the memory the run may still use (the least of `ulimit "
        "-v` less what the process uses, the control group's memory.max less its use, and the "
        "system's MemAvailable); a factor that will not fit is refused, naming the size in GB "
        "and what to do, instead of the process being ended by the kernel.\n";
  md << "\n## Output files\n\n"
        "Lengths, forces and stresses are in the units of the problem file (the program has no "
        "unit system of its own; summary.json's `units` says so). Forces and pressures are per "
        "unit thickness (plane strain: per unit length of the cylinder).\n\n"
        "- `summary.json`: the run's figures — `converged`, `dofs`, `strain_energy`, "
        "`load_steps`, `newton_iterations` (of the final solve; `newton_iterations_total` of "
        "every solve of the run), `shape_space` of the p-version (tensor or trunk), the first "
        "contact pair as `contact` and every pair "
        "in `contact_pairs` (body, obstacle, `enforcement`, `carrier` (exact contact between two "
        "bodies: \"as written: body '...'\" or, with contact[].carrier: auto, \"auto: \" and the "
        "rule that chose the body), `resultant` [x, y] the integral of "
        "the contact tractions on the body, `normal_force` its component along "
        "`normal_direction` (contact[].normal_direction, else the surface's normal where it is a "
        "line, else the resultant's own direction: positive in compression), `tangential_force` "
        "(where the direction is named or the surface straight), `surface` the surface the pair "
        "is reported along (a plane; a circle where the surfaces conform: a pin in a hole, a shaft "
        "in a hub, with `gamma_star_angles` the zone ends' angles about its centre; another body's "
        "straight edges; else the common tangent of the linear theory), `zone` {`from`, `to`, "
        "`length`} the zone's extent as arc length along it of the undeformed points (where the "
        "linear theory's closed forms — Hertz, Shtayerman, Persson, Sadowsky — put the pressure) "
        "and `deformed` {`from`, `to`, `length`} that of the deformed ones (they differ by the "
        "displacements along the surface: Hertz p = 8 at b/R = 0.2, 2.5 %), "
        "with friction `friction` (`stick_points`, `slip_points`, "
        "`stick_slip_transitions` midway between neighbouring points along the boundary of "
        "which one sticks and one slips, never across an open or not yet anchored point; a "
        "penalty pair between two bodies also `stick_slip_transitions_other` on the other "
        "body; exact Coulomb pairs also `stick_slip_points`, the stick–slip points located "
        "between a sticking and a slipping node as the root of |λ_T + κ ĝ_T| − μ λ_N along the "
        "edge (ĝ_T the last step's slip, κ = E' p / h; what rp and hp adapt to, `adapt.stick_slip`) "
        "undeformed, and against another body `stick_slip_points_other` their feet on it; "
        "`memory_points` (and `memory_points_other`) the stick–slip points of earlier load steps "
        "where every later step stuck: the tangential traction keeps a kink there (unloaded after "
        "a shear, Mindlin and Deresiewicz's loading stick zone end; hp refines towards them too); "
        "`tangential_traction_integral` ∫ t_T dS, the force the friction carries along "
        "the contact.csv tangent; Coulomb: `tangential_force_capacity` mu ∫ p_N dS, the most it "
        "could carry, and `tangential_force_ratio` |∫ t_T dS| / capacity, 1 in gross sliding), "
        "`tangent` the direction `tangential_force` (resultant · tangent) is along, "
        "`contact_length` the zone's length along the surface, `gamma_star` the zone ends "
        "undeformed (each once), `half_width` where that is what it is (a straight surface and a "
        "zone symmetric about the obstacle's point, or a half model's from it; absent otherwise), "
        "`pressure_max` the largest `pressure` below away from the singular points, "
        "`singular_points` (only where there are any) the points where the exact pressure is "
        "unbounded — the zone closed up to an end or a corner (a turn of more than 10°) of either "
        "body's contact edges, not on a mirror or the axis, with the pressure rising towards it: "
        "`at` the point undeformed and `at_deformed`, `s` its place along the surface, `where` which body's end or "
        "corner, `peak` the pressure nearest it (the discretisation's, `peak_converged` false), "
        "`excluded_within` the distance within which pressures are left out of the fit (the "
        "elements touching it; hp's estimate leaves them out too), `pressure_max_beyond` that of "
        "`pressure_max` (beyond those elements and 1 % of the zone's extent from it), `fit` (null with fewer than 6 pressures beyond them: "
        "refine towards the point) the singularity p ≈ K d^-λ fitted in least squares of log p "
        "over d from `from` to `to` (a quarter of the zone's extent): `exponent` λ, `strength` K, "
        "`square_root_strength` K½ = lim p d^(1/2) (a rigid flat punch's corner, frictionless: "
        "P / (π √(2a)) for Sadowsky's), `points`, `rms_log_residual` of each fit; a warning says "
        "the same, `traction_max` = "
        "`p_max` the largest traction the method carries, `max_penetration`; with `compare` the "
        "errors `e_L2_*`, `e_seed_*` of the pressure from the stresses, under `multiplier` (or "
        "`penalty_traction`) those of the method's own pressure, and `compared_for` the F, E*, "
        "R* used), `adapt` for rp and hp runs (`history` a record per iteration or step, with "
        "its `dofs`, `elements`, `degree_range` [lowest, highest], "
        "`stopped` why the loop ended, `result_step` the one kept; hp with a tolerance: "
        "`estimated_error` of the result and of each step — `pressure_rel_L2`, `energy_rel`, "
        "with exact Coulomb friction `shear_rel_L2`, from a solve one degree higher on the step's mesh; with goal-oriented degrees each step's "
        "`degrees`, how many elements it gave a degree more and a degree less), `error` with "
        "`exact`, `reactions` (2D) what the supports and pairs exert on the bodies at the "
        "result (the last converged step): `supports` a record per constraint entry of every body "
        "(`body`, `constraint` its index in bodies[].constraints, its `edges`, `nodes` and "
        "`components`, `force` [x, y] the residual f_int(u) − f − f_c the solve leaves at the "
        "dofs it prescribes, from the solver's own element routines with the condensed modes "
        "recovered, summed over the vertex modes alone (the constant field 1 is the vertex "
        "modes: the edge and internal modes vanish at the vertices; Lagrange: every node), "
        "`moment` about the origin, counter-clockwise, the same residual on the rotation field "
        "(x × f with x the position's own modes: exact on straight edges, on curved ones to the "
        "projection's error, below 1e-11 from p = 6; finite strain: the deformed position)), a "
        "dof that two entries prescribe belongs to the first listed (`shared_dofs`), `pairs` "
        "per contact pair the contact `force` on its body (its `resultant`) and `moment`, "
        "`balance` per body the sums of its supports' `reactions`, its `loads` (tractions, "
        "pressures, nodal and body forces at the loads' factor) and its `contact` forces, their "
        "`imbalance` and `relative` (the imbalance over the largest force involved); "
        "axisymmetric bodies: the forces are totals over the whole circle (2 pi r included, as "
        "`resultant`), x the radial total, no moment (null), and only the axial component "
        "balances (the radial totals are carried by the hoop stresses); `equilibrium_residual` "
        "the largest `relative` of a body, with a warning above `equilibrium_limit` (1e-6) "
        "(follower pressures count among the loads, on the deformed boundary, over their "
        "wetted part); `penetration` (loads with bodies[].loads[].penetration, one record "
        "each): `load` its place in the file, `contact` and `from` as given, `stop` the "
        "undeformed point where the pressure stops (the first multiplier node or point of the "
        "pair, from the pressurised end, that presses harder than the pressure), "
        "`wetted_length` the undeformed length it acts on, `leaks` whether it reached the far "
        "end of its edges (no point seals; also a warning naming the load and the pair).\n"
        "- `contact.csv`: a row per contact point — exact contact: the multiplier nodes; "
        "penalty: the Gauss points; a two-body pair lists both bodies' points (`body`). "
        "Columns: `pair`; `X`, `Y` undeformed and `x`, `y` deformed position; `gap` (exact: the "
        "node's weighted gap ĝ; negative: penetration); `pressure` the contact pressure, the "
        "normal force per unit length along the pair's surface (summary.json `surface`: the "
        "traction times dS/ds, s the arc length along it; per unit length of the meridian for an "
        "axisymmetric body, whose ring force per unit meridian length is 2 pi r times it); "
        "each row per unit of its own body's undeformed surface (length, and 2 pi r), as its "
        "stresses are: the other body's rows of an exact pair read the carrier's multipliers at "
        "their feet and refer them to their own surface, times (w dS) / (w_o dS_o) (w the "
        "carrier's 2 pi r or thickness at the foot, dS / dS_o the two undeformed lengths that "
        "touch, from the two surfaces' stretches), so each body's rows are the same whichever "
        "body carries the multipliers (a press fit: to 1e-6, docs/theory.md); "
        "`pressure_from_stress` the same from the body's "
        "stresses, n_o·(P N) dS/ds (P N the traction per unit undeformed length, σ N in the "
        "linear theory; n_o the obstacle's outward normal at the deformed point, which the normal "
        "multiplier acts along; with `normal: mean` the mean of it and the body's own deformed "
        "normal); `tangential_gap` (penalty: (x − x_anchor)·τ of an anchored point; exact: the "
        "node's weighted slip over the last load step, zero where it sticks or is open), `tangential_traction` t_T (the multiplier or "
        "penalty traction, per unit undeformed length), `slip` (friction: the slip over the whole load "
        "path; exact: the node's step slips added up, kept when it opens; the other body's rows of "
        "an exact pair: both slips read at the point's foot between this body's nodes, the "
        "relative slip, as t_T), signed along the "
        "tangent τ = (`tangent_x`, `tangent_y`) = (n_y, −n_x), n the outward normal of what the "
        "point touches, the same way along the whole boundary: against a rigid obstacle its "
        "tangent ((1, 0) on a plane with normal (0, 1)); between two bodies the other body's "
        "normal turned, so the two bodies' rows have opposite tangents and t_T of one sign (the "
        "row's body receives −t_T τ; zero where the point has no foot); `state` open, contact, "
        "stick or slip; `s` the position along the pair's surface (arc length); `traction` "
        "what the method carries per unit undeformed boundary length (the multiplier, or the "
        "penalty traction ε_N⟨−g_N⟩); `minus_sigma_nn` −n·σ·n on the body's own undeformed "
        "normal (the seed's plotted pressure); `shear_from_stress` the tangential traction from "
        "the stresses, −τ·(P N) dS/ds (t_T dS/ds, per unit length along the obstacle as "
        "`pressure`).\n"
        "- `pressure.csv` (with `compare`): 1001 points of [0, 1.5 b] along the obstacle: `x`, "
        "`pressure_from_stress`, `pressure_multiplier` (penalty: `pressure_penalty`: the traction "
        "the method carries), `hertz`, `shtayerman`, `pressure` and `minus_sigma_nn` as in "
        "contact.csv.\n"
        "- `path.csv`: a row per converged load step: `step`, `displacement_factor`, "
        "`load_factor`, `iterations`, `arc_length`, with `solver.monitor` `monitor_ux`, "
        "`monitor_uy`, the first pair's `resultant_x`, `resultant_y` and `pairN_resultant_x`, "
        "`pairN_resultant_y` for each further pair (rp and hp: the final mesh's solve, the first "
        "pair's resultant only), then (runs without rp or hp; after any displacement_factor_x, "
        "_y) per constraint entry `reaction_<body>_<entry>_x`, `_y` and `_moment` (empty for an "
        "axisymmetric body) as "
        "summary.json's `reactions` at that step, and `equilibrium_residual`.\n"
        "- `contact_history.csv` (runs without rp or hp): a row per converged load step and "
        "pair: `step`, `displacement_factor`, `load_factor`, `pair`, `body`, `resultant_x`, "
        "`resultant_y`, `normal_force`, `tangential_force`, `contact_length`, `pressure_max`, "
        "`traction_max`, `max_penetration`, `contact_points`, `stick_points`, `slip_points` "
        "(`scripts/plot_contact_history.py` draws it).\n"
        "- `solution.vtu` (ParaView): displacement, strain, stress, von Mises, principal "
        "stresses at the element samples (a 180° corner of a blending map sampled just inside); "
        "`sigma_zz` is the stress normal to the plane: nu (sigma_xx + sigma_yy) in linear plane "
        "strain, 0 in plane stress, and for an axisymmetric body (x the radius, y the axis) the "
        "hoop stress sigma_theta, and `strain_hoop` its hoop strain u_r / r; a mixed rubber body "
        "also `pressure_mixed`, its element pressure; "
        "`contact.vtu` the contact points with the columns of contact.csv; `input.yaml` the "
        "effective input (defaults filled in, `--set` applied).\n"
        "- `report.html` (2D runs): the run on one page for a browser, self-contained (inline SVG "
        "figures, no script, nothing fetched): the problem (bodies, materials, loads, supports, "
        "contact pairs), the key numbers with their units (named as this page's unit column "
        "names them) and the error measures, the warnings and singular points, the pressure "
        "(with friction also the shear) along each pair, von Mises on the deformed mesh (true "
        "scale; the contact zone enlarged), and an hp or rp loop's history; every number of "
        "summary.json it shows carries its key there (`data-key=\"contact_pairs.0.pressure_max\"`, "
        "10 digits). A failed run's, in `last-good/`, opens with a banner: the run failed, why, "
        "and that this is the last converged state. `hpcontact study` writes one too: study.csv "
        "as a table and its error measures against DOF (docs/study.md).\n";
  md << "\n## Warnings\n\n"
        "`check` (on its output) and `run` (on stderr, whatever `-q` says; summary.json "
        "`warnings`) say what the input allows but a user should know, each naming the file, the "
        "place and the cause; the run goes on:\n\n"
        "- Mesh quality (of the input's mesh, not of meshes hp or rp make): an element on a contact "
        "edge whose edge is more than 10 times its depth (the edge's length squared over the "
        "element's area: needles along a contact surface resolve the pressure as coarsely as they "
        "are long); an aspect ratio (the largest ratio of the singular values of the element "
        "map's Jacobian at its Gauss points) above 300; a Jacobian ratio (the largest over the "
        "smallest det J there) above 20. Stretched p-elements are right where the field is smooth "
        "along them, so the general limits are those no designed mesh reaches.\n"
        "- A contact zone that lies on one or two contact edges and is shorter than a tenth of "
        "the shortest of them: its pressure, peak and ends are that element's polynomial's "
        "(refine towards it, or `adapt: {method: hp}`).\n"
        "- An axisymmetric body whose nodes on the axis may move radially (no `ux: 0` there), and "
        "one of linear elasticity whose deformed section crosses the axis.\n";
  md << "\n## The output folder\n\n"
        "`hpcontact run` (and `hpcontact study`, and the Python module's `run(out=...)`) writes "
        "its results into an output folder (`--out`, default `results/<problem file name>`):\n\n"
        "- The files are written into a staging folder inside it (`.hpcontact-staging-XXXXXX`) "
        "and moved into place, each by a rename, only when the run has succeeded. A run that "
        "fails after a converged state replaces only `last-good/` (that state, with `converged: "
        "false`); any other failure, a wrong `--set` or a killed run leaves the folder as it "
        "was. The next run removes a staging folder a killed run left.\n"
        "- `hpcontact run` sent SIGTERM (a scheduler's time limit), SIGINT (Ctrl-C) or SIGHUP stops "
        "within a moment — before its next Newton iteration, or inside one (the iteration given "
        "up between two elements, blocks of an element's points or a factorisation's phases) — "
        "and ends as a failed run: what had converged (the last load step, or an hp or rp loop's "
        "best step) in `last-good/`, the earlier results left; the process then ends by the same "
        "signal. A second signal more than a second after the first "
        "kills it at once; within a second it is the same request delivered twice (`timeout` "
        "signals the run and its process group; Ctrl-C reaches a study's runs from the terminal "
        "and from the study).\n"
        "- `.hpcontact-manifest` lists the files the last run wrote; a run replaces or removes "
        "only those. A file with an output name (`summary.json`, `report.html`, `input.yaml`, `contact.csv`, "
        "`pressure.csv`, `path.csv`, `contact_history.csv`, `mesh.yaml`, `solution.vtu`, `contact.vtu`, "
        "`solution.pvd`, `contact.pvd`, `rp/pressure-N.csv`, `hp/pressure-N.csv`, "
        "`steps/step-NNNN.vtu`, `steps/contact-NNNN.vtu`, all of these in `last-good/`; for a "
        "study `study.csv`, `study.json`, `report.html`, `runs/NN-label/log.txt`, "
        "`stopped/runs/NN-label/log.txt`) that the manifest does not "
        "list is someone else's: the run is refused, naming it, before anything is solved. "
        "Other files are never touched. (Results of an hpcontact without manifests count as "
        "someone else's: remove them.)\n"
        "- A folder that holds the problem file or a `compare` section's `reference` file "
        "(directly or in a folder below) is refused.\n"
        "- Symbolic links inside the folder are never followed: a link where an output goes "
        "refuses the folder. The folder itself may be a link.\n"
        "- A run holds a lock on the folder (`.hpcontact-lock`) while it writes; a second run into "
        "the same folder fails at once.\n"
        "- Every file is checked to the disk (each write, fsync and close): a full disk ends the "
        "run with exit code 1 and a message naming the file and the system's reason.\n"
        "- `study` passes SIGINT, SIGTERM and SIGHUP on to its running runs, waits for them, "
        "writes no table and ends by the same signal; each stopped run keeps what had converged "
        "in its `runs/NN-label/last-good/`, and the logs of the runs it started are moved to "
        "`stopped/runs/NN-label/log.txt` (replaced by the next stopped study, removed by the "
        "next finished one). A study killed outright (SIGKILL), which can pass nothing on, "
        "leaves no run computing: each of its runs stops as on SIGTERM when the study dies, "
        "keeping its `last-good/`.\n";
  md << "\n# 3D problems (`dimension: 3`)\n\n"
        "A file with `dimension: 3` at its top level is a 3D problem: one body meshed with "
        "hierarchic hexahedra (integrated-Legendre vertex, edge, face and internal modes, exact "
        "spherical faces for `shell_octant`), isotropic linear elasticity, constraints and "
        "surface loads on named face sets; one linear solve with the internal modes condensed. "
        "It writes `summary.json` (`dimension`, `dofs`, `strain_energy`, `volume`, "
        "`displacement_max`, `von_mises_max` at the Gauss points, with `exact` the relative "
        "energy-norm `error`), `solution.vtu` and `input.yaml`. The limits above apply (the "
        "unknowns counted as elements × 3(p_xi + 1)(p_eta + 1)(p_zeta + 1)). Examples: "
        "`examples/solid/`. Its keys:\n\n"
     << schema_tables_markdown(solid_schema());
  return md.str();
}

std::string schema_tables_markdown(const Schema& schema) {
  std::ostringstream md;
  render_section(md, "", schema);
  return md.str();
}

}  // namespace hpcontact::io
