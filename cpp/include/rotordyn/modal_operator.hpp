// A rotor's modal operator kept between calls: the sparse M, C, G, K and the factorisation of
// K that the shift-invert Arnoldi uses at every speed (σ = 0 when K is regular), so a repeated
// modal analysis of one model costs its Arnoldi iteration, not its set-up (issue 22).
#pragma once
#include <Eigen/Core>

#include <memory>
#include <utility>
#include <vector>

#include "rotordyn/modal.hpp"

namespace rotordyn {

class ModalOperator {
 public:
  /// M, C, G, K: (n, n) dense, the analysed coordinates (D = C + Ω G at a speed Ω).
  ModalOperator(const Eigen::MatrixXd& M, const Eigen::MatrixXd& C, const Eigen::MatrixXd& G,
                const Eigen::MatrixXd& K);
  /// The same answer as rotordyn::modal(M, C + omega G, K, ...), bit for bit: the same
  /// numbers go through the same solver; only the set-up is reused.
  ModalResult modal(double omega, const std::vector<std::pair<int, int>>& xy_pairs,
                    int n_modes, bool with_modes,
                    const std::vector<std::pair<int, int>>& rot_pairs) const;
  Eigen::Index size() const;
  /// True when K was factorised once (K regular); else every call factorises its shifted
  /// pencil as rotordyn::modal does.
  bool factored() const;

  struct Impl;

 private:
  std::shared_ptr<const Impl> impl_;
};

}  // namespace rotordyn
