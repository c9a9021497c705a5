// Unbalance response over speeds with bearing elements in one call (see unbalance.hpp).
#include "rotordyn/unbalance.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <exception>
#include <limits>
#include <thread>

#include "rotordyn/bearing_table.hpp"
#include "rotordyn/errors.hpp"
#include "rotordyn/harmonic.hpp"
#include "rotordyn/modal.hpp"
#include "parallel_detail.hpp"

namespace rotordyn {

namespace {

bool converged(const std::string& s) { return s == "ok" || s == "contact"; }

// "<class>: <what>" as the Python side names the translated exception.
std::string named(const std::exception& ex) {
  const char* cls = dynamic_cast<const InputError*>(&ex)         ? "InputError"
                    : dynamic_cast<const ConvergenceError*>(&ex) ? "ConvergenceError"
                    : dynamic_cast<const ContactError*>(&ex)     ? "ContactError"
                    : dynamic_cast<const SundialsError*>(&ex)    ? "SundialsError"
                                                                 : "RuntimeError";
  return std::string(cls) + ": " + ex.what();
}

// Speeds [begin, end) in order on one solver, continued from in.r0 at `begin`.
void sweep_block(const SystemModel& m, const UnbalanceSweepInput& in, Eigen::Index begin,
                 Eigen::Index end, UnbalanceSweepResult& out) {
  const Eigen::Index n = m.n();
  SystemSolver solver(m);
  Eigen::VectorXd start = in.r0;
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = begin; i < end; ++i) {
    const auto si = static_cast<std::size_t>(i);
    const double w = in.omegas(i);
    Linearization lin;
    EquilibriumResult e;
    try {
      const Eigen::VectorXd a = in.a.row(i).transpose();
      e = pad_system_equilibrium(solver, m, w, in.pressure(i), a, start,
                                 Eigen::VectorXd(), in.options, in.pad_penalty);
      out.status[si] = e.status;
      out.message[si] = e.message;
      out.r.row(i) = e.r.transpose();
      if (converged(e.status)) {
        lin = in.finite_difference ? solver.linearize_fd(e.r, w, in.fd_step)
                                   : solver.linearize(e.r, zero, w);
        if (!lin.KH.allFinite() || !lin.DH.allFinite())
          throw ConvergenceError("linearize: non-finite K_H or D_H");
        if (in.bearing_elements && (lin.KH.array() == 0.0).all() &&
            (lin.DH.array() == 0.0).all())
          throw ConvergenceError("linearize: K_H and D_H are identically zero");
      }
    } catch (const std::exception& ex) {
      out.status[si] = "error";
      out.message[si] = named(ex);
      out.r.row(i).setConstant(std::numeric_limits<double>::quiet_NaN());
      if (in.cold_after_failure) start.resize(0);
      continue;
    }
    if (!converged(e.status)) {
      if (in.cold_after_failure) start.resize(0);
      continue;
    }
    start = e.r;
    try {
      const Eigen::MatrixXd M = m.has_table_mass() ? m.mass_at(w) : m.M;
      const Eigen::MatrixXd D = m.C + w * m.G + lin.DH;
      const Eigen::MatrixXd K = m.K + lin.KH;
      const Eigen::MatrixXcd F = in.F * (w * w);
      const Eigen::VectorXcd q = harmonic_response(M, D, K, w, F).col(0);
      out.Y.row(i) = (in.O.cast<std::complex<double>>() * q).transpose();
      if (in.check_stability) {
        const ModalResult mr = modal(M, D, K, in.xy_pairs, 0, false, in.rot_pairs);
        // the largest Re λ with the round-off band set to 0 (kRoundOffRel): the verdict's
        // key, so an undamped rotor is not called unstable on round-off
        for (Eigen::Index j = 0; j < mr.eigenvalues.size(); ++j) {
          const double re = settled_real(mr.eigenvalues[j]);
          if (j == 0 || re > out.max_real(i)) out.max_real(i) = re;
        }
      }
    } catch (const std::exception& ex) {
      out.solve_error[si] = named(ex);
      if (in.cold_after_failure) {
        out.status[si] = "error";
        out.message[si] = named(ex);
        out.Y.row(i).setConstant(std::complex<double>(std::numeric_limits<double>::quiet_NaN(),
                                                      std::numeric_limits<double>::quiet_NaN()));
        start.resize(0);
      }
    }
  }
}

}  // namespace

UnbalanceSweepResult unbalance_sweep(const SystemModel& model, const UnbalanceSweepInput& in) {
  model.validate();
  const Eigen::Index n = model.n(), ns = in.omegas.size();
  require(in.omegas.allFinite(), "omegas: expected finite speeds");
  require(in.pressure.size() == ns, shape_msg("pressure", ns, 1, in.pressure.size(), 1));
  require(in.a.rows() == ns && in.a.cols() == n, shape_msg("a", ns, n, in.a.rows(), in.a.cols()));
  require(in.r0.size() == 0 || in.r0.size() == n, shape_msg("r0", n, 1, in.r0.size(), 1));
  require(in.F.size() == n, shape_msg("F", n, 1, in.F.size(), 1));
  require(in.O.cols() == n, shape_msg("O", in.O.rows(), n, in.O.rows(), in.O.cols()));
  require(in.pad_penalty.size() == 0 ||
              (in.pad_penalty.rows() == n && in.pad_penalty.cols() == n),
          shape_msg("pad_penalty", n, n, in.pad_penalty.rows(), in.pad_penalty.cols()));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  UnbalanceSweepResult out;
  out.Y = Eigen::MatrixXcd::Constant(ns, in.O.rows(), std::complex<double>(nan, nan));
  out.status.assign(static_cast<std::size_t>(ns), "error");
  out.message.assign(static_cast<std::size_t>(ns), "");
  out.solve_error.assign(static_cast<std::size_t>(ns), "");
  out.r = RowMatrixXd::Constant(ns, n, nan);
  out.max_real = Eigen::VectorXd::Constant(ns, nan);
  int k = in.n_threads <= 0 ? static_cast<int>(std::max(1u, std::thread::hardware_concurrency()))
                            : in.n_threads;
  k = static_cast<int>(std::min<Eigen::Index>(k, std::max<Eigen::Index>(ns, 1)));
  detail::run_blocks(ns, k, [&](Eigen::Index b, Eigen::Index e) {
    sweep_block(model, in, b, e, out);
  });
  return out;
}

}  // namespace rotordyn
