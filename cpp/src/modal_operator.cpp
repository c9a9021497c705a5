// ModalOperator: the set-up of the shift-invert modal analysis done once per model.
#include "rotordyn/modal_operator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "modal_detail.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

struct ModalOperator::Impl {
  Eigen::MatrixXd M, C, G, K;       // dense: the rigid-body threshold and the dense path
  detail::SpMat Ms, Cs, Gs, Ks;     // the same numbers, zeros dropped
  double scale = 1.0;
  detail::SpLU lu0;                 // K's factorisation (σ = 0), when `factored`
  bool factored = false;
  detail::RigidBodyCache rigid;     // K's rigid-body motions, found on first need
};

namespace {
constexpr Eigen::Index kDenseLimit = 48;  // as in modal.cpp: below, the dense path only
}

ModalOperator::ModalOperator(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C,
                             const Eigen::MatrixXd& G, const Eigen::MatrixXd& K) {
  const Eigen::Index n = M.rows();
  require(n > 0 && M.cols() == n, shape_msg("M", n, n, M.rows(), M.cols()));
  require(C.rows() == n && C.cols() == n, shape_msg("C", n, n, C.rows(), C.cols()));
  require(G.rows() == n && G.cols() == n, shape_msg("G", n, n, G.rows(), G.cols()));
  require(K.rows() == n && K.cols() == n, shape_msg("K", n, n, K.rows(), K.cols()));
  auto p = std::make_shared<Impl>();
  p->M = M;
  p->C = C;
  p->G = G;
  p->K = K;
  p->Ms = M.sparseView(0.0, 0.0);
  p->Cs = C.sparseView(0.0, 0.0);
  p->Gs = G.sparseView(0.0, 0.0);
  p->Ks = K.sparseView(0.0, 0.0);
  p->scale = std::sqrt(K.diagonal().cwiseAbs().maxCoeff() /
                       std::max(1e-300, M.diagonal().cwiseAbs().maxCoeff()));
  if (n > kDenseLimit) p->factored = detail::factor_at_zero(p->Ks, p->Ms, p->lu0);
  impl_ = std::move(p);
}

Eigen::Index ModalOperator::size() const { return impl_->M.rows(); }

bool ModalOperator::factored() const { return impl_->factored; }

ModalResult ModalOperator::modal(double omega, const std::vector<std::pair<int, int>>& xy_pairs,
                                 int n_modes, bool with_modes,
                                 const std::vector<std::pair<int, int>>& rot_pairs) const {
  require(std::isfinite(omega), "omega: expected a finite spin speed (rad/s)");
  const Impl& p = *impl_;
  // D = C + Ω G entry by entry as the dense sum (c + Ω g), zeros dropped as sparseView does.
  detail::SpMat D = p.Cs + omega * p.Gs;
  D.prune(0.0, 0.0);
  detail::SparsePencil pencil;
  pencil.M = &p.Ms;
  pencil.D = &D;
  pencil.K = &p.Ks;
  pencil.scale = p.scale;
  pencil.lu0 = p.factored ? &p.lu0 : nullptr;
  Eigen::MatrixXd Dd;
  bool made = false;
  auto dense_D = [&]() -> const Eigen::MatrixXd& {
    if (!made) {
      Dd = p.C + omega * p.G;
      made = true;
    }
    return Dd;
  };
  return detail::modal_impl(p.M, dense_D, p.K, xy_pairs, n_modes, with_modes, rot_pairs,
                            nullptr, &pencil, &p.rigid);
}

}  // namespace rotordyn
