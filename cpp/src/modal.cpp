#include "rotordyn/modal.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <exception>
#include <functional>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "modal_detail.hpp"
#include "rotordyn/errors.hpp"

extern "C" {
void dgeev_(const char* jobvl, const char* jobvr, const int* n, double* a, const int* lda,
            double* wr, double* wi, double* vl, const int* ldvl, double* vr, const int* ldvr,
            double* work, const int* lwork, int* info);
}

namespace rotordyn {

namespace {
constexpr Eigen::Index kDenseLimit = 48;  // DOFs above which the sparse path is tried
// Kept roots above which the dense path takes dgeev's vectors instead of one LU per root.
constexpr int kInverseIterationRoots = 12;
}

void eig_general(const Eigen::MatrixXd& A_in, Eigen::VectorXcd& w, Eigen::MatrixXcd* V) {
  const int n = static_cast<int>(A_in.rows());
  require(A_in.cols() == n, shape_msg("A", n, n, A_in.rows(), A_in.cols()));
  Eigen::MatrixXd A = A_in;  // dgeev overwrites
  Eigen::VectorXd wr(n), wi(n);
  Eigen::MatrixXd vr(V ? n : 1, V ? n : 1);
  const char jobvl = 'N', jobvr = V ? 'V' : 'N';
  int ldv = V ? n : 1, info = 0, lwork = -1, one = 1;
  double wq = 0, dummy = 0;
  dgeev_(&jobvl, &jobvr, &n, A.data(), &n, wr.data(), wi.data(), &dummy, &one, vr.data(), &ldv,
         &wq, &lwork, &info);
  lwork = std::max(1, static_cast<int>(wq));
  std::vector<double> work(static_cast<std::size_t>(lwork));
  dgeev_(&jobvl, &jobvr, &n, A.data(), &n, wr.data(), wi.data(), &dummy, &one, vr.data(), &ldv,
         work.data(), &lwork, &info);
  if (info != 0)
    throw ConvergenceError("eigenvalue solver (LAPACK dgeev) failed, info = " +
                           std::to_string(info));
  w.resize(n);
  for (int i = 0; i < n; ++i) w(i) = {wr(i), wi(i)};
  if (V) {
    V->resize(n, n);
    for (int j = 0; j < n; ++j) {
      if (wi(j) == 0.0) {
        V->col(j) = vr.col(j).cast<std::complex<double>>();
      } else if (j + 1 < n) {
        for (int i = 0; i < n; ++i) {
          (*V)(i, j) = {vr(i, j), vr(i, j + 1)};
          (*V)(i, j + 1) = {vr(i, j), -vr(i, j + 1)};
        }
        ++j;
      }
    }
  }
}

Whirl whirl_direction(const Eigen::VectorXcd& s, const std::vector<std::pair<int, int>>& xy,
                      const std::vector<std::pair<int, int>>& rot) {
  // x = Re(X e^{iωt}), y = Re(Y e^{iωt}); counter-clockwise (forward, with Ω > 0) when
  // Im(X conj(Y)) > 0. Sum the signed orbit areas over all pairs. For rotations the disk
  // axis tip sits at (θy, −θx), which turns counter-clockwise when Im(θx conj(θy)) > 0: the
  // same expression with (θx, θy) in place of (x, y).
  auto areas = [&](const std::vector<std::pair<int, int>>& pairs, double& area, double& scale) {
    area = 0;
    scale = 0;
    for (const auto& p : pairs) {
      const auto X = s(p.first), Y = s(p.second);
      area += std::imag(X * std::conj(Y));
      scale += std::norm(X) + std::norm(Y);
    }
  };
  double at, st, ar, sr;
  areas(xy, at, st);
  areas(rot, ar, sr);
  // Translations decide unless they are round-off against the rotations (pure tilt modes).
  const bool use_rot = !rot.empty() && st <= 1e-12 * (st + sr);
  const double area = use_rot ? ar : at, scale = use_rot ? sr : st;
  // One rule with a stated tolerance (also rotordyn.results.modes.WHIRL_PLANAR_TOL): the whirl
  // index 2·area/scale = (|F|² − |B|²)/(|F|² + |B|²) of the forward/backward circular
  // components lies in [−1, 1]; a mode is planar when |index| < 0.05, i.e. its orbits'
  // minor/major axis ratio is below about 2.5 % (near-planar modes of a nearly isotropic rotor
  // at rest no longer flip between forward and backward on round-off).
  constexpr double kPlanarTol = 0.05;
  if (scale == 0 || 2.0 * std::abs(area) < kPlanarTol * scale) return Whirl::Planar;
  return area > 0 ? Whirl::Forward : Whirl::Backward;
}

namespace {
Eigen::MatrixXd state_matrix(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D,
                             const Eigen::MatrixXd& K) {
  const Eigen::Index n = M.rows();
  require(M.cols() == n, shape_msg("M", n, n, M.rows(), M.cols()));
  require(D.rows() == n && D.cols() == n, shape_msg("D", n, n, D.rows(), D.cols()));
  require(K.rows() == n && K.cols() == n, shape_msg("K", n, n, K.rows(), K.cols()));
  Eigen::LLT<Eigen::MatrixXd> llt(M);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  if (llt.info() == Eigen::Success) {
    A.bottomLeftCorner(n, n) = -llt.solve(K);
    A.bottomRightCorner(n, n) = -llt.solve(D);
  } else {
    Eigen::PartialPivLU<Eigen::MatrixXd> lu(M);
    require(std::abs(lu.determinant()) > 0, "M: mass matrix is singular");
    A.bottomLeftCorner(n, n) = -lu.solve(K);
    A.bottomRightCorner(n, n) = -lu.solve(D);
  }
  return A;
}

std::vector<int> pick_modes(const Eigen::VectorXcd& w, int n_modes, double zero,
                            const std::vector<char>* rigid = nullptr) {
  // Keep one of each conjugate pair (ω_d >= 0); real roots are kept once each. Rigid-body
  // roots (|λ| below `zero`, a multiple root that rounding spreads into tiny complex pairs,
  // or marked by detail::rigid_roots) are dropped.
  std::vector<int> idx;
  const double big = w.size() ? w.cwiseAbs().maxCoeff() : 0.0;
  for (int i = 0; i < w.size(); ++i) {
    const double im = w(i).imag();
    if (std::abs(w(i)) < zero) continue;
    if (rigid && (*rigid)[static_cast<std::size_t>(i)]) continue;
    if (im > 1e-12 * big || im == 0.0) idx.push_back(i);
  }
  std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) {
    const double fa = w(a).imag(), fb = w(b).imag();
    if (fa != fb) return fa < fb;
    return std::abs(w(a)) < std::abs(w(b));
  });
  // Drop decaying real roots: overdamped motions carry no natural frequency. Keep them only
  // when nothing else is left. A growing real root (Re λ above the round-off band
  // kRoundOffRel) is a divergence — a static instability,
  // e.g. an equilibrium past a fold — and is always kept (first: its frequency is 0), so
  // the verdict of every caller sees it.
  std::vector<int> osc;
  for (int i : idx)
    if (w(i).imag() > 0 || settled_real(w(i)) > 0)
      osc.push_back(i);
  if (!osc.empty()) idx.swap(osc);
  if (n_modes > 0 && static_cast<int>(idx.size()) > n_modes) idx.resize(n_modes);
  return idx;
}
}  // namespace

namespace detail {
ModalResult modal_impl(const Eigen::MatrixXd& M,
                       const std::function<const Eigen::MatrixXd&()>& dense_D,
                       const Eigen::MatrixXd& K, const std::vector<std::pair<int, int>>& xy_pairs,
                       int n_modes, bool with_modes,
                       const std::vector<std::pair<int, int>>& rot_pairs, Eigen::VectorXd* start,
                       const SparsePencil* pre, const RigidBodyCache* rigid_cache) {
  const Eigen::Index n = M.rows();
  Eigen::VectorXcd w;
  Eigen::MatrixXcd V;
  // Rigid-body threshold from the model's own frequency scale √(max K_ii / max M_ii).
  const double mk = K.diagonal().cwiseAbs().maxCoeff(), mm = M.diagonal().cwiseAbs().maxCoeff();
  const double zero = 1e-7 * std::sqrt(mk / std::max(mm, 1e-300));
  // The roots that are K's rigid-body motions spread by rounding (one rule for both paths,
  // modal_rigid.cpp). rigid_body's O(n³) is spent only when a root is small enough to be one:
  // never for a supported rotor, once per model when the cache is shared.
  const double omega_ref = frequency_reference(M, K);
  RigidBodyCache own_cache;
  const RigidBodyCache& cache = rigid_cache ? *rigid_cache : own_cache;
  // When K is singular the count of rigid_roots replaces the threshold `zero` (which would
  // drop a slow nutation that rigid_roots keeps); `zero` stays for a regular K.
  double zero_here = zero;
  Eigen::VectorXcd spread;  // the roots before rigid_roots (those it replaced by μ differ)
  auto rigid_marks = [&](Eigen::VectorXcd& roots) {
    zero_here = zero;
    spread = roots;
    if (roots.size() == 0) return std::vector<char>();
    const double hi = std::max(omega_ref, roots.cwiseAbs().maxCoeff());
    if (!(roots.cwiseAbs().minCoeff() < rigid_root_bound(hi)))
      return std::vector<char>(static_cast<std::size_t>(roots.size()), 0);
    const RigidBody& rb = cache.get(M, K);
    if (rb.phi.cols() > 0) zero_here = 0.0;
    return rigid_roots(rb, M, dense_D(), roots);
  };
  std::vector<int> idx;
  bool done = false;
  // Large model, few modes: shift-invert Arnoldi on the sparse pencil; ask for more roots
  // while rigid-body or overdamped roots crowd out the oscillating ones.
  for (int extra = 0; n > kDenseLimit && n_modes > 0 && extra <= 16; extra += 8) {
    if (2 * (n_modes + extra) + 30 >= n) break;
    const bool conv =
        pre ? modal_shift_invert(*pre, n_modes + extra, w, V, start)
            : modal_shift_invert(M, dense_D(), K, n_modes + extra, w, V, start);
    if (!conv) break;
    const std::vector<char> rigid = rigid_marks(w);
    idx = pick_modes(w, n_modes, zero_here, &rigid);
    if (static_cast<int>(idx.size()) >= n_modes) {
      done = true;
      break;
    }
  }
  if (!done) {
    // Dense path: eigenvalues only (LAPACK dgeev without vectors is ~3x cheaper), then one
    // inverse-iteration step on the quadratic pencil for each kept root — an O(n³) LU per
    // root, so when many roots are kept (all modes asked, or most of them) the vectors come
    // from dgeev itself: 27.6 s → 0.4 s CPU for all 244 modes of a 244-DOF rotor.
    const Eigen::MatrixXd& D = dense_D();
    const Eigen::MatrixXd A = state_matrix(M, D, K);
    // Every root, eigenvalues only (a verdict over all of them): no vectors, so the whirl of
    // these roots is not classified (planar). Not for a conservative gyroscopic pencil: its
    // roots are refined below from their vectors (else dgeev's rounding in Re λ, up to
    // ~1e-6·|λ|, would reach the verdict and make it depend on n_modes).
    if (n_modes <= 0 && !with_modes && !detail::conservative_gyroscopic(M, D, K)) {
      eig_general(A, w, nullptr);
      const std::vector<char> rigid = rigid_marks(w);
      idx = pick_modes(w, n_modes, zero_here, &rigid);
      V = Eigen::MatrixXcd::Zero(n, w.size());
    } else if (n_modes <= 0 || n_modes > kInverseIterationRoots) {
      Eigen::MatrixXcd Vs;
      eig_general(A, w, &Vs);
      const std::vector<char> rigid = rigid_marks(w);
      idx = pick_modes(w, n_modes, zero_here, &rigid);
      V = Vs.topRows(n);
      for (int k : idx) V.col(k).normalize();
    } else {
      eig_general(A, w, nullptr);
      const std::vector<char> rigid = rigid_marks(w);
      idx = pick_modes(w, n_modes, zero_here, &rigid);
      V.resize(n, w.size());
      const Eigen::MatrixXcd Mc = M.cast<std::complex<double>>(),
                             Dc = D.cast<std::complex<double>>(),
                             Kc = K.cast<std::complex<double>>();
      Eigen::VectorXcd b(n);
      for (Eigen::Index i = 0; i < n; ++i) b(i) = {1.0 + 0.1 * std::sin(1.0 + 2.3 * i), 0.0};
      for (int k : idx) {
        const std::complex<double> lam = w(k);
        const std::complex<double> mu = lam + 1e-9 * std::abs(lam);  // keep P(μ) invertible
        Eigen::PartialPivLU<Eigen::MatrixXcd> lu(mu * mu * Mc + mu * Dc + Kc);
        Eigen::VectorXcd x = lu.solve(b);
        x.normalize();
        x = lu.solve(x);  // a second step cleans components of close roots
        if (!x.allFinite()) x = b;
        V.col(k) = x.normalized();
      }
    }
  }
  // A conservative gyroscopic pencil (no damping, symmetric K: a free rotor, one on linear
  // springs) has purely imaginary roots for K ≥ 0, but the solvers' own carry rounding of
  // O(ε ω_max² / |λ|) in Re λ: a spurious damping ratio of -7e-6 on a free rotor's 1 Hz
  // nutation (dense path), -5e-8 on a pump's 200 N/m support modes. Each kept root takes its
  // vector's structured Rayleigh quotient (exactly imaginary, second-order accurate); the
  // roots rigid_roots set to the rigid-body subspace's μ keep that value.
  if (!idx.empty() && detail::conservative_gyroscopic(M, dense_D(), K)) {
    const Eigen::MatrixXd& D = dense_D();
    for (int k : idx)
      if (spread.size() != w.size() || spread(k) == w(k))
        w(k) = detail::conservative_root(M, D, K, V.col(k).head(n), w(k));
    std::stable_sort(idx.begin(), idx.end(), [&](int a, int b) {
      const double fa = w(a).imag(), fb = w(b).imag();
      if (fa != fb) return fa < fb;
      return std::abs(w(a)) < std::abs(w(b));
    });
  }
  ModalResult out;
  const int m = static_cast<int>(idx.size());
  out.eigenvalues.resize(m);
  if (with_modes) out.modes.resize(n, m);
  out.whirl.resize(static_cast<std::size_t>(m));
  for (int j = 0; j < m; ++j) {
    out.eigenvalues(j) = w(idx[j]);
    Eigen::VectorXcd s = V.col(idx[j]).head(n);
    Eigen::Index imax = 0;
    s.cwiseAbs().maxCoeff(&imax);
    if (std::abs(s(imax)) > 0) s /= s(imax);
    out.whirl[static_cast<std::size_t>(j)] = whirl_direction(s, xy_pairs, rot_pairs);
    if (with_modes) out.modes.col(j) = s;
  }
  return out;
}
}  // namespace detail

ModalResult modal(const Eigen::MatrixXd& M, const Eigen::MatrixXd& D, const Eigen::MatrixXd& K,
                  const std::vector<std::pair<int, int>>& xy_pairs, int n_modes,
                  bool with_modes, const std::vector<std::pair<int, int>>& rot_pairs) {
  const Eigen::Index n = M.rows();
  require(M.cols() == n, shape_msg("M", n, n, M.rows(), M.cols()));
  require(D.rows() == n && D.cols() == n, shape_msg("D", n, n, D.rows(), D.cols()));
  require(K.rows() == n && K.cols() == n, shape_msg("K", n, n, K.rows(), K.cols()));
  auto dense_D = [&D]() -> const Eigen::MatrixXd& { return D; };
  return detail::modal_impl(M, dense_D, K, xy_pairs, n_modes, with_modes, rot_pairs, nullptr,
                            nullptr);
}

CampbellResult campbell(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                        const Eigen::MatrixXd& G, const Eigen::MatrixXd& K,
                        const std::vector<std::pair<int, int>>& xy_pairs,
                        const Eigen::VectorXd& speeds, int n_modes,
                        const std::vector<std::pair<int, int>>& rot_pairs) {
  require(n_modes > 0, "n_modes: expected > 0, got " + std::to_string(n_modes));
  CampbellResult out;
  out.eigenvalues = Eigen::MatrixXcd::Constant(speeds.size(), n_modes,
                                               std::complex<double>(NAN, NAN));
  out.whirl = Eigen::MatrixXi::Zero(speeds.size(), n_modes);
  // Speeds are spread over threads in contiguous blocks; within a block each speed's Krylov
  // start is the previous speed's wanted Ritz vectors (nearby operators). The eigenvalues do
  // not depend on the start beyond the convergence tolerance. An exception in any thread is
  // stored and rethrown on the calling thread.
  std::exception_ptr error = nullptr;
  const detail::RigidBodyCache rigid;  // K's rigid-body motions: the same at every speed
#pragma omp parallel
  {
    Eigen::VectorXd start;
#pragma omp for schedule(static)
    for (Eigen::Index s = 0; s < speeds.size(); ++s) {
      try {
        const Eigen::MatrixXd D = C + speeds(s) * G;
        auto dense_D = [&D]() -> const Eigen::MatrixXd& { return D; };
        const ModalResult r = detail::modal_impl(M, dense_D, K, xy_pairs, n_modes, false,
                                                 rot_pairs, &start, nullptr, &rigid);
        for (Eigen::Index j = 0; j < r.eigenvalues.size(); ++j) {
          out.eigenvalues(s, j) = r.eigenvalues(j);
          out.whirl(s, j) = static_cast<int>(r.whirl[static_cast<std::size_t>(j)]);
        }
      } catch (...) {
        start.resize(0);
#pragma omp critical
        if (!error) error = std::current_exception();
      }
    }
  }
  if (error) std::rethrow_exception(error);
  return out;
}

}  // namespace rotordyn
