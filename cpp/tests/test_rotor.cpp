// Rotor FEM kernel tests: element matrix symmetry, rigid-body modes, pinned-pinned beam.
#include <Eigen/Eigenvalues>
#include <cmath>

#include "rotordyn/errors.hpp"
#include "rotordyn/modal.hpp"
#include "rotordyn/reduction.hpp"
#include "rotordyn/rotor.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
ShaftElement steel(double L, double d) {
  ShaftElement e;
  e.length = L;
  e.outer_diameter = d;
  e.density = 7850;
  e.young = 2.1e11;
  e.shear_modulus = 2.1e11 / 2.6;
  return e;
}
}  // namespace

TEST_CASE("element matrices: M, K symmetric, G skew-symmetric, M positive definite") {
  const ElementMatrices em = element_matrices(steel(0.1, 0.05));
  CHECK((em.M - em.M.transpose()).norm() < 1e-14 * em.M.norm());
  CHECK((em.K - em.K.transpose()).norm() < 1e-14 * em.K.norm());
  CHECK((em.G + em.G.transpose()).norm() < 1e-14 * em.G.norm());
  Eigen::SelfAdjointEigenSolver<Matrix8d> es(em.M);
  CHECK(es.eigenvalues().minCoeff() > 0);
}

TEST_CASE("element: rigid translation and rotation produce no elastic force") {
  const ElementMatrices em = element_matrices(steel(0.3, 0.04));
  Eigen::Matrix<double, 8, 1> t;
  t << 1, 0, 0, 0, 1, 0, 0, 0;  // x translation
  CHECK((em.K * t).norm() < 1e-6 * em.K.norm());
  // Rigid rotation about y: x = θ z, θy = θ.
  Eigen::Matrix<double, 8, 1> r;
  r << 0, 0, 0, 1, 0.3, 0, 0, 1;
  CHECK((em.K * r).norm() < 1e-6 * em.K.norm());
  // Rigid rotation about x: y = -θ z, θx = θ.
  Eigen::Matrix<double, 8, 1> s;
  s << 0, 0, 1, 0, 0, -0.3, 1, 0;
  CHECK((em.K * s).norm() < 1e-6 * em.K.norm());
  // A rigid translation carries the element mass ρ A L.
  const ShaftElement e = steel(0.3, 0.04);
  CHECK_CLOSE(t.transpose() * em.M * t, e.density * e.area() * e.length, 1e-12, 0);
}

TEST_CASE("pinned-pinned Euler-Bernoulli beam: first frequency within 0.1%") {
  RotorModel m;
  const int ne = 40;
  for (int i = 0; i < ne; ++i) {
    ShaftElement e = steel(1.0 / ne, 0.02);
    e.shear = false;
    e.rotary_inertia = false;
    m.elements.push_back(e);
  }
  m.rigid_nodes = {0, ne};
  const ConstrainedRotor c = constrain(m);
  const ModalResult r = modal(c.M, c.C, c.K, c.xy, 4);
  const ShaftElement& e = m.elements[0];
  const double w1 = M_PI * M_PI * std::sqrt(e.young * e.second_moment() / (e.density * e.area()));
  CHECK_CLOSE(r.eigenvalues(0).imag(), w1, 1e-3, 0);
  CHECK_CLOSE(r.eigenvalues(1).imag(), w1, 1e-3, 0);  // the other plane
}

TEST_CASE("guyan with all DOFs as masters is the identity; bad masters raise InputError") {
  Eigen::MatrixXd K(2, 2), M(2, 2);
  K << 2, -1, -1, 2;
  M << 1, 0, 0, 1;
  const Reduction r = guyan(M, K, {0, 1});
  CHECK((r.K - K).norm() < 1e-14);
  CHECK_THROWS(guyan(M, K, {0, 5}), InputError);
  CHECK_THROWS(guyan(M, K, {0, 0}), InputError);
}

TEST_CASE("validate names the field of a negative length") {
  RotorModel m;
  ShaftElement e = steel(-1.0, 0.02);
  m.elements.push_back(e);
  bool ok = false;
  try {
    m.validate();
  } catch (const InputError& ex) {
    ok = std::string(ex.what()).find("elements[0].length") != std::string::npos;
  }
  CHECK(ok);
}

TEST_CASE("proportional damping: C = α M + β K of the elements, none from disks or at 0") {
  RotorModel m;
  for (int i = 0; i < 3; ++i) m.elements.push_back(steel(0.2, 0.04));
  m.disks.push_back(Disk{1, 5.0, 0.01, 0.005});
  const RotorMatrices undamped = assemble(m);
  CHECK(undamped.C.nonZeros() == 0);  // α = β = 0 adds no entry
  for (auto& e : m.elements) {
    e.damping_alpha = 4.0;
    e.damping_beta = 3e-5;
  }
  const RotorMatrices d = assemble(m);
  m.disks.clear();
  const RotorMatrices shaft = assemble(m);
  const Eigen::MatrixXd expected =
      4.0 * Eigen::MatrixXd(shaft.M) + 3e-5 * Eigen::MatrixXd(shaft.K);
  CHECK((Eigen::MatrixXd(d.C) - expected).norm() < 1e-14 * expected.norm());
  m.elements[1].damping_beta = -1.0;
  bool ok = false;
  try {
    m.validate();
  } catch (const InputError& ex) {
    ok = std::string(ex.what()).find("elements[1].damping_beta") != std::string::npos;
  }
  CHECK(ok);
}
