#include "rotordyn/sleeve.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "rotordyn/errors.hpp"
#include "rotordyn/reduction.hpp"

namespace rotordyn {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr int kGauss = 16;

// 16-point Gauss-Legendre rule on [-1, 1] (Newton on P_16, Golub-Welsch accuracy ~1e-16). The
// integrands (products of trigonometric functions of the angle and, for the mass, of their
// integrals) are entire; on an element of at most π the rule is exact to rounding.
struct GaussRule {
  std::array<double, kGauss> x{}, w{};
  GaussRule() {
    const int n = kGauss;
    for (int i = 0; i < n; ++i) {
      double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
      double dp = 1.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-16) break;
      }
      x[i] = z;
      w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};
const GaussRule& gauss() {
  static const GaussRule g;
  return g;
}

std::string num(double v) {
  std::ostringstream os;
  os.precision(10);
  os << v;
  return os.str();
}

void require_finite_positive(double v, const std::string& field) {
  require(std::isfinite(v) && v > 0.0, field + ": expected a finite value > 0, got " + num(v));
}

// Angle in [0, 2π).
double wrap(double a) {
  double r = std::fmod(a, kTwoPi);
  if (r < 0) r += kTwoPi;
  if (r >= kTwoPi) r -= kTwoPi;
  return r;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
CurvedBeamProperties curved_beam_properties(const CurvedBeamSection& s) {
  require_finite_positive(s.thickness, "section.thickness");
  require_finite_positive(s.width, "section.width");
  require_finite_positive(s.young, "section.young");
  require_finite_positive(s.density, "section.density");
  require(std::isfinite(s.poisson) && s.poisson > -1.0 && s.poisson < 0.5,
          "section.poisson: expected a value in (-1, 0.5), got " + num(s.poisson));
  require(std::isfinite(s.options.shear_coefficient) && s.options.shear_coefficient <= 2.0,
          "section.options.shear_coefficient: expected a value in (0, 2] (or <= 0 for "
          "Cowper's value), got " + num(s.options.shear_coefficient));
  const double nu = s.poisson;
  const double E = s.options.plane_strain ? s.young / (1.0 - nu * nu) : s.young;
  const double G = s.young / (2.0 * (1.0 + nu));
  const double A = s.width * s.thickness;
  const double I = s.width * s.thickness * s.thickness * s.thickness / 12.0;
  const double kappa = s.options.shear_coefficient > 0.0 ? s.options.shear_coefficient
                                                         : 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
  CurvedBeamProperties p;
  p.compliance_bending = 1.0 / (E * I);
  p.compliance_axial = s.options.extension ? 1.0 / (E * A) : 0.0;
  p.compliance_shear = s.options.shear ? 1.0 / (kappa * G * A) : 0.0;
  p.mass = s.density * A;
  p.rotary = s.options.rotary_inertia ? s.density * I : 0.0;
  return p;
}

// ---------------------------------------------------------------------------------------------
CurvedBeamElement::CurvedBeamElement(double radius, double theta_a, double theta_b,
                                     const CurvedBeamProperties& p)
    : R_(radius), ta_(theta_a), tb_(theta_b), p_(p) {
  require_finite_positive(radius, "element.radius");
  require(std::isfinite(theta_a) && std::isfinite(theta_b) && theta_b > theta_a &&
              theta_b - theta_a <= kPi * (1.0 + 1e-12),
          "element: expected theta_a < theta_b <= theta_a + pi, got theta_a = " + num(theta_a) +
              ", theta_b = " + num(theta_b));
  require(p.compliance_bending > 0 && p.mass > 0 && p.compliance_axial >= 0 &&
              p.compliance_shear >= 0 && p.rotary >= 0,
          "element: expected 1/EI > 0, rhoA > 0 and non-negative 1/EA, 1/kGA, rhoI");
  F_ = coupling(tb_, tb_);
  F_ = 0.5 * (F_ + F_.transpose());
  Eigen::LDLT<Eigen::Matrix3d> f(F_);
  K22_ = f.solve(Eigen::Matrix3d::Identity());
  K22_ = 0.5 * (K22_ + K22_.transpose());
  B_.leftCols<3>() = -rigid(tb_);
  B_.rightCols<3>().setIdentity();
  K_ = B_.transpose() * K22_ * B_;
  K_ = 0.5 * (K_ + K_.transpose());

  // Consistent mass from the exact static displacement field.
  const GaussRule& g = gauss();
  const double half = 0.5 * (tb_ - ta_);
  const Eigen::Vector3d dens(p_.mass, p_.mass, p_.rotary);
  M_.setZero();
  for (int q = 0; q < kGauss; ++q) {
    const double th = ta_ + half * (g.x[q] + 1.0);
    const Matrix36d N = shape(th);
    M_.noalias() += (g.w[q] * half * R_) * N.transpose() * dens.asDiagonal() * N;
  }
  M_ = 0.5 * (M_ + M_.transpose());
}

// Internal forces (N, V, M: columns) at the section ψ due to a unit load (rows: P_x, P_y, M_z)
// applied at angle θ ≥ ψ, acting on the part between ψ and θ.
Eigen::Matrix3d CurvedBeamElement::internal(double psi, double theta) const {
  const double c = std::cos(psi), s = std::sin(psi);
  const double dx = R_ * (std::cos(theta) - c), dy = R_ * (std::sin(theta) - s);
  Eigen::Matrix3d A;
  A << -s, c, -dy,  //
      c, s, dx,     //
      0, 0, 1;
  return A;
}

// Castigliano: displacement (x, y, v) at θ1 due to unit loads at θ2, node a clamped.
Eigen::Matrix3d CurvedBeamElement::coupling(double t1, double t2) const {
  const double up = std::min(t1, t2);
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  if (up <= ta_) return C;
  const GaussRule& g = gauss();
  const double half = 0.5 * (up - ta_);
  const Eigen::Vector3d comp(p_.compliance_axial, p_.compliance_shear, p_.compliance_bending);
  for (int q = 0; q < kGauss; ++q) {
    const double psi = ta_ + half * (g.x[q] + 1.0);
    const Eigen::Matrix3d A1 = internal(psi, t1), A2 = internal(psi, t2);
    C.noalias() += (g.w[q] * half * R_) * A1 * comp.asDiagonal() * A2.transpose();
  }
  return C;
}

// Rigid motion of node a carried to the point at θ.
Eigen::Matrix3d CurvedBeamElement::rigid(double theta_p) const {
  const double dx = R_ * (std::cos(theta_p) - std::cos(ta_));
  const double dy = R_ * (std::sin(theta_p) - std::sin(ta_));
  Eigen::Matrix3d T;
  T << 1, 0, -dy,  //
      0, 1, dx,    //
      0, 0, 1;
  return T;
}

Matrix36d CurvedBeamElement::shape(double theta) const {
  require(theta >= ta_ - 1e-12 && theta <= tb_ + 1e-12,
          "shape: theta " + num(theta) + " outside the element [" + num(ta_) + ", " + num(tb_) +
              "]");
  const double t = std::clamp(theta, ta_, tb_);
  Matrix36d N;
  N.leftCols<3>() = rigid(t);
  N.rightCols<3>().setZero();
  N.noalias() += coupling(t, tb_) * K22_ * B_;
  return N;
}

Matrix6d CurvedBeamElement::to_local() const {
  Matrix6d Q = Matrix6d::Zero();
  const double th[2] = {ta_, tb_};
  for (int k = 0; k < 2; ++k) {
    const double c = std::cos(th[k]), s = std::sin(th[k]);
    Q.block<3, 3>(3 * k, 3 * k) << -s, c, 0,  //
        c, s, 0,                              //
        0, 0, 1;
  }
  return Q;
}
Matrix6d CurvedBeamElement::K_local() const {
  const Matrix6d Q = to_local();
  return Q * K_ * Q.transpose();
}
Matrix6d CurvedBeamElement::M_local() const {
  const Matrix6d Q = to_local();
  return Q * M_ * Q.transpose();
}

// ---------------------------------------------------------------------------------------------
namespace {
void assemble(CurvedBeamMesh& mesh) {
  const Eigen::Index n = 3 * static_cast<Eigen::Index>(mesh.node_angles.size());
  mesh.M = Eigen::MatrixXd::Zero(n, n);
  mesh.K = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
    const auto& el = mesh.elements[e];
    int dof[6];
    for (int k = 0; k < 2; ++k)
      for (int i = 0; i < 3; ++i) dof[3 * k + i] = 3 * mesh.element_nodes[e][k] + i;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) {
        mesh.M(dof[i], dof[j]) += el.M()(i, j);
        mesh.K(dof[i], dof[j]) += el.K()(i, j);
      }
  }
}
}  // namespace

CurvedBeamMesh curved_arc(double radius, double theta_start, double arc, int n_elements,
                          const CurvedBeamSection& section) {
  require_finite_positive(radius, "radius");
  require(std::isfinite(theta_start), "theta_start: expected a finite angle, got " +
                                          num(theta_start));
  require(std::isfinite(arc) && arc > 0.0 && arc <= kTwoPi * (1.0 + 1e-12),
          "arc: expected a value in (0, 2*pi] rad, got " + num(arc));
  require(n_elements >= 1 && n_elements <= 100000,
          "n_elements: expected an integer in [1, 100000], got " + std::to_string(n_elements));
  require(arc / n_elements <= kPi * (1.0 + 1e-12),
          "n_elements: each element must span at most 180 deg; use at least " +
              std::to_string(static_cast<int>(std::ceil(arc / kPi))) + " elements");
  require(section.thickness < radius,
          "section.thickness: expected a value in (0, radius = " + num(radius) + "), got " +
              num(section.thickness));
  const CurvedBeamProperties p = curved_beam_properties(section);
  CurvedBeamMesh mesh;
  mesh.radius = radius;
  for (int k = 0; k <= n_elements; ++k)
    mesh.node_angles.push_back(theta_start + arc * static_cast<double>(k) / n_elements);
  for (int e = 0; e < n_elements; ++e) {
    mesh.elements.emplace_back(radius, mesh.node_angles[e], mesh.node_angles[e + 1], p);
    mesh.element_nodes.push_back({e, e + 1});
  }
  assemble(mesh);
  return mesh;
}

CurvedBeamMesh closed_ring(double radius, int n_elements, const CurvedBeamSection& section) {
  require(n_elements >= 3 && n_elements <= 100000,
          "n_elements: expected an integer in [3, 100000] for a closed ring, got " +
              std::to_string(n_elements));
  require_finite_positive(radius, "radius");
  require(section.thickness < radius,
          "section.thickness: expected a value in (0, radius = " + num(radius) + "), got " +
              num(section.thickness));
  const CurvedBeamProperties p = curved_beam_properties(section);
  CurvedBeamMesh mesh;
  mesh.radius = radius;
  for (int k = 0; k < n_elements; ++k)
    mesh.node_angles.push_back(kTwoPi * static_cast<double>(k) / n_elements);
  for (int e = 0; e < n_elements; ++e) {
    const double ta = kTwoPi * static_cast<double>(e) / n_elements;
    const double tb = kTwoPi * static_cast<double>(e + 1) / n_elements;
    // Global Cartesian DOFs make the closing element consistent: its node b (θ = 2π) is
    // node 0, at the same place with the same DOF directions.
    mesh.elements.emplace_back(radius, ta, tb, p);
    mesh.element_nodes.push_back({e, (e + 1) % n_elements});
  }
  assemble(mesh);
  return mesh;
}

Eigen::VectorXd natural_frequencies_hz(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K) {
  const Eigen::Index n = K.rows();
  require(K.cols() == n, shape_msg("K", n, n, K.rows(), K.cols()));
  require(M.rows() == n && M.cols() == n, shape_msg("M", n, n, M.rows(), M.cols()));
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> es(K, M, Eigen::EigenvaluesOnly);
  require(es.info() == Eigen::Success,
          "M: expected a symmetric positive-definite mass matrix (generalized eigen-solve "
          "failed)");
  Eigen::VectorXd f(n);
  for (Eigen::Index i = 0; i < n; ++i)
    f(i) = std::sqrt(std::max(es.eigenvalues()(i), 0.0)) / kTwoPi;
  return f;
}

// ---------------------------------------------------------------------------------------------
namespace {
void validate(const SleeveModel& m) {
  const SleeveGeometry& g = m.geometry;
  require_finite_positive(g.radius, "sleeve.radius");
  require(std::isfinite(g.arc) && g.arc > 0.0 && g.arc <= kTwoPi * (1.0 + 1e-12),
          "sleeve.arc: expected a value in (0, 2*pi] rad (0 to 360 deg), got " + num(g.arc));
  require(std::isfinite(g.clamp_angle),
          "sleeve.clamp_angle: expected a finite angle, got " + num(g.clamp_angle));
  require_finite_positive(m.section.thickness, "sleeve.thickness");
  require(m.section.thickness < g.radius,
          "sleeve.thickness: expected a value in (0, radius = " + num(g.radius) + "), got " +
              num(m.section.thickness));
  require(m.n_elements >= 2 && m.n_elements <= 10000,
          "sleeve.n_elements: expected an integer in [2, 10000], got " +
              std::to_string(m.n_elements));
  require(g.arc / m.n_elements <= kPi * (1.0 + 1e-12),
          "sleeve.n_elements: each element must span at most 180 deg");
  require(!m.master_nodes.empty() &&
              static_cast<int>(m.master_nodes.size()) <= 2 * m.n_elements,
          "sleeve.master_nodes: expected 1 to 2*n_elements stations, got " +
              std::to_string(m.master_nodes.size()));
  for (std::size_t i = 0; i < m.master_nodes.size(); ++i) {
    const int k = m.master_nodes[i];
    require(k >= 1 && k <= m.n_elements,
            "sleeve.master_nodes[" + std::to_string(i) + "]: expected a node in [1, " +
                std::to_string(m.n_elements) + "] (0 is the clamp), got " + std::to_string(k));
    // The message names the previous node, so it is built only when there is one (i > 0):
    // an eagerly built message read master_nodes[-1] on every condensation (ASan, issue 13).
    if (i > 0 && k <= m.master_nodes[i - 1])
      throw InputError("sleeve.master_nodes: expected strictly increasing node numbers, got " +
                       std::to_string(m.master_nodes[i - 1]) + " before " + std::to_string(k));
  }
}
}  // namespace

SleeveCondensation condense_sleeve(const SleeveModel& model) {
  validate(model);
  SleeveCondensation c;
  c.model = model;
  const int n = model.n_elements;
  c.mesh = curved_arc(model.geometry.radius, model.geometry.clamp_angle, model.geometry.arc, n,
                      model.section);
  // Clamp node 0: keep DOFs 3 … 3n+2.
  c.M_full = c.mesh.M.bottomRightCorner(3 * n, 3 * n);
  c.K_full = c.mesh.K.bottomRightCorner(3 * n, 3 * n);

  // Step 1: eliminate the rotations (masters x_g, y_g of every free node).
  std::vector<int> m1;
  for (int k = 0; k < n; ++k) {
    m1.push_back(3 * k);
    m1.push_back(3 * k + 1);
  }
  const Reduction r1 = guyan(c.M_full, c.K_full, m1);
  c.M_xy = r1.M;
  c.K_xy = r1.K;

  // Step 2: polar coordinates at each node, (x, y) = −r e_n + t e_t (r inward).
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for (int k = 0; k < n; ++k) {
    const double th = c.mesh.node_angles[k + 1];
    P(2 * k, 2 * k) = -std::cos(th);
    P(2 * k + 1, 2 * k) = -std::sin(th);
    P(2 * k, 2 * k + 1) = -std::sin(th);
    P(2 * k + 1, 2 * k + 1) = std::cos(th);
  }
  c.M_rt = P.transpose() * c.M_xy * P;
  c.K_rt = P.transpose() * c.K_xy * P;
  c.M_rt = 0.5 * (c.M_rt + c.M_rt.transpose());
  c.K_rt = 0.5 * (c.K_rt + c.K_rt.transpose());

  // Step 3: condense to the radial coordinates of the master stations.
  std::vector<int> m3;
  for (int k : model.master_nodes) m3.push_back(2 * (k - 1));
  const Reduction r3 = guyan(c.M_rt, c.K_rt, m3);
  c.Ms = 0.5 * (r3.M + r3.M.transpose());
  c.Ks = 0.5 * (r3.K + r3.K.transpose());
  c.T = r1.T * P * r3.T;

  c.freq_full_hz = natural_frequencies_hz(c.M_full, c.K_full);
  c.freq_xy_hz = natural_frequencies_hz(c.M_xy, c.K_xy);
  c.freq_condensed_hz = natural_frequencies_hz(c.Ms, c.Ks);
  c.master_angles.resize(static_cast<Eigen::Index>(model.master_nodes.size()));
  for (std::size_t i = 0; i < model.master_nodes.size(); ++i)
    c.master_angles(static_cast<Eigen::Index>(i)) = c.mesh.node_angles[model.master_nodes[i]];
  return c;
}

Eigen::MatrixXd SleeveCondensation::expand(const Eigen::MatrixXd& r_s) const {
  require(r_s.rows() == T.cols(), shape_msg("r_s", T.cols(), r_s.cols(), r_s.rows(), r_s.cols()));
  return T * r_s;
}

namespace {
// Row (1, 3n) over the full DOFs: inward radial displacement of the centre line at the arc
// position `rel` (angle from the clamp), from element e's exact shape functions.
Eigen::RowVectorXd radial_row_full(const SleeveCondensation& c, int e, double rel) {
  const CurvedBeamElement& el = c.mesh.elements[static_cast<std::size_t>(e)];
  const double th = std::clamp(c.model.geometry.clamp_angle + rel, el.theta_a(), el.theta_b());
  Eigen::RowVector3d er;
  er << -std::cos(th), -std::sin(th), 0.0;
  const Eigen::Matrix<double, 1, 6> re = er * el.shape(th);
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(3 * c.model.n_elements);
  for (int k = 0; k < 2; ++k) {
    const int node = e + k;
    if (node == 0) continue;  // clamped
    row.segment<3>(3 * (node - 1)) += re.segment<3>(3 * k);
  }
  return row;
}
}  // namespace

Eigen::MatrixXd SleeveCondensation::interpolation_full(const Eigen::VectorXd& phi) const {
  const double arc = model.geometry.arc;
  const int n = model.n_elements;
  const double h = arc / n;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(phi.size(), 3 * n);
  for (Eigen::Index k = 0; k < phi.size(); ++k) {
    require(std::isfinite(phi(k)), "phi[" + std::to_string(k) + "]: expected a finite angle");
    double rel = wrap(phi(k) - model.geometry.clamp_angle);
    if (rel > kTwoPi - 1e-12) rel = 0.0;       // rounding just below the clamp
    if (rel > arc + 1e-12 * kTwoPi) continue;  // outside the sleeve: rigid bush, w = 0
    rel = std::min(rel, arc);
    const int e = std::clamp(static_cast<int>(std::floor(rel / h)), 0, n - 1);
    W.row(k) = radial_row_full(*this, e, rel);
  }
  return W;
}

Eigen::MatrixXd SleeveCondensation::interpolation(const Eigen::VectorXd& phi) const {
  return interpolation_full(phi) * T;
}

Eigen::VectorXd SleeveCondensation::chamber_load_full(double phi_start, double phi_end) const {
  const double arc = model.geometry.arc;
  require(std::isfinite(phi_start) && std::isfinite(phi_end),
          "chamber: expected finite start and end angles");
  const double span = phi_end - phi_start;
  require(span > 0.0 && span <= arc * (1.0 + 1e-12),
          "chamber: expected 0 < phi_end - phi_start <= sleeve arc = " + num(arc) +
              " rad, got " + num(span));
  double rs = wrap(phi_start - model.geometry.clamp_angle);
  if (rs > kTwoPi - 1e-12) rs = 0.0;
  const double re = rs + span;
  require(re <= arc * (1.0 + 1e-12),
          "chamber: expected the chamber arc [phi_start, phi_end] inside the sleeve arc [" +
              num(model.geometry.clamp_angle) + ", " + num(model.geometry.clamp_angle + arc) +
              "] (mod 2*pi) rad, got [" + num(phi_start) + ", " + num(phi_end) + "]");
  const double outer = model.geometry.radius + 0.5 * model.section.thickness;
  const int n = model.n_elements;
  const double h = arc / n;
  const GaussRule& g = gauss();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(3 * n);
  for (int e = 0; e < n; ++e) {
    const double a = std::max(rs, e * h), b = std::min(std::min(re, arc), (e + 1) * h);
    if (b <= a) continue;
    const double half = 0.5 * (b - a);
    // Element e explicitly (a point may sit on a node; the field is continuous there).
    for (int q = 0; q < kGauss; ++q)
      f.noalias() += (g.w[q] * half * outer * model.section.width) *
                     radial_row_full(*this, e, a + half * (g.x[q] + 1.0)).transpose();
  }
  return f;
}

Eigen::VectorXd SleeveCondensation::chamber_load(double phi_start, double phi_end) const {
  return T.transpose() * chamber_load_full(phi_start, phi_end);
}

}  // namespace rotordyn
