// Threshold of instability along one sweep line in one call (see threshold.hpp).
#include "rotordyn/threshold.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <exception>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "brent_detail.hpp"
#include "rotordyn/errors.hpp"
#include "rotordyn/modal.hpp"

namespace rotordyn {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The Python loop's exception classes, named in the crossing's message.
struct ArithmeticFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

using brent_detail::brent;
using brent_detail::ValueFailure;

std::string named(const std::exception& ex) {
  const char* cls = dynamic_cast<const ArithmeticFailure*>(&ex)  ? "ArithmeticError"
                    : dynamic_cast<const ValueFailure*>(&ex)     ? "ValueError"
                    : dynamic_cast<const InputError*>(&ex)       ? "InputError"
                    : dynamic_cast<const ConvergenceError*>(&ex) ? "ConvergenceError"
                    : dynamic_cast<const ContactError*>(&ex)     ? "ContactError"
                    : dynamic_cast<const SundialsError*>(&ex)    ? "SundialsError"
                                                                 : "RuntimeError";
  return std::string(cls) + ": " + ex.what();
}

struct Point {
  double y = kNaN, f = kNaN;
  std::string status;  ///< the equilibrium's
  Eigen::VectorXd r;  ///< empty: no converged equilibrium
  Eigen::VectorXcd lam;      ///< every eigenvalue (ModalResult's order)
  std::vector<int> whirl;    ///< per eigenvalue: -1, 0, 1
  std::vector<double> share;  ///< per eigenvalue: the sleeve's kinetic-energy share (0: none)
  std::vector<double> pad_share;  ///< per eigenvalue: the tilting pads' share (0: none)
  bool stable = false;  ///< the verdict: every counted root's Re λ below the round-off band
  /// The bracket's and Brent's function: y where the verdict is unstable or y < 0, else
  /// −kRoundOffRel·max(|λ|, 1) of the deciding root (a stable point's y in the band is
  /// round-off of 0, never a sign): its sign is the verdict's, and it is never 0.
  double g = kNaN;
};

// max Re λ of eq. 19 at one operating point (the sweep's rule: every mode, the sleeve's own
// left out with exclude_sleeve), from r0.
Point max_real(SystemSolver& s, const ThresholdLineInput& in, double omega, double pc,
               const Eigen::VectorXd& a, const Eigen::VectorXd& r0) {
  const SystemModel& m = s.model();
  const Eigen::Index n = m.n();
  const EquilibriumResult e = s.equilibrium(omega, pc, a, r0, in.options);
  Point p;
  p.status = e.status;
  if (e.status != "ok" && e.status != "contact") return p;
  const Linearization lin = s.linearize(e.r, Eigen::VectorXd::Zero(n), omega);
  const Eigen::MatrixXd M = m.has_table_mass() ? m.mass_at(omega) : m.M;
  const Eigen::MatrixXd D = m.C + omega * m.G + lin.DH;
  const Eigen::MatrixXd K = m.K + lin.KH;
  if (!K.allFinite() || !D.allFinite())
    throw ArithmeticFailure("non-finite bearing coefficients");
  const ModalResult mr = modal(M, D, K, in.xy_pairs, static_cast<int>(n), true, in.rot_pairs);
  if (!mr.eigenvalues.allFinite()) throw ArithmeticFailure("non-finite eigenvalues");
  Eigen::Index best = -1;
  const Eigen::Index ke = mr.eigenvalues.size();
  p.share.assign(static_cast<std::size_t>(ke), 0.0);
  p.pad_share.assign(static_cast<std::size_t>(ke), 0.0);
  p.whirl.resize(static_cast<std::size_t>(ke));
  std::vector<char> counted(static_cast<std::size_t>(ke), 0);
  // a mode's kinetic energy on the coordinates idx over its whole kinetic energy
  auto kinetic_share = [&](Eigen::Index j, const std::vector<int>& idx) {
    const Eigen::VectorXcd phi = mr.modes.col(j);
    const double kin = (phi.adjoint() * M * phi).real()(0, 0);
    double part = 0.0;
    for (int i : idx)
      for (int k : idx) part += (std::conj(phi[i]) * M(i, k) * phi[k]).real();
    return kin > 0 ? part / kin : 0.0;
  };
  for (Eigen::Index j = 0; j < ke; ++j) {
    p.whirl[static_cast<std::size_t>(j)] = static_cast<int>(mr.whirl[static_cast<std::size_t>(j)]);
    if (!in.pads.empty())  // the "pad" kind: the pads' kinetic share
      p.pad_share[static_cast<std::size_t>(j)] = kinetic_share(j, in.pads);
    if (!in.sleeve.empty()) {  // stability_batch's kind rule: the sleeve's kinetic share
      const double ks = kinetic_share(j, in.sleeve);
      p.share[static_cast<std::size_t>(j)] = ks;
      if (in.exclude_sleeve && ks > 0.5) continue;  // a sleeve mode
    }
    counted[static_cast<std::size_t>(j)] = 1;
    if (best < 0 || mr.eigenvalues[j].real() > mr.eigenvalues[best].real()) best = j;
  }
  if (best < 0) throw ValueFailure("attempt to get argmax of an empty sequence");
  p.stable = true;  // the one verdict rule (the round-off band, modal.hpp)
  for (Eigen::Index j = 0; j < ke; ++j)
    if (counted[static_cast<std::size_t>(j)] && settled_real(mr.eigenvalues[j]) > 0)
      p.stable = false;
  p.y = mr.eigenvalues[best].real();
  p.g = (!p.stable || p.y < 0) ? p.y
                               : -kRoundOffRel * std::max(std::abs(mr.eigenvalues[best]), 1.0);
  p.f = mr.eigenvalues[best].imag() / (2.0 * M_PI);
  p.r = e.r;
  p.lam = mr.eigenvalues;
  return p;
}


}  // namespace

ThresholdLineResult threshold_line(SystemSolver& solver, const ThresholdLineInput& in) {
  const Eigen::Index np = in.x.size();
  const Eigen::Index n = solver.model().n();
  if (in.omega.size() != np || in.pressure.size() != np || in.a.rows() != np ||
      in.a.cols() != n || static_cast<Eigen::Index>(in.valid.size()) != np)
    throw InputError("threshold_line: expected x, omega, pressure, valid of length n_pts and "
                     "a of shape (n_pts, n)");
  if (in.axis == ThresholdAxis::Config && (in.config_index < 0 || in.config_index >= n))
    throw InputError("threshold_line: config_index out of range");
  ThresholdLineResult out;
  out.y = Eigen::VectorXd::Constant(np, kNaN);
  out.freq = Eigen::VectorXd::Constant(np, kNaN);
  out.stable.assign(static_cast<std::size_t>(np), -1);
  std::vector<Eigen::VectorXd> rs(static_cast<std::size_t>(np));
  Eigen::VectorXd r0;
  int evals = 0;
  for (Eigen::Index i = 0; i < np; ++i) {
    Point p;
    if (in.valid[static_cast<std::size_t>(i)]) {
      try {
        p = max_real(solver, in, in.omega[i], in.pressure[i], in.a.row(i).transpose(), r0);
      } catch (const std::exception&) {
        p = Point();
      }
    }
    ++evals;
    r0 = p.r;
    out.y[i] = p.y;
    out.freq[i] = p.f;
    if (std::isfinite(p.y)) out.stable[static_cast<std::size_t>(i)] = p.stable ? 1 : 0;
    rs[static_cast<std::size_t>(i)] = p.r;
  }
  const double rtol = 4 * std::numeric_limits<double>::epsilon();
  for (Eigen::Index i = 0; i + 1 < np; ++i) {
    // a bracket: one end stable and the other unstable by the verdict (the band's rule; the
    // raw sign of max Re λ called a conservative rotor's round-off +1e-12 unstable)
    const int s0 = out.stable[static_cast<std::size_t>(i)];
    const int s1 = out.stable[static_cast<std::size_t>(i + 1)];
    if (s0 < 0 || s1 < 0 || s0 == s1) continue;
    const Eigen::VectorXd& start = rs[static_cast<std::size_t>(i)];
    // the operating point of x in this bracket: point i with the varied value replaced
    auto at = [&](double x, double& omega, double& pc, Eigen::VectorXd& a) {
      omega = in.omega[i];
      pc = in.pressure[i];
      a = in.a.row(i).transpose();
      if (in.axis == ThresholdAxis::Speed) omega = x * (2.0 * M_PI);
      else if (in.axis == ThresholdAxis::ChamberPressure) {
        if (!(x >= 0) || !std::isfinite(x))
          throw InputError("chamber_pressure_pa: expected a finite value >= 0");
        pc = x;
      } else a(in.config_index) = x;
    };
    auto g = [&](double x) {
      ++evals;
      double omega, pc;
      Eigen::VectorXd a;
      at(x, omega, pc, a);
      const Point p = max_real(solver, in, omega, pc, a, start);
      if (!std::isfinite(p.g)) throw ArithmeticFailure("no equilibrium inside the bracket");
      return p.g;
    };
    const double span = std::abs(in.x[i + 1] - in.x[i]);
    double x = kNaN, fr = kNaN;
    std::string status = "ok", msg;
    try {
      x = brent(g, in.x[i], in.x[i + 1], in.xtol_given ? in.xtol : span * 1e-8, rtol,
                in.max_iter);
      double omega, pc;
      Eigen::VectorXd a;
      at(x, omega, pc, a);
      fr = max_real(solver, in, omega, pc, a, start).f;
    } catch (const std::exception& ex) {
      x = kNaN;
      fr = kNaN;
      status = "error";
      msg = named(ex);
    }
    out.bracket.push_back(static_cast<int>(i));
    out.root.push_back(x);
    out.root_freq.push_back(fr);
    out.status.push_back(status);
    out.message.push_back(msg);
    out.evaluations.push_back(evals);
  }
  return out;
}

MaxRealBatchResult max_real_batch(SystemSolver& solver, const MaxRealBatchInput& in) {
  const Eigen::Index np = in.omega.size();
  const Eigen::Index n = solver.model().n();
  if (in.pressure.size() != np || in.a.rows() != np || in.a.cols() != n ||
      static_cast<Eigen::Index>(in.restart.size()) != np ||
      static_cast<Eigen::Index>(in.valid.size()) != np)
    throw InputError("max_real_batch: expected omega, pressure, restart, valid of length "
                     "n_pts and a of shape (n_pts, n)");
  if (in.r0.size() != 0 && in.r0.size() != n)
    throw InputError("max_real_batch: expected r0 of length 0 or n");
  const bool own = in.starts.rows() != 0 || in.starts.cols() != 0;
  if (own && (in.starts.rows() != np || in.starts.cols() != n))
    throw InputError("max_real_batch: expected starts of shape (0, 0) or (n_pts, n)");
  ThresholdLineInput rule;  // the scan's rule of max Re λ
  rule.options = in.options;
  rule.exclude_sleeve = in.exclude_sleeve;
  rule.xy_pairs = in.xy_pairs;
  rule.rot_pairs = in.rot_pairs;
  rule.sleeve = in.sleeve;
  rule.pads = in.pads;
  MaxRealBatchResult out;
  out.y = Eigen::VectorXd::Constant(np, kNaN);
  out.freq = Eigen::VectorXd::Constant(np, kNaN);
  out.status.assign(static_cast<std::size_t>(np), "invalid");
  out.message.assign(static_cast<std::size_t>(np), "");
  out.r = RowMatrixXd::Constant(np, n, kNaN);
  out.n_eig = Eigen::VectorXi::Zero(np);
  std::vector<Point> pts(static_cast<std::size_t>(np));
  Eigen::VectorXd prev = in.r0;
  for (Eigen::Index i = 0; i < np; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!in.valid[k]) {
      prev.resize(0);
      continue;
    }
    Eigen::VectorXd start = in.restart[k] ? Eigen::VectorXd() : prev;
    if (own && in.starts.row(i).allFinite()) start = in.starts.row(i).transpose();
    try {
      const Point p = max_real(solver, rule, in.omega[i], in.pressure[i],
                               in.a.row(i).transpose(), start);
      out.status[k] = p.status;
      out.y[i] = p.y;
      out.freq[i] = p.f;
      prev = p.r;
      if (p.r.size() == n) out.r.row(i) = p.r.transpose();
      out.n_eig[i] = static_cast<int>(p.lam.size());
      pts[k] = p;
    } catch (const std::exception& ex) {
      out.status[k] = "error";
      out.message[k] = named(ex);
      prev.resize(0);
    }
  }
  out.r_last = prev;
  // every point's eigenvalues, whirl, sleeve and pad shares (past n_eig: NaN, 0, NaN, NaN)
  const Eigen::Index k = np ? out.n_eig.maxCoeff() : 0;
  out.eigenvalues = Eigen::MatrixXcd::Constant(np, k, std::complex<double>(kNaN, kNaN));
  out.whirl = Eigen::MatrixXi::Zero(np, k);
  out.sleeve_share = RowMatrixXd::Constant(np, k, kNaN);
  out.pad_share = RowMatrixXd::Constant(np, k, kNaN);
  for (Eigen::Index i = 0; i < np; ++i) {
    const Point& p = pts[static_cast<std::size_t>(i)];
    for (Eigen::Index j = 0; j < p.lam.size(); ++j) {
      const auto u = static_cast<std::size_t>(j);
      out.eigenvalues(i, j) = p.lam[j];
      out.whirl(i, j) = p.whirl[u];
      out.sleeve_share(i, j) = p.share[u];
      out.pad_share(i, j) = p.pad_share[u];
    }
  }
  return out;
}

}  // namespace rotordyn
