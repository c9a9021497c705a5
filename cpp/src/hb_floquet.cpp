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

// The lower blocks of the first-order matrix at one node: −M⁻¹(K + K_H), −M⁻¹(C + ΩG + D_H).
struct Node {
  Eigen::MatrixXd Ak, Ad;
};

Node node_of(const shooting_detail::Flow& F, const SystemModel& m, const Eigen::MatrixXd& KH,
             const Eigen::MatrixXd& DH) {
  Node nd;
  nd.Ak = -F.Mllt.solve(m.K + KH);
  nd.Ad = -F.Mllt.solve(F.Cd + DH);
  return nd;
}

Eigen::MatrixXd first_order(const Node& nd) {
  const Eigen::Index n = nd.Ak.rows();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.block(0, n, n, n).setIdentity();
  A.block(n, 0, n, n) = nd.Ak;
  A.block(n, n, n, n) = nd.Ad;
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

// The nodes doubled: the old nodes at even indices, the films linearised at the midpoints
// (in the order of τ, as the Newton's samples: the cavitation-set continuation sees
// consecutive nearby states). false with out.why / out.contact on a film failure.
bool double_nodes(std::vector<Node>& nodes, Problem& P, const Eigen::MatrixXd& Z, double w,
                  RefinedMonodromy& out) {
  const SystemModel& m = P.solver->model();
  const int G = static_cast<int>(nodes.size());
  std::vector<Node> next(static_cast<std::size_t>(2 * G));
  Eigen::VectorXd r, v;
  for (int i = 0; i < G; ++i) {
    next[static_cast<std::size_t>(2 * i)] = std::move(nodes[static_cast<std::size_t>(i)]);
    const double tau = 2 * M_PI * (2 * i + 1) / (2.0 * G);
    state_at(Z, w, tau, r, v);
    Linearization lin;
    try {
      lin = P.solver->linearize(r, v, P.in->omega);
    } catch (const ContactError& ex) {
      out.contact = true;
      out.why = std::string("a film closed between the samples (τ = ") + std::to_string(tau) +
                "): " + ex.what();
      return false;
    } catch (const ConvergenceError& ex) {
      out.why = std::string("film solve between the samples: ") + ex.what();
      return false;
    }
    ++out.linearizations;
    ++P.linearizations;
    if (!lin.KH.allFinite() || !lin.DH.allFinite()) {
      out.why = "non-finite film linearisation between the samples";
      return false;
    }
    next[static_cast<std::size_t>(2 * i + 1)] = node_of(*P.F, m, lin.KH, lin.DH);
  }
  nodes = std::move(next);
  return true;
}

// Φ over one period from G = 2 ns nodes at τ_i = 2πi/G: ns steps of 4th-order Magnus with
// Simpson's rule for the moments (B0 = (A0 + 4Am + A1)/6, B1 = (A1 − A0)/12; Ω = h B0 +
// h² [B1, B0]; Blanes, Casas, Oteo & Ros, Phys. Rep. 470 (2009), sec. 5) and the balanced
// exponential of each step.
Eigen::MatrixXd simpson_magnus(const std::vector<Node>& nodes, double T) {
  const int G = static_cast<int>(nodes.size()), ns = G / 2;
  const double h = T / ns;
  Eigen::MatrixXd A0 = first_order(nodes[0]);
  const Eigen::Index N = A0.rows();
  Eigen::MatrixXd Phi = Eigen::MatrixXd::Identity(N, N);
  for (int i = 0; i < ns; ++i) {
    const Eigen::MatrixXd Am = first_order(nodes[static_cast<std::size_t>(2 * i + 1)]);
    Eigen::MatrixXd A1 = first_order(nodes[static_cast<std::size_t>((2 * i + 2) % G)]);
    const Eigen::MatrixXd B0 = (A0 + 4.0 * Am + A1) / 6.0, B1 = (A1 - A0) / 12.0;
    const Eigen::MatrixXd Om = h * B0 + (h * h) * (B1 * B0 - B0 * B1);
    Phi = balanced_exp(Om) * Phi;
    A0 = std::move(A1);
  }
  return Phi;
}

}  // namespace

int refined_max_steps(int M, int requested) { return requested > 0 ? requested : 8 * M; }

RefinedMonodromy refined_monodromy(Problem& P, const Eval& e, const Eigen::MatrixXd& Z, double w,
                                   bool autonomous, double tol, int max_steps) {
  RefinedMonodromy out;
  const SystemModel& m = P.solver->model();
  const int M = static_cast<int>(e.KH.size());
  const double T = 2 * M_PI / w;
  std::vector<Node> nodes(static_cast<std::size_t>(M));
  for (int j = 0; j < M; ++j)
    nodes[static_cast<std::size_t>(j)] =
        node_of(*P.F, m, e.KH[static_cast<std::size_t>(j)], e.DH[static_cast<std::size_t>(j)]);
  // Simpson's steps need an even number of nodes: an odd M is doubled first.
  if (M % 2 == 1 && !double_nodes(nodes, P, Z, w, out)) return out;
  double prev = std::numeric_limits<double>::quiet_NaN();
  std::string prev_type;
  for (;;) {
    const int ns = static_cast<int>(nodes.size()) / 2;
    Eigen::MatrixXd Phi = simpson_magnus(nodes, T);
    if (!Phi.allFinite()) {
      out.why = "non-finite monodromy from the samples (" + std::to_string(ns) + " steps)";
      out.Phi.resize(0, 0);
      return out;
    }
    const Floquet fq = floquet(Phi, autonomous);
    const double mod = fq.critical >= 0 ? fq.critical_modulus : 0.0;
    out.Phi = std::move(Phi);
    out.steps = ns;
    ++out.levels;
    out.moduli.push_back(mod);
    out.trivial_error = fq.trivial >= 0 ? std::abs(fq.multipliers(fq.trivial) - 1.0) : 0.0;
    if (out.levels >= 2) {
      out.error = std::abs(mod - prev);
      if (out.error <= tol * std::max(1.0, mod) && fq.critical_type == prev_type) {
        out.converged = true;
        break;
      }
    }
    if (2 * ns > max_steps) break;  // the budget: the verdict stays unresolved
    prev = mod;
    prev_type = fq.critical_type;
    if (!double_nodes(nodes, P, Z, w, out)) {
      out.Phi.resize(0, 0);
      return out;
    }
  }
  // One level only (a budget below M steps): no estimate, so nothing is resolved.
  if (out.levels < 2) out.error = std::numeric_limits<double>::infinity();
  out.ok = true;
  return out;
}

}  // namespace rotordyn::hb_detail
