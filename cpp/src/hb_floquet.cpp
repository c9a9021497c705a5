// The samples route's monodromy refined on the HB orbit itself (hb_detail.hpp,
// refined_monodromy): the orbit is a Fourier series, so the films can be linearised at any
// time of the period without another Newton iteration; the product of exponentials is
// repeated with twice the steps until the critical multiplier stops moving.
//
// Why: the interpolated A(τ) of the M Newton samples (sample_monodromy) aliases where the film
// Jacobians vary fast along the orbit (large cycles on cavitated films, stiff flexible
// shafts): on the motor–fan train (84 coordinates) at 110 Hz its |μ_c| was 13.49 with M = 32
// and 1.129 with M = 64 for the same orbit (docs/nonlinear.md, "Refined sample multipliers").
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>

#include "hb_detail.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn::hb_detail {

namespace {

// The films' K_H, D_H at one node, on the film coordinates only (the rows and columns where
// any sample's K_H or D_H is non-zero): a node of the 84-coordinate train is then 2 × 6²
// values instead of 2 × 84², so thousands of nodes fit in memory.
struct Node {
  Eigen::MatrixXd KH, DH;  // (k, k) on Frame::idx
};

// What every node shares: the film coordinates, −M⁻¹K, −M⁻¹(C + ΩG) and M⁻¹ on the film
// columns.
struct Frame {
  std::vector<Eigen::Index> idx;
  Eigen::MatrixXd MK, MC, Mf;  // (n, n), (n, n), (n, k)
};

Frame make_frame(const shooting_detail::Flow& F, const SystemModel& m, const Eval& e) {
  const Eigen::Index n = F.n;
  Frame fr;
  for (Eigen::Index i = 0; i < n; ++i) {
    bool used = false;
    for (std::size_t j = 0; j < e.KH.size() && !used; ++j)
      used = e.KH[j].row(i).any() || e.KH[j].col(i).any() || e.DH[j].row(i).any() ||
             e.DH[j].col(i).any();
    if (used) fr.idx.push_back(i);
  }
  const Eigen::Index k = static_cast<Eigen::Index>(fr.idx.size());
  fr.MK = -F.Mllt.solve(m.K);
  fr.MC = -F.Mllt.solve(F.Cd);
  // A model with no film (linear supports only) has k = 0: Eigen's triangular solve of a
  // zero-column right-hand side binds a reference to a null pointer (UBSan), so skip it.
  if (k == 0) {
    fr.Mf.resize(n, 0);
    return fr;
  }
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(n, k);
  for (Eigen::Index a = 0; a < k; ++a) S(fr.idx[static_cast<std::size_t>(a)], a) = 1.0;
  fr.Mf = F.Mllt.solve(S);
  return fr;
}

// A film linearisation restricted to the frame's coordinates; false if it has a non-zero
// entry outside them (a new sample's film touching other coordinates cannot happen for a
// fixed model, but is refused rather than dropped).
bool node_of(const Frame& fr, const Eigen::MatrixXd& KH, const Eigen::MatrixXd& DH, Node& nd) {
  const Eigen::Index k = static_cast<Eigen::Index>(fr.idx.size());
  nd.KH.resize(k, k);
  nd.DH.resize(k, k);
  for (Eigen::Index a = 0; a < k; ++a)
    for (Eigen::Index b = 0; b < k; ++b) {
      nd.KH(a, b) = KH(fr.idx[static_cast<std::size_t>(a)], fr.idx[static_cast<std::size_t>(b)]);
      nd.DH(a, b) = DH(fr.idx[static_cast<std::size_t>(a)], fr.idx[static_cast<std::size_t>(b)]);
    }
  return std::abs(KH.cwiseAbs().sum() - nd.KH.cwiseAbs().sum()) <= 1e-12 * KH.cwiseAbs().sum() &&
         std::abs(DH.cwiseAbs().sum() - nd.DH.cwiseAbs().sum()) <= 1e-12 * DH.cwiseAbs().sum();
}

// The first-order matrix at a node: [0 I; −M⁻¹(K + K_H) −M⁻¹(C + ΩG + D_H)].
Eigen::MatrixXd first_order(const Frame& fr, const Node& nd) {
  const Eigen::Index n = fr.MK.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.block(0, n, n, n).setIdentity();
  A.block(n, 0, n, n) = fr.MK;
  A.block(n, n, n, n) = fr.MC;
  const Eigen::MatrixXd dK = fr.Mf * nd.KH, dD = fr.Mf * nd.DH;  // (n, k)
  for (std::size_t b = 0; b < fr.idx.size(); ++b) {
    A.block(n, fr.idx[b], n, 1) -= dK.col(static_cast<Eigen::Index>(b));
    A.block(n, n + fr.idx[b], n, 1) -= dD.col(static_cast<Eigen::Index>(b));
  }
  return A;
}

// Position and velocity of the HB orbit (Z, ω) at τ.
void state_at(const Eigen::MatrixXd& Z, double w, double tau, Eigen::VectorXd& r,
              Eigen::VectorXd& v) {
  const int H = static_cast<int>((Z.rows() - 1) / 2);
  r = Z.row(0).transpose();
  v = Eigen::VectorXd::Zero(Z.cols());
  for (int k = 1; k <= H; ++k) {
    const double c = std::cos(k * tau), s = std::sin(k * tau);
    r += c * Z.row(2 * k - 1).transpose() + s * Z.row(2 * k).transpose();
    v += (w * k) * (c * Z.row(2 * k).transpose() - s * Z.row(2 * k - 1).transpose());
  }
}

// The films' linearisation at one state of the orbit (`where` names it in a failure); false
// with out.why / out.contact set on a film failure or a non-finite K_H, D_H.
bool linearize_at(SystemSolver& solver, const Eigen::VectorXd& r, const Eigen::VectorXd& v,
                  double omega, const std::string& where, Linearization& lin,
                  RefinedMonodromy& out) {
  try {
    lin = solver.linearize(r, v, omega);
  } catch (const ContactError& ex) {
    out.contact = true;
    out.why = "a film closed " + where + ": " + ex.what();
    return false;
  } catch (const ConvergenceError& ex) {
    out.why = "film solve " + where + ": " + ex.what();
    return false;
  }
  ++out.linearizations;
  if (!lin.KH.allFinite() || !lin.DH.allFinite()) {
    out.why = "non-finite film linearisation " + where;
    return false;
  }
  return true;
}

// The nodes doubled: the old nodes at even indices, the films linearised at the midpoints
// (in the order of τ, as the Newton's samples: the cavitation-set continuation sees
// consecutive nearby states). false with out.why / out.contact on a film failure.
bool double_nodes(std::vector<Node>& nodes, const Frame& fr, Problem& P, const Eigen::MatrixXd& Z,
                  double w, RefinedMonodromy& out) {
  const int G = static_cast<int>(nodes.size());
  std::vector<Node> next(static_cast<std::size_t>(2 * G));
  Eigen::VectorXd r, v;
  for (int i = 0; i < G; ++i) {
    next[static_cast<std::size_t>(2 * i)] = std::move(nodes[static_cast<std::size_t>(i)]);
    const double tau = 2 * M_PI * (2 * i + 1) / (2.0 * G);
    state_at(Z, w, tau, r, v);
    Linearization lin;
    if (!linearize_at(*P.solver, r, v, P.in->omega,
                      "between the samples (τ = " + std::to_string(tau) + ")", lin, out))
      return false;
    ++P.linearizations;
    if (!node_of(fr, lin.KH, lin.DH, next[static_cast<std::size_t>(2 * i + 1)])) {
      out.why = "a film linearisation between the samples acts on other coordinates";
      return false;
    }
  }
  nodes = std::move(next);
  return true;
}

// Φ over one period from G = 2 ns nodes at τ_i = 2πi/G: ns steps of 4th-order Magnus with
// Simpson's rule for the moments (B0 = (A0 + 4Am + A1)/6, B1 = (A1 − A0)/12; Ω = h B0 +
// h² [B1, B0]; Blanes, Casas, Oteo & Ros, Phys. Rep. 470 (2009), sec. 5) and the balanced
// exponential of each step.
Eigen::MatrixXd simpson_magnus(const Frame& fr, const std::vector<Node>& nodes, double T) {
  const int G = static_cast<int>(nodes.size()), ns = G / 2;
  const double h = T / ns;
  Eigen::MatrixXd A0 = first_order(fr, nodes[0]);
  const Eigen::Index N = A0.rows();
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Identity(N, N);
  for (int i = 0; i < ns; ++i) {
    const Eigen::MatrixXd Am = first_order(fr, nodes[static_cast<std::size_t>(2 * i + 1)]);
    Eigen::MatrixXd A1 = first_order(fr, nodes[static_cast<std::size_t>((2 * i + 2) % G)]);
    const Eigen::MatrixXd B0 = (A0 + 4.0 * Am + A1) / 6.0, B1 = (A1 - A0) / 12.0;
    const Eigen::MatrixXd Om = h * B0 + (h * h) * (B1 * B0 - B0 * B1);
    Phi = balanced_exp(Om) * Phi;
    A0 = std::move(A1);
  }
  return Phi;
}

}  // namespace

int refined_max_steps(int M, int requested) { return requested > 0 ? requested : 128 * M; }

RefinedMonodromy refined_monodromy(Problem& P, const Eval& e, const Eigen::MatrixXd& Z, double w,
                                   bool autonomous, double tol, int max_steps,
                                   double trivial_tol) {
  RefinedMonodromy out;
  const SystemModel& m = P.solver->model();
  const int M = static_cast<int>(e.KH.size());
  const double T = 2 * M_PI / w;
  const Frame fr = make_frame(*P.F, m, e);
  std::vector<Node> nodes(static_cast<std::size_t>(M));
  for (int j = 0; j < M; ++j)
    node_of(fr, e.KH[static_cast<std::size_t>(j)], e.DH[static_cast<std::size_t>(j)],
            nodes[static_cast<std::size_t>(j)]);
  // Simpson's steps need an even number of nodes: an odd M is doubled first.
  if (M % 2 == 1 && !double_nodes(nodes, fr, P, Z, w, out)) return out;
  double prev = std::numeric_limits<double>::quiet_NaN();
  std::string prev_type;
  for (;;) {
    const int ns = static_cast<int>(nodes.size()) / 2;
    Eigen::MatrixXd Phi = simpson_magnus(fr, nodes, T);
    if (!Phi.allFinite()) {
      // A coarse level of a stiff model can overflow (the rig's sleeve at M/2 = 16 steps:
      // the commutator term of a long step): no estimate from it, the next level decides.
      ++out.levels;
      out.moduli.push_back(std::numeric_limits<double>::quiet_NaN());
      out.error = std::numeric_limits<double>::quiet_NaN();
      if (2 * ns > max_steps) {
        out.why = "non-finite monodromy from the samples (" + std::to_string(ns) + " steps)";
        out.Phi.resize(0, 0);
        return out;
      }
      prev = std::numeric_limits<double>::quiet_NaN();
      prev_type.clear();
      if (!double_nodes(nodes, fr, P, Z, w, out)) {
        out.Phi.resize(0, 0);
        return out;
      }
      continue;
    }
    const Floquet fq = floquet(Phi, autonomous);
    const double mod = fq.critical >= 0 ? fq.critical_modulus : 0.0;
    out.Phi = std::move(Phi);
    out.steps = ns;
    ++out.levels;
    out.moduli.push_back(mod);
    out.trivial_error = fq.trivial >= 0 ? std::abs(fq.multipliers(fq.trivial) - 1.0) : 0.0;
    if (std::isfinite(prev)) {
      out.error = std::abs(mod - prev);
      if (out.error <= tol * std::max(1.0, mod) && fq.critical_type == prev_type &&
          !(trivial_tol > 0 && autonomous && out.trivial_error > trivial_tol)) {
        out.converged = true;
        break;
      }
    }
    if (2 * ns > max_steps) break;  // the budget: the verdict stays unresolved
    prev = mod;
    prev_type = fq.critical_type;
    if (!double_nodes(nodes, fr, P, Z, w, out)) {
      out.Phi.resize(0, 0);
      return out;
    }
  }
  // One finite level only (a budget below M steps): no estimate, nothing resolved. An
  // autonomous cycle's trivial multiplier is exactly 1 for the exact orbit: its distance from
  // 1 measures what the refinement cannot (the HB orbit's truncation), and the whip cycle's
  // |μ_c| converged 9.4e-3 away from the flow's with a trivial error of 1.4e-2
  // (docs/nonlinear.md): the estimate is the larger of the two.
  if (!std::isfinite(out.error)) out.error = std::numeric_limits<double>::infinity();
  if (autonomous) out.error = std::max(out.error, out.trivial_error);
  out.ok = true;
  return out;
}

bool linearize_samples(SystemSolver& solver, const PeriodicInput& in, const Eigen::MatrixXd& X,
                       Eval& e, RefinedMonodromy& out) {
  const Eigen::Index n = X.cols() / 2;
  const int M = static_cast<int>(X.rows()) - 1;  // the end sample repeats the start
  if (M < 2) {
    out.why = "the orbit has fewer than 3 samples (n_out)";
    return false;
  }
  e.KH.resize(static_cast<std::size_t>(M));
  e.DH.resize(static_cast<std::size_t>(M));
  for (int j = 0; j < M; ++j) {
    Linearization lin;
    if (!linearize_at(solver, X.row(j).head(n).transpose(), X.row(j).tail(n).transpose(),
                      in.omega, "at orbit sample " + std::to_string(j), lin, out))
      return false;
    e.KH[static_cast<std::size_t>(j)] = std::move(lin.KH);
    e.DH[static_cast<std::size_t>(j)] = std::move(lin.DH);
  }
  return true;
}

RefinedMonodromy refine_samples(SystemSolver& solver, const PeriodicInput& in,
                                shooting_detail::Flow& F, const Eigen::MatrixXd& X,
                                const Eval& e, double T, bool autonomous, double tol,
                                int max_steps) {
  const Eigen::Index n = F.n;
  const int M = static_cast<int>(e.KH.size());
  Problem P;
  P.solver = &solver;
  P.in = &in;
  P.F = &F;
  P.n = n;
  // The samples' linearisations use the orbit's own states (exact); the interpolant serves
  // the refinement's midpoints only.
  const Eigen::MatrixXd Z = project_samples(X.topLeftCorner(M, n), (M - 1) / 2);
  // the orbit is the integrator's (not a truncated series): its trivial multiplier must be 1
  return refined_monodromy(P, e, Z, 2 * M_PI / T, autonomous, tol, max_steps, tol);
}

RefinedMonodromy refined_monodromy_of_samples(SystemSolver& solver, const PeriodicInput& in,
                                              shooting_detail::Flow& F, const Eigen::MatrixXd& X,
                                              double T, bool autonomous, double tol,
                                              int max_steps) {
  RefinedMonodromy out;
  Eval e;
  if (!linearize_samples(solver, in, X, e, out)) return out;
  const long base = out.linearizations;
  out = refine_samples(solver, in, F, X, e, T, autonomous, tol, max_steps);
  out.linearizations += base;
  return out;
}

}  // namespace rotordyn::hb_detail
