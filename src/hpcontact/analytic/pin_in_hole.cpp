// Persson's problem by a Chebyshev collocation of its gap equation, with Michell's compliances.
//
// Derivation (scripts/pin_in_hole_reference.py checks each step symbolically or numerically):
//
// 1. Gap. With the pin's centre moved by δ towards θ = 0, the radial gap on the circle r = R1 is,
//    to first order in ΔR/R1 (Persson 1964; Johnson, Contact Mechanics §5.6),
//      g(θ) = ΔR − δ cos θ + u_r,plate(θ) − u_r,pin(θ)  >= 0,  = 0 where p(θ) > 0.       (G1)
//    With p(θ) = p_0 + Σ_n p_n cos nθ (p symmetric), each mode moves the surfaces apart by
//    Λ_n p_n cos nθ. The cos θ parts of u_r (n = 1, also a rigid translation's) add to δ, which is
//    unknown, and p_1 is fixed by the force: P = ∫ p cos θ R1 dθ = π R1 p_1. So
//      g(θ) = ΔR − δ cos θ + (1/π) ∫ p(φ) K(θ − φ) dφ,  K(x) = Λ_0/2 + Σ_{n>=2} Λ_n cos nx. (G2)
//
// 2. Compliances (Michell's Airy functions r^m cos nθ, m = ±n, 2 ± n; G shear modulus,
//    κ = 3 − 4ν in plane strain, (3 − ν)/(1 + ν) in plane stress; pressure positive inwards on
//    the pin, outwards on the plate):
//      disc  (pin):    u_r = −(R p_n / 4G1) [1/(n − 1) + κ1/(n + 1)],  n >= 2;
//                      u_r = −(κ1 − 1) R p_0 / (4G1)                   (Lamé)
//      hole (plate):   u_r =  (R p_n / 4G2) [κ2/(n − 1) + 1/(n + 1)],  n >= 2;
//                      u_r =  R p_0 / (2G2)                            (Lamé)
//    so that, with 2/E* = (κ1 + 1)/(4G1) + (κ2 + 1)/(4G2) and Dundurs' β,
//      Λ_n = (2R/E*) (n + β)/(n² − 1),  n >= 2;   Λ_0 = R [1/(2G2) + (κ1 − 1)/(4G1)].   (C1)
//    (Λ_0 = R/E* for elastically similar bodies.) A finite plate held at R_out, or a pin held on a
//    rigid core r_c, changes Λ_n by ΔΛ_n = O((R/R_out)^(2n−2)) and O((r_c/R)^(2n)): annulus
//    solutions, a 4×4 system per mode (2×2 for n = 0).
//
// 3. Kernel in closed form. From Σ_{m>=1} e^{imx}/m = −ln(1 − e^{ix}) and (C1), for 0 < |x| < 2π,
//      Σ_{n>=2} Λ_n^∞ cos nx = (2R/E*) [ −cos x ln|2 sin(x/2)| + (β/2)(x sin x − π sin|x|)
//                                         − ((1 − β)/2)(1 + cos(x)/2) ].                (K1)
//    The logarithm is the half-plane's (Λ_n ~ 2R/(E* n)); the rest is the curvature's.
//
// 4. Map to a straight crack. With s = tan(θ/2), t = tan(φ/2), b = tan(ε/2), x = s/b, y = t/b,
//      ln|2 sin((θ − φ)/2)| = ln|x − y| + ln(2b) − ½ ln(1 + s²) − ½ ln(1 + t²),          (M1)
//    and cos(θ − φ) = cos θ cos φ + sin θ sin φ, sin|θ − φ| = sign(x − y)(sin θ cos φ − cos θ sin φ).
//    The pressure density in y is written with the bounded (vanishing) end behaviour of a smooth
//    contact, q(y) = p dφ/dy = sqrt(1 − y²) Σ_k a_k U_2k(y), and then, exactly,
//      ∫ ln|x − y| sqrt(1 − y²) U_j(y) dy = π [T_{j+2}(x)/(2(j + 2)) − T_j(x)/(2j)],  j >= 1,
//                                         = π [T_2(x)/4 − ln(2)/2],                  j = 0,  (M2)
//      ∫_{−1}^{x} sqrt(1 − y²) U_j(y) dy = −½ [sin(jχ)/j − sin((j + 2)χ)/(j + 2)],  j >= 1,
//                                         = ½ [π − χ + sin(2χ)/2],               j = 0,  (M3)
//    with x = cos χ. The smooth factors cos φ, sin φ are taken into the U_j series by a discrete
//    sine transform in y = cos ψ; the smooth rest of K by Gauss–Chebyshev quadrature of the second
//    kind. Collocating g = 0 at N + 1 Chebyshev points of [0, 1) gives a_k and δ (δ absorbs
//    whatever multiplies cos θ); P = R1 ∫ q cos φ dy. All of it is linear in ΔR.
//
// Accuracy: for β = 0 the solution is analytic in y and the error is at round-off (1e-12 in P,
// checked against N = 80, M = 1200); for β != 0 the sign kernel gives the pressure weak
// singularities at the ends of the arc, and the error falls as N^−4 (about 1e-8 here).
//
// The body-force load: a uniform body force b = P/(π R1²) on the disc, balanced by the pressure
// (P/(π R1)) cos θ, has the particular solution u = (c x², 0), c = −b(κ − 1)/(2G(κ + 1)), whose
// rim traction and radial displacement hold modes 1 and 3 only; the mode-3 parts cancel against
// Michell's r³, r⁵ correction (u_r,3 = 0 exactly), so the rim moves by a multiple of cos θ, which
// (G2) absorbs: the contact is that of a force at the centre.
#include "hpcontact/analytic/pin_in_hole.hpp"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <numbers>

#include "hpcontact/core/error.hpp"

namespace hpcontact::analytic {

namespace {
constexpr double pi = std::numbers::pi;
constexpr int n_coefficients = 40;  ///< N: a_k, k < N (the even U_2k)
constexpr int n_nodes = 320;        ///< M: quadrature and sine-transform points

struct Elastic {
  double shear_modulus, kappa;
};

Elastic elastic(double E, double nu, bool plane_strain) {
  return {E / (2 * (1 + nu)), plane_strain ? 3 - 4 * nu : (3 - nu) / (1 + nu)};
}
Elastic pin_elastic(const PinInHole& q) {
  return elastic(q.pin_youngs_modulus, q.pin_poisson_ratio, q.plane_strain);
}
Elastic plate_elastic(const PinInHole& q) {
  return elastic(q.plate_youngs_modulus, q.plate_poisson_ratio, q.plane_strain);
}

void check(const PinInHole& q) {
  HPC_REQUIRE(q.pin_radius > 0 && q.hole_radius > q.pin_radius, InputError,
              "pin in hole: needs 0 < pin radius < hole radius (got ", q.pin_radius, " and ",
              q.hole_radius, ")");
  HPC_REQUIRE(q.plate_outer_radius > q.hole_radius, InputError,
              "pin in hole: the plate's outer radius must exceed the hole's (got ",
              q.plate_outer_radius, " <= ", q.hole_radius, ")");
  HPC_REQUIRE(q.pin_core_radius >= 0 && q.pin_core_radius < q.pin_radius, InputError,
              "pin in hole: needs 0 <= pin core radius < pin radius (got ", q.pin_core_radius, ")");
  HPC_REQUIRE(q.pin_youngs_modulus > 0 && q.plate_youngs_modulus > 0, InputError,
              "pin in hole: Young's moduli must be > 0 (got ", q.pin_youngs_modulus, ", ",
              q.plate_youngs_modulus, ")");
}

/// The stresses σ_rr, σ_rθ and displacements U, V (u_r = U cos nθ, u_θ = V sin nθ) of the Airy
/// function φ = s² (r/s)^m cos nθ, n >= 2, m != 1; from σ_rr = φ_r/r + φ_θθ/r², σ_θθ = φ_rr,
/// σ_rθ = −(φ_θ/r)_r and 8G ε_rr = (κ+1)σ_rr − (3−κ)σ_θθ, 8G ε_θθ = (κ+1)σ_θθ − (3−κ)σ_rr:
///   σ_rr = (m − n²) ρ^(m−2),  σ_rθ = n(m − 1) ρ^(m−2),  ρ = r/s,
///   U = s [(κ+1)(m − n²) − (3−κ) m(m − 1)] ρ^(m−1) / (8G (m − 1)),
///   V = s {[(κ+1) m(m − 1) − (3−κ)(m − n²)] ρ^(m−1) / (8G) − U/s} / n.
std::array<double, 4> michell_term(int m, int n, double r, double s, Elastic e) {
  const double rho = r / s, G = e.shear_modulus, k = e.kappa;
  const double srr = (m - n * n) * std::pow(rho, m - 2);
  const double srt = n * (m - 1.0) * std::pow(rho, m - 2);
  const double U = ((k + 1) * (m - n * n) - (3 - k) * m * (m - 1.0)) /
                   (8 * G * (m - 1.0)) * std::pow(rho, m - 1);
  const double V = (((k + 1) * m * (m - 1.0) - (3 - k) * (m - n * n)) * std::pow(rho, m - 1) /
                        (8 * G) - U) / n;
  return {srr, srt, s * U, s * V};
}

/// The annulus a <= r <= c under the pressure cos nθ on one circle (σ_rr = −cos nθ, σ_rθ = 0)
/// and held (u = 0) on the other: the loaded circle's radial displacement away from the
/// material (outwards when the inner circle is loaded, inwards when the outer is). The growing
/// terms r^n, r^(n+2) are scaled by c and the decaying r^−n, r^(2−n) by a, so that the system
/// stays well conditioned for large n and c/a.
double annulus_compliance(int n, double a, double c, Elastic e, bool inner_loaded) {
  const double r_load = inner_loaded ? a : c, r_held = inner_loaded ? c : a;
  const std::array<int, 4> m = {n, n + 2, -n, 2 - n};
  const std::array<double, 4> s = {c, c, a, a};
  Eigen::Matrix4d A;
  Eigen::Vector4d u_load;
  for (int j = 0; j < 4; ++j) {
    const auto load = michell_term(m[j], n, r_load, s[j], e);
    const auto held = michell_term(m[j], n, r_held, s[j], e);
    A.col(j) << load[0], load[1], held[2], held[3];
    u_load(j) = load[2];
  }
  const Eigen::Vector4d x = A.partialPivLu().solve(Eigen::Vector4d(-1, 0, 0, 0));
  return (inner_loaded ? 1 : -1) * u_load.dot(x);
}

/// The n = 0 counterpart (Lamé: σ_rr = A − B/r², u_r = [(κ−1)/2 A r + B/r] / (2G)).
double annulus_compliance_uniform(double a, double c, Elastic e, bool inner_loaded) {
  const double r_load = inner_loaded ? a : c, r_held = inner_loaded ? c : a;
  const double k = (e.kappa - 1) / 2;
  Eigen::Matrix2d A;
  A << 1, -1 / (r_load * r_load), k * r_held, 1 / r_held;
  const Eigen::Vector2d x = A.partialPivLu().solve(Eigen::Vector2d(-1, 0));
  const double u = (k * x(0) * r_load + x(1) / r_load) / (2 * e.shear_modulus);
  return inner_loaded ? u : -u;
}

/// The infinite plate's and the solid disc's compliances (C1), per body.
double hole_compliance(int n, double R, Elastic e) {
  if (n == 0) return R / (2 * e.shear_modulus);
  return R / (4 * e.shear_modulus) * (e.kappa / (n - 1.0) + 1 / (n + 1.0));
}
double disc_compliance(int n, double R, Elastic e) {
  if (n == 0) return (e.kappa - 1) * R / (4 * e.shear_modulus);
  return R / (4 * e.shear_modulus) * (1 / (n - 1.0) + e.kappa / (n + 1.0));
}

/// Λ_n of the plate and of the pin as the problem has them.
double plate_compliance(const PinInHole& q, int n) {
  const double R = q.pin_radius;
  if (std::isinf(q.plate_outer_radius)) return hole_compliance(n, R, plate_elastic(q));
  return n == 0 ? annulus_compliance_uniform(R, q.plate_outer_radius, plate_elastic(q), true)
                : annulus_compliance(n, R, q.plate_outer_radius, plate_elastic(q), true);
}
double pin_compliance(const PinInHole& q, int n) {
  const double R = q.pin_radius;
  if (q.pin_core_radius == 0) return disc_compliance(n, R, pin_elastic(q));
  return n == 0 ? annulus_compliance_uniform(q.pin_core_radius, R, pin_elastic(q), false)
                : annulus_compliance(n, q.pin_core_radius, R, pin_elastic(q), false);
}

/// The kernel K of (G2) but for its logarithm and sign terms, which are integrated exactly:
///   K_reg(x) = (2R/E*)[(β/2) x sin x − ((1 − β)/2)(1 + cos(x)/2)] + Λ_0/2 + Σ ΔΛ_n cos nx,
/// ΔΛ_n = Λ_n − Λ_n^∞ the finite plate's and the core's change of the modes n >= 2.
struct RegularKernel {
  double scale, beta, half_uniform;
  std::vector<double> mode_changes;  ///< ΔΛ_n at n = 2, 3, ...

  explicit RegularKernel(const PinInHole& q)
      : scale(2 * q.pin_radius / pin_in_hole_modulus(q)),
        beta(pin_in_hole_dundurs_beta(q)),
        half_uniform(0.5 * pin_in_hole_gap_compliance(q, 0)) {
    if (std::isinf(q.plate_outer_radius) && q.pin_core_radius == 0) return;
    for (int n = 2; n < 2000; ++n) {
      const double change =
          pin_in_hole_gap_compliance(q, n) - scale * (n + beta) / (n * n - 1.0);
      mode_changes.push_back(change);
      if (std::abs(change) < 1e-17 * scale) break;
    }
  }
  double operator()(double x) const {
    double k = scale * (0.5 * beta * x * std::sin(x) - 0.5 * (1 - beta) * (1 + 0.5 * std::cos(x))) +
               half_uniform;
    for (size_t i = 0; i < mode_changes.size(); ++i) k += mode_changes[i] * std::cos((i + 2.0) * x);
    return k;
  }
};

/// sin((j + 1) ψ_m), ψ_m = mπ/(M + 1), m = 1..M: the discrete sine transform's matrix.
const Eigen::MatrixXd& sine_table() {
  static const Eigen::MatrixXd S = [] {
    Eigen::MatrixXd s(n_nodes, n_nodes);
    for (int j = 0; j < n_nodes; ++j)
      for (int m = 0; m < n_nodes; ++m) s(j, m) = std::sin((j + 1) * (m + 1) * pi / (n_nodes + 1));
    return s;
  }();
  return S;
}

/// The collocation solution for ΔR = 1: the coefficients a_k (then δ last).
Eigen::VectorXd solve_unit_clearance(const PinInHole& q, double eps) {
  const int N = n_coefficients, M = n_nodes, n_points = N + 1;
  const double b = std::tan(eps / 2);
  const RegularKernel K_reg(q);
  const double log_scale = K_reg.scale, beta = K_reg.beta;
  const Eigen::MatrixXd& S = sine_table();

  // Nodes y_m = cos ψ_m; ∫ sqrt(1 − y²) f(y) dy ≈ Σ w_m f(y_m), w_m = π/(M+1) sin² ψ_m.
  Eigen::VectorXd psi(M), w(M), phi(M);
  for (int m = 0; m < M; ++m) {
    psi(m) = (m + 1) * pi / (M + 1);
    w(m) = pi / (M + 1) * std::pow(std::sin(psi(m)), 2);
    phi(m) = 2 * std::atan(b * std::cos(psi(m)));
  }
  // Collocation points x_i in (0, 1), Chebyshev points of the even functions' half interval.
  Eigen::VectorXd x(n_points), chi(n_points), theta(n_points);
  for (int i = 0; i < n_points; ++i) {
    chi(i) = (2 * i + 1) * pi / (4 * n_points);
    x(i) = std::cos(chi(i));
    theta(i) = 2 * std::atan(b * x(i));
  }
  Eigen::MatrixXd regular(n_points, M);  // w_m K_reg(θ_i − φ_m)
  for (int i = 0; i < n_points; ++i)
    for (int m = 0; m < M; ++m) regular(i, m) = w(m) * K_reg(theta(i) - phi(m));
  // (M2) and (M3) at the collocation points, row j = U_j.
  Eigen::MatrixXd log_table(M, n_points), cumulative(M, n_points);
  for (int i = 0; i < n_points; ++i) {
    auto T = [&](int j) { return std::cos(j * chi(i)); };
    log_table(0, i) = pi * (T(2) / 4 - std::log(2.0) / 2);
    cumulative(0, i) = 0.5 * (pi - chi(i) + std::sin(2 * chi(i)) / 2);
    for (int j = 1; j < M; ++j) {
      log_table(j, i) = pi * (T(j + 2) / (2.0 * (j + 2)) - T(j) / (2.0 * j));
      cumulative(j, i) = -0.5 * (std::sin(j * chi(i)) / j - std::sin((j + 2) * chi(i)) / (j + 2));
    }
  }

  Eigen::MatrixXd A(n_points, N + 1);
  for (int k = 0; k < N; ++k) {
    // sqrt(1 − y²) U_2k(y) = sin((2k + 1) ψ) at the nodes, times cos φ and sin φ: their U_j
    // series by the sine transform c_j = 2/(M+1) Σ_m f(ψ_m) sin((j + 1) ψ_m).
    Eigen::VectorXd U(M), f_cos(M), f_sin(M);
    for (int m = 0; m < M; ++m) {
      U(m) = std::sin((2 * k + 1) * psi(m)) / std::sin(psi(m));
      f_cos(m) = std::sin((2 * k + 1) * psi(m)) * std::cos(phi(m));
      f_sin(m) = std::sin((2 * k + 1) * psi(m)) * std::sin(phi(m));
    }
    const Eigen::VectorXd c_cos = 2.0 / (M + 1) * (S * f_cos);
    const Eigen::VectorXd c_sin = 2.0 / (M + 1) * (S * f_sin);
    // ∫ q_k cos φ dy and ∫ q_k cos φ ln cos(φ/2) dy; the sin φ ones vanish (odd integrands).
    double C = 0, C_log = 0;
    for (int m = 0; m < M; ++m) {
      C += w(m) * U(m) * std::cos(phi(m));
      C_log += w(m) * U(m) * std::cos(phi(m)) * std::log(std::cos(phi(m) / 2));
    }
    const Eigen::VectorXd log_cos = log_table.transpose() * c_cos;
    const Eigen::VectorXd log_sin = log_table.transpose() * c_sin;
    // ∫ sign(x − y) f dy = 2 ∫_{−1}^{x} f dy − ∫ f dy; ∫ f dy = (π/2) c_0.
    const Eigen::VectorXd sign_cos =
        2 * (cumulative.transpose() * c_cos).array() - 0.5 * pi * c_cos(0);
    const Eigen::VectorXd sign_sin =
        2 * (cumulative.transpose() * c_sin).array() - 0.5 * pi * c_sin(0);
    const Eigen::VectorXd regular_part = regular * U;
    for (int i = 0; i < n_points; ++i) {
      const double ct = std::cos(theta(i)), st = std::sin(theta(i));
      const double s = b * x(i), log_const = std::log(2 * b) - 0.5 * std::log1p(s * s);
      // −cos(θ−φ) ln|2 sin((θ−φ)/2)| by (M1), (M2); −(πβ/2) sin|θ−φ| by (M3).
      double g = -ct * (log_cos(i) + log_const * C + C_log) - st * log_sin(i) -
                 0.5 * pi * beta * (st * sign_cos(i) - ct * sign_sin(i));
      A(i, k) = (log_scale * g + regular_part(i)) / pi;
    }
  }
  for (int i = 0; i < n_points; ++i) A(i, N) = -std::cos(theta(i));
  return A.partialPivLu().solve(Eigen::VectorXd::Constant(n_points, -1.0));
}

/// P for ΔR = 1 from the coefficients: P = R1 ∫ q(y) cos φ(y) dy.
double unit_force(const PinInHole& q, double eps, const Eigen::VectorXd& a) {
  const int M = n_nodes;
  const double b = std::tan(eps / 2);
  double P = 0;
  for (int m = 0; m < M; ++m) {
    const double psi = (m + 1) * pi / (M + 1), w = pi / (M + 1) * std::pow(std::sin(psi), 2);
    const double c = std::cos(2 * std::atan(b * std::cos(psi)));
    double q_over_weight = 0;
    for (int k = 0; k < n_coefficients; ++k)
      q_over_weight += a(k) * std::sin((2 * k + 1) * psi) / std::sin(psi);
    P += w * q_over_weight * c;
  }
  return q.pin_radius * P;
}
}  // namespace

double pin_in_hole_modulus(const PinInHole& q) {
  const Elastic e1 = pin_elastic(q), e2 = plate_elastic(q);
  return 1 / ((e1.kappa + 1) / (8 * e1.shear_modulus) + (e2.kappa + 1) / (8 * e2.shear_modulus));
}

double pin_in_hole_dundurs_beta(const PinInHole& q) {
  const Elastic e1 = pin_elastic(q), e2 = plate_elastic(q);
  const double G1 = e1.shear_modulus, G2 = e2.shear_modulus;
  return (G1 * (e2.kappa - 1) - G2 * (e1.kappa - 1)) /
         (G1 * (e2.kappa + 1) + G2 * (e1.kappa + 1));
}

double pin_in_hole_gap_compliance(const PinInHole& q, int n) {
  check(q);
  HPC_ASSERT(n == 0 || n >= 2, "pin_in_hole_gap_compliance: n = ", n, " (1 is not defined)");
  return plate_compliance(q, n) + pin_compliance(q, n);
}

PinInHoleContact::PinInHoleContact(const PinInHole& problem, double half_angle)
    : problem_(problem), half_angle_(half_angle) {
  check(problem);
  HPC_REQUIRE(half_angle > 0 && half_angle < pi, InputError,
              "pin in hole: the half-angle must be in (0, π) (got ", half_angle, ")");
  const double clearance = problem.hole_radius - problem.pin_radius;
  const Eigen::VectorXd a = solve_unit_clearance(problem, half_angle);
  force_ = clearance * unit_force(problem, half_angle, a);
  for (int k = 0; k < n_coefficients; ++k) coefficients_.push_back(clearance * a(k));
}

double PinInHoleContact::pressure(double theta) const {
  const double b = std::tan(half_angle_ / 2);
  if (std::abs(theta) >= half_angle_) return 0.0;
  const double s = std::tan(theta / 2), psi = std::acos(s / b);
  // p = q dy/dθ, dy/dθ = (1 + s²)/(2b); q = Σ a_k sin((2k + 1) ψ), y = cos ψ.
  double q = 0;
  for (size_t k = 0; k < coefficients_.size(); ++k) q += coefficients_[k] * std::sin((2 * k + 1) * psi);
  return q * (1 + s * s) / (2 * b);
}

double pin_in_hole_force(const PinInHole& problem, double half_angle) {
  return PinInHoleContact(problem, half_angle).force();
}

double pin_in_hole_limit_half_angle(const PinInHole& problem) {
  check(problem);
  // ΔR/P(ε) is smooth and falls through 0 at the pole of P(ε): bracket it, then bisect.
  auto inverse = [&](double eps) { return 1 / pin_in_hole_force(problem, eps); };
  double lo = 1.0, hi = lo;
  while (inverse(hi) > 0) {
    lo = hi;
    hi += 0.05;
    HPC_REQUIRE(hi < 3.0, InputError, "pin in hole: no limit half-angle below 172° was found");
  }
  while (hi - lo > 1e-13) {
    const double mid = 0.5 * (lo + hi);
    (inverse(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

PinInHoleContact PinInHoleContact::at_force(const PinInHole& problem, double force) {
  check(problem);
  HPC_REQUIRE(force > 0, InputError, "pin in hole: the force must be > 0 (got ", force, ")");
  // ln P(ε) rises monotonically from −∞ (ε -> 0) to +∞ (the limit angle); beyond the pole P < 0.
  // Regula falsi on ln P − ln P_target (Illinois), falling back to bisection while an end of
  // the bracket lies past the pole.
  auto residual = [&](double eps) {
    const double P = pin_in_hole_force(problem, eps);
    return P > 0 ? std::log(P / force) : std::numeric_limits<double>::infinity();
  };
  const PinInHole& q = problem;
  const double E_star = pin_in_hole_modulus(q), clearance = q.hole_radius - q.pin_radius;
  // Start from the Hertz angle sqrt(4P/(π E* ΔR)), which is too large (the conforming contact
  // is narrower); halve the lower end until below.
  double hi = std::min(std::sqrt(4 * force / (pi * E_star * clearance)), 3.0);
  double f_hi = residual(hi);
  double lo = 0.5 * hi, f_lo = residual(lo);
  while (f_lo > 0) {
    hi = lo, f_hi = f_lo;
    lo *= 0.5;
    f_lo = residual(lo);
  }
  while (f_hi < 0) {  // below the target: move up towards the pole
    lo = hi, f_lo = f_hi;
    hi = std::min(hi + 0.1, 0.5 * (hi + pi));
    f_hi = residual(hi);
  }
  int side = 0;
  for (int it = 0; it < 200 && hi - lo > 1e-14 * hi; ++it) {
    const double mid = std::isfinite(f_hi) ? (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
                                           : 0.5 * (lo + hi);
    const double f = residual(mid);
    if (f == 0) return PinInHoleContact(problem, mid);
    if (f < 0) {
      lo = mid, f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = mid, f_hi = f;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
    if (std::abs(f) < 1e-15) return PinInHoleContact(problem, mid);
  }
  return PinInHoleContact(problem, 0.5 * (lo + hi));
}

double pin_in_hole_half_angle(const PinInHole& problem, double force) {
  return PinInHoleContact::at_force(problem, force).half_angle();
}

}  // namespace hpcontact::analytic
