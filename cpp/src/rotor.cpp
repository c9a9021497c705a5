#include "rotordyn/rotor.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rotordyn/errors.hpp"

namespace rotordyn {
namespace {
constexpr double kPi = 3.14159265358979323846;

std::string elem_field(std::size_t i, const char* f) {
  return "elements[" + std::to_string(i) + "]." + f;
}

using Matrix4d = Eigen::Matrix4d;

// One bending plane, DOF (w1, s1, w2, s2) with s = dw/dz-like section rotation.
void plane_matrices(const ShaftElement& e, Matrix4d& Mt, Matrix4d& Mr, Matrix4d& K) {
  const double L = e.length, A = e.area(), I = e.second_moment();
  const double ph = e.phi();
  const double d = 1.0 + ph;
  const double kf = e.young * I / (d * L * L * L);
  K << 12, 6 * L, -12, 6 * L,                                   //
      6 * L, (4 + ph) * L * L, -6 * L, (2 - ph) * L * L,        //
      -12, -6 * L, 12, -6 * L,                                  //
      6 * L, (2 - ph) * L * L, -6 * L, (4 + ph) * L * L;
  K *= kf;

  const double p2 = ph * ph;
  const double m1 = 13.0 / 35 + 7.0 * ph / 10 + p2 / 3;
  const double m2 = 11.0 / 210 + 11.0 * ph / 120 + p2 / 24;
  const double m3 = 9.0 / 70 + 3.0 * ph / 10 + p2 / 6;
  const double m4 = 13.0 / 420 + 3.0 * ph / 40 + p2 / 24;
  const double m5 = 1.0 / 105 + ph / 60 + p2 / 120;
  const double m6 = 1.0 / 140 + ph / 60 + p2 / 120;
  Mt << m1, m2 * L, m3, -m4 * L,                 //
      m2 * L, m5 * L * L, m4 * L, -m6 * L * L,   //
      m3, m4 * L, m1, -m2 * L,                   //
      -m4 * L, -m6 * L * L, -m2 * L, m5 * L * L;
  Mt *= e.density * A * L / (d * d);

  const double r1 = 6.0 / 5, r2 = 1.0 / 10 - ph / 2, r3 = 2.0 / 15 + ph / 6 + p2 / 3,
               r4 = -1.0 / 30 - ph / 6 + p2 / 6;
  Mr << r1, r2 * L, -r1, r2 * L,                 //
      r2 * L, r3 * L * L, -r2 * L, r4 * L * L,   //
      -r1, -r2 * L, r1, -r2 * L,                 //
      r2 * L, r4 * L * L, -r2 * L, r3 * L * L;
  Mr *= e.density * I / (L * d * d);
}
}  // namespace

double ShaftElement::area() const {
  return kPi / 4.0 * (outer_diameter * outer_diameter - inner_diameter * inner_diameter);
}
double ShaftElement::second_moment() const {
  const double o2 = outer_diameter * outer_diameter, i2 = inner_diameter * inner_diameter;
  return kPi / 64.0 * (o2 * o2 - i2 * i2);
}
double ShaftElement::kappa() const {
  if (shear_coefficient > 0) return shear_coefficient;
  // Cowper (1966) for a hollow circular section; m = di/do (m = 0: solid, 6(1+ν)/(7+6ν)).
  const double nu = young / (2.0 * shear_modulus) - 1.0;
  const double m = inner_diameter / outer_diameter, m2 = m * m, a = (1 + m2) * (1 + m2);
  return 6.0 * (1 + nu) * a / ((7 + 6 * nu) * a + (20 + 12 * nu) * m2);
}
double ShaftElement::phi() const {
  if (!shear) return 0.0;
  return 12.0 * young * second_moment() / (kappa() * shear_modulus * area() * length * length);
}

ElementMatrices element_matrices(const ShaftElement& e) {
  Matrix4d Mt, Mr, K;
  plane_matrices(e, Mt, Mr, K);
  if (!e.rotary_inertia) Mr.setZero();
  // Plane variables p = (x1, θy1, x2, θy2 | y1, s1, y2, s2) with s = -θx (slope dy/dz).
  // p = P d, d = (x1, y1, θx1, θy1, x2, y2, θx2, θy2).
  Matrix8d P = Matrix8d::Zero();
  P(0, 0) = 1;   // x1
  P(1, 3) = 1;   // θy1
  P(2, 4) = 1;   // x2
  P(3, 7) = 1;   // θy2
  P(4, 1) = 1;   // y1
  P(5, 2) = -1;  // s1 = -θx1
  P(6, 5) = 1;   // y2
  P(7, 6) = -1;  // s2 = -θx2
  Matrix8d Mp = Matrix8d::Zero(), Kp = Matrix8d::Zero(), Gp = Matrix8d::Zero();
  Mp.topLeftCorner<4, 4>() = Mt + Mr;
  Mp.bottomRightCorner<4, 4>() = Mt + Mr;
  Kp.topLeftCorner<4, 4>() = K;
  Kp.bottomRightCorner<4, 4>() = K;
  // Gyroscopic coupling of the planes: polar inertia per length 2ρI times the rotary shape
  // integral (Mr / ρI); rows xz get +, rows yz get - (see DESIGN: Id θ̈x + Ip Ω θ̇y = Mx).
  Gp.block<4, 4>(0, 4) = 2.0 * Mr;
  Gp.block<4, 4>(4, 0) = -2.0 * Mr;
  ElementMatrices out;
  out.M = P.transpose() * Mp * P;
  out.K = P.transpose() * Kp * P;
  out.G = P.transpose() * Gp * P;
  return out;
}

void RotorModel::validate() const {
  require(!elements.empty(), "elements: expected at least 1 shaft element, got 0");
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto& e = elements[i];
    auto pos = [&](double v, const char* f) {
      require(std::isfinite(v) && v > 0,
              elem_field(i, f) + ": expected a finite value > 0, got " + std::to_string(v));
    };
    pos(e.length, "length");
    pos(e.outer_diameter, "outer_diameter");
    pos(e.density, "density");
    pos(e.young, "young");
    pos(e.shear_modulus, "shear_modulus");
    auto nonneg = [&](double v, const char* f) {
      require(std::isfinite(v) && v >= 0,
              elem_field(i, f) + ": expected a finite value >= 0, got " + std::to_string(v));
    };
    nonneg(e.damping_alpha, "damping_alpha");
    nonneg(e.damping_beta, "damping_beta");
    require(std::isfinite(e.inner_diameter) && e.inner_diameter >= 0 &&
                e.inner_diameter < e.outer_diameter,
            elem_field(i, "inner_diameter") + ": expected 0 <= value < outer_diameter, got " +
                std::to_string(e.inner_diameter));
  }
  const int n = n_nodes();
  auto node_ok = [&](int node, const std::string& f) {
    require(node >= 0 && node < n, f + ": expected a node in [0, " + std::to_string(n - 1) +
                                       "], got " + std::to_string(node));
  };
  for (std::size_t i = 0; i < disks.size(); ++i) {
    const std::string f = "disks[" + std::to_string(i) + "]";
    node_ok(disks[i].node, f + ".node");
    require(disks[i].mass >= 0 && std::isfinite(disks[i].mass), f + ".mass: expected >= 0");
    require(disks[i].ip >= 0 && std::isfinite(disks[i].ip), f + ".ip: expected >= 0");
    require(disks[i].id >= 0 && std::isfinite(disks[i].id), f + ".id: expected >= 0");
  }
  for (std::size_t i = 0; i < supports.size(); ++i) {
    node_ok(supports[i].node, "supports[" + std::to_string(i) + "].node");
    require(supports[i].k.allFinite() && supports[i].c.allFinite(),
            "supports[" + std::to_string(i) + "]: coefficients must be finite");
  }
  for (std::size_t i = 0; i < rigid_nodes.size(); ++i)
    node_ok(rigid_nodes[i], "rigid_nodes[" + std::to_string(i) + "]");
}

RotorMatrices assemble(const RotorModel& model) {
  model.validate();
  const int n = model.n_dof();
  using T = Eigen::Triplet<double>;
  std::vector<T> tm, tk, tc, tg;
  tm.reserve(model.elements.size() * 64 + model.disks.size() * 4);
  tk.reserve(model.elements.size() * 64 + model.supports.size() * 4);
  tc.reserve(model.supports.size() * 4);
  tg.reserve(model.elements.size() * 64 + model.disks.size() * 2);
  for (std::size_t i = 0; i < model.elements.size(); ++i) {
    const ElementMatrices em = element_matrices(model.elements[i]);
    const int o = 4 * static_cast<int>(i);
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b) {
        if (em.M(a, b) != 0) tm.emplace_back(o + a, o + b, em.M(a, b));
        if (em.K(a, b) != 0) tk.emplace_back(o + a, o + b, em.K(a, b));
        if (em.G(a, b) != 0) tg.emplace_back(o + a, o + b, em.G(a, b));
      }
    // proportional material damping α M_e + β K_e (an undamped element adds no entry: C
    // stays the supports' alone, bit for bit)
    const double al = model.elements[i].damping_alpha, be = model.elements[i].damping_beta;
    if (al == 0.0 && be == 0.0) continue;
    const Matrix8d Ce = al * em.M + be * em.K;
    for (int a = 0; a < 8; ++a)
      for (int b = 0; b < 8; ++b)
        if (Ce(a, b) != 0) tc.emplace_back(o + a, o + b, Ce(a, b));
  }
  for (const auto& d : model.disks) {
    const int o = 4 * d.node;
    tm.emplace_back(o, o, d.mass);
    tm.emplace_back(o + 1, o + 1, d.mass);
    tm.emplace_back(o + 2, o + 2, d.id);
    tm.emplace_back(o + 3, o + 3, d.id);
    tg.emplace_back(o + 2, o + 3, d.ip);
    tg.emplace_back(o + 3, o + 2, -d.ip);
  }
  for (const auto& s : model.supports) {
    const int o = 4 * s.node;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        tk.emplace_back(o + a, o + b, s.k(a, b));
        tc.emplace_back(o + a, o + b, s.c(a, b));
      }
  }
  RotorMatrices out;
  out.M.resize(n, n);
  out.K.resize(n, n);
  out.C.resize(n, n);
  out.G.resize(n, n);
  out.M.setFromTriplets(tm.begin(), tm.end());
  out.K.setFromTriplets(tk.begin(), tk.end());
  out.C.setFromTriplets(tc.begin(), tc.end());
  out.G.setFromTriplets(tg.begin(), tg.end());
  return out;
}

std::vector<int> free_dofs(const RotorModel& model) {
  std::vector<char> fixed(static_cast<std::size_t>(model.n_dof()), 0);
  for (int node : model.rigid_nodes) {
    fixed[4 * node] = 1;
    fixed[4 * node + 1] = 1;
  }
  std::vector<int> out;
  for (int i = 0; i < model.n_dof(); ++i)
    if (!fixed[i]) out.push_back(i);
  return out;
}

double total_mass(const RotorModel& model) {
  double m = 0;
  for (const auto& e : model.elements) m += e.density * e.area() * e.length;
  for (const auto& d : model.disks) m += d.mass;
  return m;
}

}  // namespace rotordyn

namespace rotordyn {

int ConstrainedRotor::local(int full_dof) const {
  auto it = std::lower_bound(dofs.begin(), dofs.end(), full_dof);
  if (it == dofs.end() || *it != full_dof) return -1;
  return static_cast<int>(it - dofs.begin());
}

ConstrainedRotor constrain(const RotorModel& model) {
  const RotorMatrices mats = assemble(model);
  ConstrainedRotor out;
  out.dofs = free_dofs(model);
  const Eigen::Index n = static_cast<Eigen::Index>(out.dofs.size());
  const Eigen::MatrixXd M = Eigen::MatrixXd(mats.M), K = Eigen::MatrixXd(mats.K),
                        C = Eigen::MatrixXd(mats.C), G = Eigen::MatrixXd(mats.G);
  out.M.resize(n, n);
  out.K.resize(n, n);
  out.C.resize(n, n);
  out.G.resize(n, n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) {
      out.M(i, j) = M(out.dofs[i], out.dofs[j]);
      out.K(i, j) = K(out.dofs[i], out.dofs[j]);
      out.C(i, j) = C(out.dofs[i], out.dofs[j]);
      out.G(i, j) = G(out.dofs[i], out.dofs[j]);
    }
  for (int node = 0; node < model.n_nodes(); ++node) {
    const int ix = out.local(4 * node), iy = out.local(4 * node + 1);
    if (ix >= 0 && iy >= 0) out.xy.emplace_back(ix, iy);
    const int tx = out.local(4 * node + 2), ty = out.local(4 * node + 3);
    if (tx >= 0 && ty >= 0) out.rot.emplace_back(tx, ty);
  }
  return out;
}

}  // namespace rotordyn
