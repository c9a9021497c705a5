// Rotor finite-element model: Timoshenko beam elements (shear deformation, rotary inertia,
// gyroscopic matrix), rigid disks and linear supports (paper §4, eq. 6).
//
// Degrees of freedom: 4 per node, ordered (x, y, θx, θy); x horizontal, y vertical up, z along
// the shaft axis, θx and θy rotations about x and y (right-hand rule). Slopes: dx/dz = θy,
// dy/dz = -θx. Spin Ω > 0 about +z. Equations of motion:
//   M q̈ + (C + Ω G) q̇ + K q = f,   G skew-symmetric; C holds the supports' dampers and the
// shaft's proportional material damping Σ_e (α_e M_e + β_e K_e).
#pragma once
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <utility>
#include <vector>

namespace rotordyn {

using SparseMatrixD = Eigen::SparseMatrix<double>;
using Matrix8d = Eigen::Matrix<double, 8, 8>;

/// One Timoshenko beam element of circular (solid or hollow) section. SI units.
struct ShaftElement {
  double length = 0.0;            ///< m
  double outer_diameter = 0.0;    ///< m
  double inner_diameter = 0.0;    ///< m (0 for a solid section)
  double density = 0.0;           ///< kg/m^3
  double young = 0.0;             ///< Pa
  double shear_modulus = 0.0;     ///< Pa
  double shear_coefficient = -1;  ///< κ; <= 0 means Cowper's value from the section and ν
  bool shear = true;              ///< false: Euler-Bernoulli (φ = 0)
  bool rotary_inertia = true;     ///< false: no rotary inertia and no gyroscopic terms
  /// Material (structural) damping, proportional: the element adds α M_e + β K_e to C
  /// (stationary, i.e. in the fixed frame). α in 1/s, β in s; 0 = undamped (the default).
  double damping_alpha = 0.0;
  double damping_beta = 0.0;

  double area() const;
  double second_moment() const;  ///< I = π(do⁴ - di⁴)/64, m^4
  double kappa() const;          ///< shear coefficient in use
  double phi() const;            ///< 12 E I / (κ G A L²)
};

/// Element matrices in global node DOF order (x1, y1, θx1, θy1, x2, y2, θx2, θy2).
struct ElementMatrices {
  Matrix8d M;  ///< translational + rotary inertia, kg / kg·m / kg·m²
  Matrix8d K;  ///< N/m, N, N·m
  Matrix8d G;  ///< gyroscopic (per unit Ω), skew-symmetric
};
ElementMatrices element_matrices(const ShaftElement& e);

/// Rigid disk at a node: mass, polar and diametral moments of inertia.
struct Disk {
  int node = 0;
  double mass = 0.0;  ///< kg
  double ip = 0.0;    ///< kg·m²
  double id = 0.0;    ///< kg·m²
};

/// Linear translational support (spring + damper to ground) at a node.
struct LinearSupport {
  int node = 0;
  Eigen::Matrix2d k = Eigen::Matrix2d::Zero();  ///< [[kxx, kxy], [kyx, kyy]], N/m
  Eigen::Matrix2d c = Eigen::Matrix2d::Zero();  ///< [[cxx, cxy], [cyx, cyy]], N·s/m
};

/// The whole rotor: elements in a chain (node i to i+1), disks, supports, rigid supports.
struct RotorModel {
  std::vector<ShaftElement> elements;
  std::vector<Disk> disks;
  std::vector<LinearSupport> supports;
  std::vector<int> rigid_nodes;  ///< nodes whose x and y are fixed (rotations free)

  int n_nodes() const { return static_cast<int>(elements.size()) + 1; }
  int n_dof() const { return 4 * n_nodes(); }
  void validate() const;  ///< throws InputError naming the field
};

/// Assembled free-free sparse matrices (n_dof × n_dof); supports add to K and C, the shaft
/// elements' proportional damping α M_e + β K_e to C (nothing where α = β = 0).
struct RotorMatrices {
  SparseMatrixD M, K, C, G;
};
RotorMatrices assemble(const RotorModel& model);

/// Indices of the DOFs that remain after the rigid supports are applied (ascending).
std::vector<int> free_dofs(const RotorModel& model);

/// Total mass of shaft and disks, kg.
double total_mass(const RotorModel& model);

}  // namespace rotordyn

namespace rotordyn {

/// Dense matrices of the rotor after the rigid supports are applied (rows/columns of the
/// fixed DOFs removed), plus the map back to the full DOF numbering.
struct ConstrainedRotor {
  Eigen::MatrixXd M, K, C, G;              ///< (n_free, n_free)
  std::vector<int> dofs;                   ///< full DOF index of each retained DOF
  std::vector<std::pair<int, int>> xy;     ///< (ix, iy) local index pairs for whirl
  std::vector<std::pair<int, int>> rot;    ///< (iθx, iθy) local index pairs
  /// Local index of full DOF d, or -1 if it was removed.
  int local(int full_dof) const;
};
ConstrainedRotor constrain(const RotorModel& model);

}  // namespace rotordyn
