// The Python module `hpcontact`: read or compose a problem, run it, and read its results as
// numpy arrays. A thin layer over the library (io, driver, post): no numerics of its own.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/driver/run.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/rigid_motion.hpp"
#include "hpcontact/model/solid_model.hpp"
#include "hpcontact/post/fields.hpp"
#include "hpcontact/post/point_location.hpp"
#include "hpcontact/post/summary.hpp"
#include "hpcontact/post/vtu.hpp"

namespace py = pybind11;
using namespace hpcontact;

namespace {

/// nlohmann::json -> dict, list, str, int, float, bool or None.
py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::object: {
      py::dict d;
      for (auto it = j.begin(); it != j.end(); ++it) d[py::str(it.key())] = to_python(it.value());
      return d;
    }
    case nlohmann::json::value_t::array: {
      py::list l;
      for (const auto& v : j) l.append(to_python(v));
      return l;
    }
    case nlohmann::json::value_t::string: return py::str(j.get<std::string>());
    case nlohmann::json::value_t::boolean: return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer: return py::int_(j.get<std::int64_t>());
    case nlohmann::json::value_t::number_unsigned: return py::int_(j.get<std::uint64_t>());
    case nlohmann::json::value_t::number_float: return py::float_(j.get<double>());
    default: return py::none();
  }
}

template <class T>
py::array_t<T> to_numpy(const std::vector<T>& v) {
  py::array_t<T> a(static_cast<py::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

/// The `set=` argument: None, one "key.path=value" string, a sequence of them, or a mapping
/// {key.path: value} (values written as YAML: True -> true, others by str()).
std::vector<std::string> overrides_from(const py::object& set) {
  std::vector<std::string> out;
  if (set.is_none()) return out;
  if (py::isinstance<py::str>(set)) return {set.cast<std::string>()};
  if (py::isinstance<py::dict>(set)) {
    for (const auto& [key, value] : set.cast<py::dict>()) {
      const std::string v = py::isinstance<py::bool_>(value)
                                ? (value.cast<bool>() ? "true" : "false")
                                : py::str(value).cast<std::string>();
      out.push_back(py::str(key).cast<std::string>() + "=" + v);
    }
    return out;
  }
  for (const auto& item : set) {
    if (!py::isinstance<py::str>(item))
      throw py::type_error("set: expected 'key.path=value' strings, got " +
                           py::repr(item).cast<std::string>());
    out.push_back(item.cast<std::string>());
  }
  return out;
}

/// A str or os.PathLike argument as a string.
std::string fspath(const py::object& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

/// A validated problem and the effective input it was read from.
struct Problem {
  io::ReadResult read;
};

/// A finished run: the library's result, held on the heap because the locator refers into it.
struct Result {
  std::shared_ptr<const driver::RunResult> run;
  std::optional<std::string> out;
  mutable std::unique_ptr<post::PointLocator> locator;  ///< built at the first point query

  const post::PointLocator& points() const {
    if (!locator) locator = std::make_unique<post::PointLocator>(run->discretization);
    return *locator;
  }
};

/// describe() of a 3D problem: its one body of hexahedra.
py::dict describe_solid(const model::ProblemSpec& spec) {
  const auto d = model::discretize_solid(*spec.solid, spec.file);
  py::dict bd;
  bd["name"] = spec.solid->body.name;
  bd["nodes"] = d.mesh.topology.n_nodes();
  bd["elements"] = d.mesh.topology.n_hexes();
  bd["faces"] = d.mesh.topology.n_faces();
  py::list bodies;
  bodies.append(bd);
  py::dict out;
  out["case"] = spec.case_name;
  out["method"] = "p";
  out["dimension"] = 3;
  out["bodies"] = bodies;
  out["dofs"] = d.n_free();
  out["dofs_condensed"] = d.n_free_external();
  return out;
}

py::dict describe(const Problem& p) {
  const auto& spec = p.read.spec;
  if (spec.solid) return describe_solid(spec);
  const auto d = model::discretize(spec);
  model::require_held(spec, d);
  py::list bodies;
  for (const auto& b : d.bodies) {
    py::dict bd;
    bd["name"] = b.name;
    bd["nodes"] = b.mesh.n_nodes();
    bd["elements"] = b.mesh.n_quads();
    bd["edges"] = b.mesh.n_edges();
    bodies.append(bd);
  }
  py::dict out;
  out["case"] = spec.case_name;
  out["method"] = d.method;
  out["bodies"] = bodies;
  out["dofs"] = d.n_free;
  out["dofs_condensed"] = d.n_free_external;
  return out;
}

Result run(const Problem& p, const py::object& out_arg, bool quiet, bool verbose) {
  std::optional<std::string> out;
  if (!out_arg.is_none()) out = fspath(out_arg);
  driver::RunOptions options;
  if (out) {
    options.out_dir = *out;
    options.effective_input = p.read.effective_yaml;
  }
  // Progress lines go to sys.stdout; the callback also lets Ctrl-C stop a long run.
  // (Newton's iterations only when verbose, as the command line's -v.)
  options.progress = [quiet, verbose](const ProgressEvent& e) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (quiet || (!verbose && e.as<IterationProgress>())) return;
    py::print("  " + e.text, py::arg("flush") = true);
  };
  std::shared_ptr<driver::RunResult> r;
  {
    py::gil_scoped_release release;
    r = std::make_shared<driver::RunResult>(driver::run_problem(p.read.spec, options));
  }
  // run_problem throws when the solve does not converge; this guards the promise regardless.
  if (!r->summary.converged)
    throw NumericalError(p.read.spec.file + ": the run did not converge");
  return Result{std::move(r), out, nullptr};
}

/// Locates every row of an (n, 2) array (or one point of shape (2,)) and evaluates `columns`
/// values per point with `eval`; the first point outside raises ValueError.
template <class Eval>
py::array_t<double> at_points(const Result& res, const py::array_t<double, py::array::c_style |
                                                                            py::array::forcecast>& points,
                              const std::optional<std::string>& body_name, int columns, Eval eval) {
  if (res.run->summary.extra.contains("dimension"))
    throw py::value_error(
        "fields at points of a 3D result are not available yet: read solution.vtu (e.g. with "
        "meshio) or summary");
  const bool single = points.ndim() == 1;
  if (!(single && points.shape(0) == 2) && !(points.ndim() == 2 && points.shape(1) == 2))
    throw py::value_error("points: expected an array of shape (n, 2) or (2,)");
  const auto& d = res.run->discretization;
  int body = -1;
  if (body_name) {
    for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b)
      if (d.bodies[b].name == *body_name) body = b;
    if (body < 0) {
      std::string names;
      for (const auto& b : d.bodies) names += (names.empty() ? "'" : ", '") + b.name + "'";
      throw py::value_error("body: no body '" + *body_name + "' (the bodies are " + names + ")");
    }
  }
  const py::ssize_t n = single ? 1 : points.shape(0);
  py::array_t<double> values(std::vector<py::ssize_t>{n, columns});
  auto v = values.mutable_unchecked<2>();
  const double* xy = points.data();
  for (py::ssize_t i = 0; i < n; ++i) {
    const Vec2 X(xy[2 * i], xy[2 * i + 1]);
    const auto loc = res.points().locate(X, body);
    if (!loc) {
      std::ostringstream os;
      os.precision(10);
      os << "point " << i << " (" << X.x() << ", " << X.y() << ") lies outside "
         << (body_name ? "body '" + *body_name + "'" : std::string("every body"));
      throw py::value_error(os.str());
    }
    const auto pr = post::evaluate(d.bodies[loc->body], loc->element, loc->xi, loc->eta, res.run->u);
    const auto row = eval(pr);
    for (int c = 0; c < columns; ++c) v(i, c) = row[c];
  }
  if (single) return values.reshape(std::vector<py::ssize_t>{columns});
  return values;
}

py::dict contact_table(const Result& res) {
  const auto& t = res.run->contact;
  py::dict out;
  out["pair"] = to_numpy(t.pair);
  out["X"] = to_numpy(t.X);
  out["Y"] = to_numpy(t.Y);
  out["x"] = to_numpy(t.x);
  out["y"] = to_numpy(t.y);
  out["gap"] = to_numpy(t.gap);
  out["pressure"] = to_numpy(t.pressure);
  out["pressure_from_stress"] = to_numpy(t.pressure_from_stress);
  out["tangential_gap"] = to_numpy(t.tangential_gap);
  out["tangential_traction"] = to_numpy(t.tangential_traction);
  out["slip"] = to_numpy(t.slip);
  out["state"] = py::module_::import("numpy").attr("array")(py::cast(t.state), "U7");
  out["body"] = py::module_::import("numpy").attr("array")(py::cast(t.body));
  out["s"] = to_numpy(t.s);
  out["traction"] = to_numpy(t.traction);
  out["minus_sigma_nn"] = to_numpy(t.minus_sigma_nn);
  out["tangent_x"] = to_numpy(t.tangent_x);
  out["tangent_y"] = to_numpy(t.tangent_y);
  out["shear_from_stress"] = to_numpy(t.shear_from_stress);
  return out;
}

/// path.csv's columns (the load path, a row per converged step) as numpy arrays.
py::dict load_history_of(const Result& res) {
  std::vector<int> step, iterations;
  std::vector<double> displacement_factor, displacement_factor_x, displacement_factor_y, load_factor,
      arc_length, resultant_x, resultant_y, monitor_ux, monitor_uy;
  for (const auto& p : res.run->path) {
    step.push_back(static_cast<int>(step.size()) + 1);
    iterations.push_back(p.iterations);
    displacement_factor.push_back(p.displacements);
    displacement_factor_x.push_back(p.displacement_factors.x());
    displacement_factor_y.push_back(p.displacement_factors.y());
    load_factor.push_back(p.loads);
    arc_length.push_back(p.arc_length);
    resultant_x.push_back(p.resultant.x());
    resultant_y.push_back(p.resultant.y());
    monitor_ux.push_back(p.monitor.x());
    monitor_uy.push_back(p.monitor.y());
  }
  py::dict out;
  out["step"] = to_numpy(step);
  out["displacement_factor"] = to_numpy(displacement_factor);
  out["displacement_factor_x"] = to_numpy(displacement_factor_x);
  out["displacement_factor_y"] = to_numpy(displacement_factor_y);
  out["load_factor"] = to_numpy(load_factor);
  out["iterations"] = to_numpy(iterations);
  out["arc_length"] = to_numpy(arc_length);
  out["resultant_x"] = to_numpy(resultant_x);
  out["resultant_y"] = to_numpy(resultant_y);
  out["monitor_ux"] = to_numpy(monitor_ux);
  out["monitor_uy"] = to_numpy(monitor_uy);
  return out;
}

/// contact_history.csv's columns (a row per converged step and pair) as numpy arrays.
py::dict contact_history_of(const Result& res) {
  const auto& rows = res.run->contact_history;
  auto column = [&](auto field) {
    std::vector<std::decay_t<decltype(field(rows.front()))>> v;
    for (const auto& r : rows) v.push_back(field(r));
    return v;
  };
  py::dict out;
  if (rows.empty()) return out;
  using Row = driver::ContactHistoryRow;
  out["step"] = to_numpy(column([](const Row& r) { return r.step; }));
  out["pair"] = to_numpy(column([](const Row& r) { return r.pair; }));
  out["body"] = py::cast(column([](const Row& r) { return r.body; }));
  out["displacement_factor"] = to_numpy(column([](const Row& r) { return r.displacement_factor; }));
  out["load_factor"] = to_numpy(column([](const Row& r) { return r.load_factor; }));
  out["resultant_x"] = to_numpy(column([](const Row& r) { return r.resultant.x(); }));
  out["resultant_y"] = to_numpy(column([](const Row& r) { return r.resultant.y(); }));
  out["normal_force"] = to_numpy(column([](const Row& r) { return r.normal_force; }));
  out["tangential_force"] = to_numpy(column([](const Row& r) { return r.tangential_force; }));
  out["contact_length"] = to_numpy(column([](const Row& r) { return r.contact_length; }));
  out["pressure_max"] = to_numpy(column([](const Row& r) { return r.pressure_max; }));
  out["traction_max"] = to_numpy(column([](const Row& r) { return r.traction_max; }));
  out["max_penetration"] = to_numpy(column([](const Row& r) { return r.max_penetration; }));
  out["contact_points"] = to_numpy(column([](const Row& r) { return r.contact_points; }));
  out["stick_points"] = to_numpy(column([](const Row& r) { return r.stick_points; }));
  out["slip_points"] = to_numpy(column([](const Row& r) { return r.slip_points; }));
  return out;
}

/// The reactions of the result's last converged step (reactions) and of every step
/// (reaction_history), as numpy arrays; the rows' meaning is summary.json's `reactions`.
py::dict reactions_of(const Result& res, bool history) {
  const auto& steps = res.run->reaction_history;
  py::dict out;
  const auto& bodies = res.run->discretization.bodies;
  if (steps.empty()) return out;
  const auto& last = steps.back();
  const auto n_s = static_cast<py::ssize_t>(last.supports.size());
  const auto n_p = static_cast<py::ssize_t>(last.pairs.size());
  const auto n_t = static_cast<py::ssize_t>(history ? steps.size() : 1);
  py::list body, constraint;
  for (const auto& s : last.supports) {
    body.append(bodies[s.body].name);
    constraint.append(s.constraint);
  }
  py::array_t<double> force({n_t, n_s, py::ssize_t(2)}), moment({n_t, n_s}),
      pair_force({n_t, n_p, py::ssize_t(2)}), pair_moment({n_t, n_p}), residual(n_t);
  auto f = force.mutable_unchecked<3>();
  auto m = moment.mutable_unchecked<2>();
  auto pf = pair_force.mutable_unchecked<3>();
  auto pm = pair_moment.mutable_unchecked<2>();
  auto e = residual.mutable_unchecked<1>();
  for (py::ssize_t t = 0; t < n_t; ++t) {
    const auto& r = history ? steps[t] : last;
    for (py::ssize_t i = 0; i < n_s; ++i) {
      f(t, i, 0) = r.supports[i].reaction.force.x();
      f(t, i, 1) = r.supports[i].reaction.force.y();
      m(t, i) = r.supports[i].reaction.moment;
    }
    for (py::ssize_t k = 0; k < n_p; ++k) {
      pf(t, k, 0) = r.pairs[k].force.x();
      pf(t, k, 1) = r.pairs[k].force.y();
      pm(t, k) = r.pairs[k].moment;
    }
    e(t) = r.equilibrium_residual;
  }
  out["body"] = body;
  out["constraint"] = constraint;
  if (history) {
    out["force"] = force;
    out["moment"] = moment;
    out["pair_force"] = pair_force;
    out["pair_moment"] = pair_moment;
    out["equilibrium_residual"] = residual;
  } else {
    out["force"] = force[py::int_(0)];
    out["moment"] = moment[py::int_(0)];
    out["pair_force"] = pair_force[py::int_(0)];
    out["pair_moment"] = pair_moment[py::int_(0)];
    out["equilibrium_residual"] = e(0);
  }
  return out;
}

/// The solution sampled as solution.vtu samples it (post::sample_mesh), as numpy arrays.
py::dict mesh_of(const Result& res, int subdivisions) {
  if (res.run->summary.extra.contains("dimension"))
    throw py::value_error("mesh() of a 3D result is not available yet: read solution.vtu with meshio");
  if (subdivisions < 0 || subdivisions > 64)
    throw py::value_error("subdivisions: expected 0 (the element's degree, 2..16) to 64, got " +
                          std::to_string(subdivisions));
  const post::SampledMesh m = post::sample_mesh(res.run->discretization, res.run->u, subdivisions);
  const auto n = static_cast<py::ssize_t>(m.points.size());
  // A column per value of each sampled point: (n, columns), or (n,) for one.
  auto per_point = [&](int columns, auto value) {
    py::array_t<double> a = columns == 1 ? py::array_t<double>(n) : py::array_t<double>({n, py::ssize_t(columns)});
    double* out = a.mutable_data();
    for (py::ssize_t i = 0; i < n; ++i)
      for (int c = 0; c < columns; ++c) out[i * columns + c] = value(m.points[i], c);
    return a;
  };
  using P = post::PointResult;
  py::dict out;
  out["points"] = per_point(2, [](const P& p, int c) { return p.x(c); });
  out["displacement"] = per_point(2, [](const P& p, int c) { return p.u(c); });
  out["strain"] = per_point(3, [](const P& p, int c) { return p.strain(c); });
  out["stress"] = per_point(4, [](const P& p, int c) { return c < 3 ? p.stress(c) : p.stress_zz; });
  out["von_mises"] = per_point(1, [](const P& p, int) { return p.von_mises; });
  out["principal_1"] = per_point(1, [](const P& p, int) { return p.principal_1; });
  out["principal_2"] = per_point(1, [](const P& p, int) { return p.principal_2; });
  const auto n_cells = static_cast<py::ssize_t>(m.cells.size());
  py::array_t<int> cells({n_cells, py::ssize_t(4)});
  auto c = cells.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n_cells; ++i)
    for (int k = 0; k < 4; ++k) c(i, k) = m.cells[i][k];
  out["cells"] = cells;
  out["cell_body"] = to_numpy(m.cell_body);
  out["cell_element"] = to_numpy(m.cell_element);
  out["cell_degree"] = to_numpy(m.cell_degree);
  py::list names;
  for (const auto& b : res.run->discretization.bodies) names.append(b.name);
  out["body_names"] = names;
  const auto& bodies = res.run->discretization.bodies;
  if (std::any_of(bodies.begin(), bodies.end(), [](const model::Body& b) { return b.mixed; }))
    out["pressure_mixed"] = per_point(1, [](const P& p, int) { return p.pressure; });
  return out;
}

py::object pressure_curve(const Result& res) {
  const auto& c = res.run->pressure_curve;
  if (!c) return py::none();
  py::dict out;
  out["x"] = to_numpy(c->x);
  out["pressure_from_stress"] = to_numpy(c->pressure_from_stress);
  out[c->multiplier ? "pressure_multiplier" : "pressure_penalty"] = to_numpy(c->traction);
  out["pressure"] = to_numpy(c->pressure);
  out["minus_sigma_nn"] = to_numpy(c->minus_sigma_nn);
  out["hertz"] = to_numpy(c->hertz);
  out["shtayerman"] = to_numpy(c->shtayerman);
  if (!c->reference.empty()) out["reference"] = to_numpy(c->reference);
  return out;
}

constexpr const char* kModuleDoc = R"(hpcontact: 2D contact problems with high-order finite elements.

Read or compose a problem, run it, and read the results as numpy arrays::

    import hpcontact
    problem = hpcontact.Problem.from_file("examples/hertz/p5.yaml",
                                          set=["discretization.degree=6"])
    result = problem.run()                 # or run(out="results/p6") to write the usual files
    result.summary["contact"]["p_max"]     # summary.json as a dict
    result.displacement([[0.0, 5.0]])      # (n, 2) at undeformed points
    result.contact()["pressure"]           # contact.csv's columns
    result.pressure_curve()["hertz"]       # pressure.csv's columns (with a compare section)

Errors: hpcontact.InputError (also a ValueError) for bad input, hpcontact.SolverError (also a
RuntimeError) when the solution fails, hpcontact.Error, their base, for anything else the
program reports (a file that cannot be written, a bad mesh). The message is the program's.)";

}  // namespace

PYBIND11_MODULE(hpcontact, m) {
  m.doc() = kModuleDoc;
  m.attr("__version__") = HPC_VERSION;

  // The exceptions: Error for everything the library reports, InputError and SolverError also
  // the built-in exception a Python user would expect.
  static py::handle error = PyErr_NewExceptionWithDoc(
      "hpcontact.Error", "An error hpcontact reports; str(e) is its one-line message.",
      PyExc_Exception, nullptr);
  const py::tuple input_bases = py::make_tuple(error, py::handle(PyExc_ValueError));
  static py::handle input_error = PyErr_NewExceptionWithDoc(
      "hpcontact.InputError",
      "Bad input: a key, value or reference of a problem; the message names the file, line and key.",
      input_bases.ptr(), nullptr);
  const py::tuple solver_bases = py::make_tuple(error, py::handle(PyExc_RuntimeError));
  static py::handle solver_error = PyErr_NewExceptionWithDoc(
      "hpcontact.SolverError",
      "The solution failed: no convergence (Newton, load steps, force control, an adaptive loop) "
      "or a numerical breakdown; the message names the load step and the cause.",
      solver_bases.ptr(), nullptr);
  m.attr("Error") = error;
  m.attr("InputError") = input_error;
  m.attr("SolverError") = solver_error;
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(input_error.ptr(), e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(solver_error.ptr(), e.what());
    } catch (const AdaptError& e) {
      PyErr_SetString(solver_error.ptr(), e.what());
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });

  py::class_<Problem>(m, "Problem", R"(A validated problem: the problem file read, the overrides applied.

Build one with Problem.from_file() or Problem.from_yaml(); it does not change afterwards (read
it again with other overrides to vary it).)")
      .def_static(
          "from_file",
          [](const py::object& path, const py::object& set) {
            return Problem{io::read_problem_full(fspath(path), overrides_from(set))};
          },
          py::arg("path"), py::arg("set") = py::none(),
          R"(Reads a YAML problem file (path: str or os.PathLike).

set: overrides as for `hpcontact run --set`: a list of "key.path=value" strings
(e.g. ["discretization.degree=6", "bodies[0].material.E=1e5"]) or a dict {"key.path": value}.
Raises InputError (the message names the file, line and key) or Error (file not readable).)")
      .def_static(
          "from_yaml",
          [](const std::string& text, const std::string& label, const py::object& set) {
            return Problem{io::parse_problem_full(text, label, overrides_from(set))};
          },
          py::arg("text"), py::arg("label") = "<string>", py::arg("set") = py::none(),
          R"(Builds a problem from YAML text (e.g. one a script composes).

label: the name messages give the text; files the problem names (a gmsh mesh, a reference
curve) are found relative to its folder. set: overrides, as for from_file(). The text and each
set value are bounded as a problem file and --set values are (docs/input.md, Limits: 16 MB,
10^6 YAML values, counted before the tree is built); InputError names the label otherwise.)")
      .def_property_readonly(
          "case", [](const Problem& p) { return p.read.spec.case_name; }, "The case name.")
      .def_property_readonly(
          "file", [](const Problem& p) { return p.read.spec.file; },
          "The file (or label) the problem was read from.")
      .def_property_readonly(
          "input", [](const Problem& p) { return p.read.effective_yaml; },
          "The effective input: the problem with overrides and defaults, as YAML (input.yaml).")
      .def("describe", &describe,
           R"(Discretises the problem without solving it (like `hpcontact check`): a dict with the
case, the method ("p" or "h"), the bodies (name, nodes, elements, edges), "dofs" (free unknowns)
and "dofs_condensed" (after condensing internal modes). For an adaptive run, of the first mesh.)")
      .def_property_readonly(
          "dofs", [](const Problem& p) { return describe(p)["dofs"].cast<int>(); },
          "Free unknowns of the (first) discretisation, as summary.json's \"dofs\".")
      .def("run", &run, py::arg("out") = py::none(), py::arg("quiet") = true, py::arg("verbose") = false,
           R"(Solves the problem and returns a Result.

out: None writes nothing; a folder (str or os.PathLike) gets the files of `hpcontact run --out` (summary.json,
contact.csv, pressure.csv, solution.vtu, input.yaml), as the command line writes them: they
replace the earlier run's files only when this run has succeeded, and the folder is refused
(Error) if it holds the problem or reference file, a file with an output name that hpcontact did
not write, or a link where an output goes, or if another run is writing into it (docs/input.md,
"The output folder"). quiet=False prints the progress lines (a line per load step, hp/rp step,
file written and message), verbose=True also Newton's iterations, as `hpcontact run -v`. Raises SolverError when the solution does not
converge (with out, the last converged step is kept in out/last-good/), InputError for input
found wrong only now (a reference curve), Error otherwise. Ctrl-C stops the run between steps.)")
      .def("__repr__", [](const Problem& p) {
        return "<hpcontact.Problem '" + p.read.spec.case_name + "' from " + p.read.spec.file + ">";
      });

  py::class_<Result>(m, "Result", "A converged run: its summary, fields at points and interface curves.")
      .def_property_readonly(
          "summary", [](const Result& r) { return to_python(post::to_json(r.run->summary)); },
          "summary.json's content as a dict (also when nothing was written).")
      .def_property_readonly(
          "out", [](const Result& r) { return r.out; }, "The output folder, or None.")
      .def(
          "displacement",
          [](const Result& r, const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
             const std::optional<std::string>& body) {
            return at_points(r, points, body, 2, [](const post::PointResult& pr) {
              return std::array<double, 2>{pr.u.x(), pr.u.y()};
            });
          },
          py::arg("points"), py::arg("body") = py::none(),
          R"(Displacements (ux, uy) at points of the undeformed bodies.

points: array of shape (n, 2) (or one point, shape (2,)); returns shape (n, 2) (or (2,)). A
point on an edge shared by two elements or bodies takes the first (bodies in input order);
body="name" searches that body only. Raises ValueError naming the first point outside.)")
      .def(
          "stress",
          [](const Result& r, const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
             const std::optional<std::string>& body) {
            return at_points(r, points, body, 4, [](const post::PointResult& pr) {
              return std::array<double, 4>{pr.stress(0), pr.stress(1), pr.stress(2), pr.stress_zz};
            });
          },
          py::arg("points"), py::arg("body") = py::none(),
          R"(Stresses (sxx, syy, sxy, szz) at points of the undeformed bodies.

Cauchy stresses under finite strain; szz is the stress normal to the plane (the hoop stress of
an axisymmetric body, x the radius; nu (sxx + syy) in linear
plane strain, 0 in plane stress).
points and body as for displacement(); returns shape (n, 4) (or (4,)).)")
      .def_property_readonly(
          "reactions", [](const Result& r) { return reactions_of(r, false); },
          R"(The reactions of the last converged step (summary.json's `reactions`), as numpy arrays:
body and constraint (lists: support i is bodies[body[i]].constraints[constraint[i]]), force
(n_supports, 2) what each constraint entry exerts on its body, moment (n_supports,) about the
origin (nan for an axisymmetric body), pair_force (n_pairs, 2) and pair_moment the contact force
on each pair's body, equilibrium_residual the largest relative imbalance of a body's forces.)")
      .def_property_readonly(
          "reaction_history", [](const Result& r) { return reactions_of(r, true); },
          R"(The same at every converged load step (the rows of path.csv; one for a linear solve,
the final mesh's last step for rp and hp): force (n_steps, n_supports, 2), moment (n_steps,
n_supports), pair_force (n_steps, n_pairs, 2), pair_moment, equilibrium_residual (n_steps,).)")
      .def_property_readonly(
          "load_history", &load_history_of,
          R"(The load path, path.csv's rows as numpy arrays (one entry per converged load step;
rp and hp: the final mesh's solve): step, displacement_factor (y's), displacement_factor_x,
displacement_factor_y, load_factor, iterations, arc_length, resultant_x and resultant_y (the
first contact pair's), monitor_ux and monitor_uy (zero without solver.monitor).)")
      .def_property_readonly(
          "contact_history", &contact_history_of,
          R"(contact_history.csv's rows as numpy arrays (one entry per converged step and contact
pair; an empty dict without contact or for rp and hp): step, pair, body (a list), the factors,
resultant_x, resultant_y, normal_force, tangential_force, contact_length, pressure_max,
traction_max, max_penetration, contact_points, stick_points, slip_points.)")
      .def("contact", &contact_table,
           R"(The interface curve: contact.csv's columns as numpy arrays, one entry per contact
Gauss point of every pair (the "pair" column says which): pair, X, Y (undeformed), x, y
(deformed), gap, pressure (penalty), pressure_from_stress, tangential_gap,
tangential_traction, slip (zero without friction) and state (str array: "open", "contact",
"stick", "slip"), body, s, traction, minus_sigma_nn, tangent_x, tangent_y (the tangent the
friction columns are signed along) and shear_from_stress. Arrays of length 0 when the problem
has no contact.)")
      .def("mesh", &mesh_of, py::arg("subdivisions") = 0,
           R"(The solution on the mesh, as solution.vtu holds it, as numpy arrays: each element
sampled on an (s+1) x (s+1) grid of its reference square (s = subdivisions; 0: the element's
degree, at least 2 and at most 16, as solution.vtu without output.vtu_subdivisions) and drawn as
linear quads. points (n, 2) undeformed positions, cells (m, 4) point indices counter-clockwise,
displacement (n, 2), strain (n, 3) xx, yy, gamma_xy (Green-Lagrange under finite strain),
stress (n, 4) xx, yy, xy, zz (Cauchy under finite strain; zz: out of plane, the hoop stress of an
axisymmetric body), von_mises, principal_1, principal_2 (n,), cell_body (index into body_names),
cell_element (the element's id in the input), cell_degree (m,); with a mixed (u-p) rubber body
pressure_mixed (n,), its element pressure (0 on other bodies). A point on an edge between two
elements appears once per element. The deformed mesh is points + displacement; e.g. with
matplotlib: tripcolor or PolyCollection(points[cells] + displacement[cells]).

solution.vtu itself (and steps/step-NNNN.vtu) is an ASCII VTK unstructured grid that ParaView
opens and meshio reads (Debian's python3-meshio): mesh = meshio.read("out/solution.vtu");
mesh.points (n, 3), mesh.cells_dict["quad"], mesh.point_data["von_mises"], the same arrays.)")
      .def("pressure_curve", &pressure_curve,
           R"(pressure.csv's columns as numpy arrays, when the first contact pair has a compare
section (None otherwise): x (along the obstacle, on 1001 points of [0, 1.5 b] and the zone ends),
pressure_from_stress, pressure_penalty, hertz, shtayerman and, if the input names one,
reference. b and p0 are summary["contact"]["hertz_half_width"] and ["hertz_peak_pressure"].)")
      .def("__repr__", [](const Result& r) {
        const auto& s = r.run->summary;
        std::ostringstream os;
        os << "<hpcontact.Result '" << s.case_name << "': " << s.method << "-version, " << s.dofs
           << " dofs, strain energy " << s.strain_energy << ">";
        return os.str();
      });
}
