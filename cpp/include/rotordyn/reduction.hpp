// Model reduction of M q̈ + D q̇ + K q = f to master coordinates (paper §4 and §6: Guyan
// condensation of the rotor to a few stations), plus IRS and Craig-Bampton.
//
// q ≈ T q_r; reduced matrices X_r = Tᵀ X T. The first n_masters reduced coordinates are the
// master DOFs themselves (in the order given); Craig-Bampton appends modal coordinates.
#pragma once
#include <Eigen/Core>

#include <string>
#include <vector>

namespace rotordyn {

enum class ReductionKind { Guyan, IRS, CraigBampton };

/// Parse "guyan" | "irs" | "craig-bampton" (InputError naming `field` otherwise).
ReductionKind parse_reduction(const std::string& name, const std::string& field = "reduction");

struct Reduction {
  ReductionKind kind = ReductionKind::Guyan;
  std::vector<int> masters;  ///< indices into the full DOF vector
  Eigen::MatrixXd T;         ///< (n_full, n_reduced) transformation
  Eigen::MatrixXd M, K;      ///< reduced mass and stiffness

  /// Tᵀ X T for any other full matrix (damping, gyroscopic).
  Eigen::MatrixXd reduce(const Eigen::MatrixXd& X) const;
  /// Full DOF vector(s) from reduced coordinates: T q_r.
  Eigen::MatrixXd expand(const Eigen::MatrixXd& qr) const;
};

/// Guyan (static) condensation. Throws InputError if the slave stiffness is singular
/// (e.g. a free-free rotor with fewer masters than rigid-body modes need).
Reduction guyan(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
                const std::vector<int>& masters);
/// Improved Reduced System (O'Callahan 1989): T = T_G + S M T_G M_G⁻¹ K_G.
Reduction irs(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K, const std::vector<int>& masters);
/// Craig-Bampton: masters plus n_modes fixed-interface (slave) normal modes.
Reduction craig_bampton(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
                        const std::vector<int>& masters, int n_modes);

Reduction reduce_model(ReductionKind kind, const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
                       const std::vector<int>& masters, int n_modes = 0);

}  // namespace rotordyn
