// Speed-dependent coefficient tables: interpolation of a table bearing (TableCoupling) and
// batches of operating points over speed (equilibrium + linearisation per speed, parallel).
#include "rotordyn/bearing_table.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <sstream>
#include <thread>

#include "rotordyn/errors.hpp"
#include "parallel_detail.hpp"

namespace rotordyn {

void TableCoupling::validate(const std::string& where, Eigen::Index n) const {
  const std::string w = where + " '" + name + "'";
  require(coords.size() == 2, w + ".coords: expected 2 indices (x, y), got " +
                                  std::to_string(coords.size()));
  for (int c : coords)
    require(c >= 0 && c < n, w + ".coords: expected indices in [0, " + std::to_string(n - 1) +
                                 "], got " + std::to_string(c));
  const Eigen::Index ns = omegas.size();
  require(ns >= 1, w + ".speeds: expected at least one speed");
  require(omegas.allFinite(), w + ".speeds: expected finite speeds");
  for (Eigen::Index i = 1; i < ns; ++i)
    require(omegas(i) > omegas(i - 1),
            w + ".speeds: expected strictly increasing speeds (row " + std::to_string(i) + ")");
  require(K.rows() == ns && K.cols() == 4, shape_msg(w + ".K", ns, 4, K.rows(), K.cols()));
  require(C.rows() == ns && C.cols() == 4, shape_msg(w + ".C", ns, 4, C.rows(), C.cols()));
  require(K.allFinite() && C.allFinite(), w + ": expected finite coefficients");
  require(M.size() == 0 || (M.rows() == ns && M.cols() == 4),
          shape_msg(w + ".M", ns, 4, M.rows(), M.cols()));
  require(M.allFinite(), w + ": expected finite mass coefficients");
}

void TableCoupling::at(double omega, Eigen::Matrix2d& Kout, Eigen::Matrix2d& Cout,
                       Eigen::Matrix2d* Mout) const {
  const Eigen::Index ns = omegas.size();
  auto fill = [&](Eigen::Index i, Eigen::Index j, double t) {
    for (int e = 0; e < 4; ++e) {
      Kout(e / 2, e % 2) = (1 - t) * K(i, e) + t * K(j, e);
      Cout(e / 2, e % 2) = (1 - t) * C(i, e) + t * C(j, e);
      if (Mout) (*Mout)(e / 2, e % 2) = M.size() ? (1 - t) * M(i, e) + t * M(j, e) : 0.0;
    }
  };
  if (ns == 1) {
    fill(0, 0, 0.0);
    return;
  }
  const double lo = omegas(0), hi = omegas(ns - 1);
  const double tol = 1e-12 * std::max(std::abs(lo), std::abs(hi));
  if (!(omega >= lo - tol && omega <= hi + tol) && !extrapolate) {
    std::ostringstream os;
    os << "bearing '" << name << "': speed " << omega / (2 * M_PI) << " Hz is outside its table ["
       << lo / (2 * M_PI) << ", " << hi / (2 * M_PI)
       << "] Hz (extend the table or set extrapolate = true)";
    throw InputError(os.str());
  }
  // interval i: omegas(i) <= omega < omegas(i+1), clamped to the end intervals
  const double* b = omegas.data();
  Eigen::Index i = std::upper_bound(b, b + ns, omega) - b - 1;
  i = std::clamp<Eigen::Index>(i, 0, ns - 2);
  const double t = (omega - omegas(i)) / (omegas(i + 1) - omegas(i));
  fill(i, i + 1, t);
}

namespace {
// homotopy_start, adding every stage's Reynolds solves to `solves`
Eigen::VectorXd counted_homotopy_start(const SystemModel& model, double omega, double pc,
                                       const Eigen::VectorXd& a, const Eigen::VectorXd& r0,
                                       const EquilibriumOptions& options,
                                       const Eigen::MatrixXd& P, long& solves) {
  const Eigen::Index n = model.n();
  require(P.rows() == n && P.cols() == n, shape_msg("pad_penalty", n, n, P.rows(), P.cols()));
  Eigen::VectorXd r = r0.size() ? r0 : Eigen::VectorXd::Zero(n);
  double kappa0 = 0.0;
  {
    SystemSolver s(model);
    Eigen::VectorXd start = r;
    try {
      const Linearization lin = s.linearize(start, Eigen::VectorXd::Zero(n), omega);
      kappa0 = 100.0 * lin.KH.diagonal().cwiseAbs().maxCoeff();
      solves += s.reynolds_solves();
    } catch (const std::exception&) {
      return r;
    }
  }
  if (!(kappa0 > 0) || !std::isfinite(kappa0)) return r;
  const double pmax = P.diagonal().maxCoeff();
  if (!(pmax > 0)) return r;
  // κ = κ_0·10^{−t}, t from 0 to 10 (below the softest pad's own film stiffness) in steps of
  // one decade, halved (down to 1/16) where a stage fails and doubled again after a success.
  double t = 0.0, dt = 1.0;
  bool first = true;
  // Work budget: the fallback runs only where the pad assembly failed, typically for a load
  // the bearing cannot carry (e.g. two narrow pads under a side load), where every failed
  // stage ends in the equilibrium's whole load continuation: the failed stages' Reynolds
  // solves are capped (a hopeless case cost ~10^5 solves, ~10 s, before the cap).
  long wasted = 0;
  while (t < 10.0 && wasted < kHomotopyMaxSolves) {
    const double next = first ? 0.0 : std::min(10.0, t + dt);
    SystemModel m = model;
    m.K += (kappa0 * std::pow(10.0, -next) / pmax) * P;
    SystemSolver s(std::move(m));
    const EquilibriumResult e = s.equilibrium(omega, pc, a, r, options);
    solves += e.reynolds_solves;
    if (e.status != "ok") wasted += e.reynolds_solves;
    if (e.status == "ok") {
      r = e.r;
      t = next;
      first = false;
      dt = std::min(1.0, 2.0 * dt);
    } else if (first || dt <= 1.0 / 16) {
      break;
    } else {
      dt *= 0.5;
    }
  }
  return r;
}
}  // namespace

Eigen::VectorXd homotopy_start(const SystemModel& model, double omega, double pc,
                               const Eigen::VectorXd& a, const Eigen::VectorXd& r0,
                               const EquilibriumOptions& options,
                               const Eigen::MatrixXd& P) {
  long solves = 0;
  return counted_homotopy_start(model, omega, pc, a, r0, options, P, solves);
}

EquilibriumResult pad_system_equilibrium(SystemSolver& solver, const SystemModel& model,
                                         double omega, double pc, const Eigen::VectorXd& a,
                                         const Eigen::VectorXd& r0,
                                         const Eigen::VectorXd& homotopy_r0,
                                         const EquilibriumOptions& options,
                                         const Eigen::MatrixXd& P) {
  EquilibriumResult e = solver.equilibrium(omega, pc, a, r0, options);
  if (P.size() == 0) return e;
  const bool converged = e.status == "ok" || e.status == "contact";
  if (converged && e.path == "pad_assembly") return e;
  // not through the pad assembly: a plain Newton may sit on an unloaded pad's pressure-free
  // branch, so the homotopy decides; a converged first answer stays if the homotopy fails
  long solves = 0;
  const Eigen::VectorXd start =
      counted_homotopy_start(model, omega, pc, a, homotopy_r0, options, P, solves);
  EquilibriumResult h = solver.equilibrium(omega, pc, a, start, options);
  h.path = "homotopy";
  // the call's whole work: the first attempt, the homotopy's stages and the answer's Newton
  const long total = e.reynolds_solves + solves + h.reynolds_solves;
  EquilibriumResult& out = converged && h.status != "ok" && h.status != "contact" ? e : h;
  out.reynolds_solves = total;
  return out;
}

OperatingPointTable operating_points(const SystemModel& model, const Eigen::VectorXd& omegas,
                                     const Eigen::VectorXd& a, const Eigen::VectorXd& r0,
                                     const EquilibriumOptions& options, int n_threads,
                                     const Eigen::MatrixXd& pad_penalty) {
  model.validate();
  const Eigen::Index n = model.n(), ns = omegas.size();
  require(omegas.allFinite(), "speeds: expected finite values");
  OperatingPointTable out;
  out.r = RowMatrixXd::Constant(ns, n, NAN);
  out.force = RowMatrixXd::Constant(ns, n, NAN);
  out.KH = RowMatrixXd::Constant(ns, n * n, NAN);
  out.DH = RowMatrixXd::Constant(ns, n * n, NAN);
  out.status.assign(static_cast<std::size_t>(ns), "error");
  out.message.assign(static_cast<std::size_t>(ns), "");
  out.iterations = Eigen::VectorXi::Zero(ns);
  out.reynolds_solves = Eigen::VectorXi::Zero(ns);
  out.path.assign(static_cast<std::size_t>(ns), "");
  if (n_threads <= 0) n_threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  n_threads = static_cast<int>(std::min<Eigen::Index>(n_threads, std::max<Eigen::Index>(ns, 1)));

  auto work = [&](Eigen::Index begin, Eigen::Index end) {
    SystemSolver solver(model);
    for (Eigen::Index i = begin; i < end; ++i) {
      const auto si = static_cast<std::size_t>(i);
      try {
        // With pads the equilibrium starts from the pad assembly (pad_equilibrium.cpp); the
        // tilt homotopy is the fallback when that path fails.
        const EquilibriumResult e =
            pad_system_equilibrium(solver, model, omegas(i), 0.0, a, r0, r0, options, pad_penalty);
        out.path[si] = e.path;
        out.reynolds_solves(i) = e.reynolds_solves;
        out.r.row(i) = e.r.transpose();
        out.iterations(i) = e.iterations;
        out.status[si] = e.status;
        out.message[si] = e.message;
        // A converged equilibrium (ok, or contact: converged with a thin film) is linearised
        // as in every system analysis; a failed one never is.
        if (e.status != "ok" && e.status != "contact") continue;
        const Linearization lin = solver.linearize(e.r, Eigen::VectorXd::Zero(n), omegas(i));
        if (!lin.KH.allFinite() || !lin.DH.allFinite()) {
          out.status[si] = "error";
          out.message[si] = "non-finite film coefficients";
          continue;
        }
        out.force.row(i) = lin.film_force.transpose();
        for (Eigen::Index p = 0; p < n; ++p)
          for (Eigen::Index q = 0; q < n; ++q) {
            out.KH(i, p * n + q) = lin.KH(p, q);
            out.DH(i, p * n + q) = lin.DH(p, q);
          }
      } catch (const std::exception& ex) {
        out.status[si] = "error";
        out.message[si] = ex.what();
      }
    }
  };
  detail::run_blocks(ns, n_threads, work);
  return out;
}

}  // namespace rotordyn
