// Flexible sleeve of the active journal bearing (paper §3.1): an in-plane curved-beam finite
// element, the sleeve as a curved cantilever, and the paper's three-step Guyan condensation to a
// few radial master coordinates, with the interpolation of the sleeve's radial displacement and
// the chamber-pressure load vector on the masters (eq. 1, 3, 11).
//
// Element formulation (see docs/sleeve.md): a circular-arc element of mid-surface radius R with
// thin-curved-beam energy U = ½∫(N²/EA + V²/κGA + M²/EI) ds, whose stiffness is the exact inverse
// of the tip flexibility of the arc clamped at its first node (Castigliano / force method), and
// whose consistent mass uses the exact static displacement field of the same arc (rigid motion
// of node a plus the cantilever deflection under the node-b end forces). The static solution is
// therefore exact for any mesh, there is no membrane or shear locking (no displacement
// interpolation is assumed), exactly three rigid-body modes exist, and the inextensible /
// shear-rigid limits are reached by setting a compliance to zero.
//
// Frames and signs: bearing frame x horizontal, y up, angles φ from +x positive with the
// rotation (counter-clockwise). A point of the arc at angle θ sits at R(cos θ, sin θ); e_t =
// (−sin θ, cos θ) (tangential, along increasing θ), e_n = (cos θ, sin θ) (outward normal).
// Global nodal DOFs (x_g, y_g, v_g): Cartesian displacements and the counter-clockwise section
// rotation. Local nodal DOFs (s, n, u): s = e_t·d, n = e_n·d (outward), u = v_g.
// Radial sleeve coordinates r (and the master coordinates) are positive INWARD, toward the
// journal: r = −e_n·d; the film thickness is h = c − x cos φ − y sin φ − w(φ) with w inward.
#pragma once
#include <Eigen/Core>

#include <vector>

namespace rotordyn {

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Matrix36d = Eigen::Matrix<double, 3, 6>;

/// Which effects the curved beam includes (all on: extensible, shear-flexible Timoshenko-type
/// thin curved beam with rotary inertia).
struct CurvedBeamOptions {
  bool extension = true;        ///< false: inextensible centre line (1/EA = 0)
  bool shear = true;            ///< false: shear-rigid (1/κGA = 0)
  bool rotary_inertia = true;   ///< false: no rotary inertia (ρI = 0)
  bool plane_strain = false;    ///< true: E → E/(1−ν²) (wide sleeve in cylindrical bending)
  double shear_coefficient = 0; ///< κ; <= 0: Cowper's rectangle 10(1+ν)/(12+11ν)
};

/// Rectangular section of the sleeve and its material. SI units.
struct CurvedBeamSection {
  double thickness = 0.0;  ///< d, radial, m
  double width = 0.0;      ///< b, axial (bearing length), m
  double young = 0.0;      ///< E, Pa
  double density = 0.0;    ///< ρ, kg/m³
  double poisson = 0.3;    ///< ν
  CurvedBeamOptions options;
};

/// Per-unit-length compliances and inertias used by the element.
struct CurvedBeamProperties {
  double compliance_bending = 0.0;  ///< 1/EI, 1/(N·m²)
  double compliance_axial = 0.0;    ///< 1/EA, 1/N (0: inextensible)
  double compliance_shear = 0.0;    ///< 1/κGA, 1/N (0: shear-rigid)
  double mass = 0.0;                ///< ρA, kg/m
  double rotary = 0.0;              ///< ρI, kg·m (0: no rotary inertia)
};
/// Validate the section (InputError naming the field and range) and derive the properties.
CurvedBeamProperties curved_beam_properties(const CurvedBeamSection& s);

/// One circular-arc element from angle theta_a to theta_b (> theta_a, at most π) at radius R.
class CurvedBeamElement {
 public:
  CurvedBeamElement(double radius, double theta_a, double theta_b, const CurvedBeamProperties& p);

  /// Stiffness and consistent mass in global DOFs (x_a, y_a, v_a, x_b, y_b, v_b).
  const Matrix6d& K() const { return K_; }
  const Matrix6d& M() const { return M_; }
  /// The same in local nodal DOFs (s_a, n_a, u_a, s_b, n_b, u_b) (n outward).
  Matrix6d K_local() const;
  Matrix6d M_local() const;
  /// Global → local transformation Q: d_local = Q d_global (orthogonal).
  Matrix6d to_local() const;
  /// (3, 6) exact static shape functions: (u_x, u_y, v) at angle theta ∈ [θa, θb] from the
  /// global nodal DOFs.
  Matrix36d shape(double theta) const;
  /// (3, 3) flexibility of node b (x, y, v) with node a clamped.
  const Eigen::Matrix3d& flexibility() const { return F_; }

  double radius() const { return R_; }
  double theta_a() const { return ta_; }
  double theta_b() const { return tb_; }

 private:
  Eigen::Matrix3d coupling(double t1, double t2) const;
  Eigen::Matrix3d internal(double psi, double theta) const;
  Eigen::Matrix3d rigid(double theta_p) const;
  double R_, ta_, tb_;
  CurvedBeamProperties p_;
  Eigen::Matrix3d F_, K22_;
  Eigen::Matrix<double, 3, 6> B_;
  Matrix6d K_, M_;
};

/// Assembled arc or ring in global DOFs (3 per node: x, y, v), no boundary conditions.
struct CurvedBeamMesh {
  double radius = 0.0;
  std::vector<double> node_angles;  ///< (n_nodes,) rad; a closed ring repeats no node
  std::vector<CurvedBeamElement> elements;
  std::vector<std::vector<int>> element_nodes;  ///< (n_elements, 2)
  Eigen::MatrixXd M, K;                        ///< (3 n_nodes, 3 n_nodes)
};
/// Open arc from theta_start over `arc` (> 0, ≤ 2π) with n_elements equal elements (each ≤ π).
CurvedBeamMesh curved_arc(double radius, double theta_start, double arc, int n_elements,
                          const CurvedBeamSection& section);
/// Complete closed ring of n_elements (≥ 3) equal elements; the last element closes on node 0.
CurvedBeamMesh closed_ring(double radius, int n_elements, const CurvedBeamSection& section);

/// Undamped natural frequencies (Hz, ascending) of K q = ω² M q (symmetric-definite).
Eigen::VectorXd natural_frequencies_hz(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K);

/// The sleeve: a curved cantilever clamped at clamp_angle, extending over `arc` in the
/// direction of rotation (φ increasing).
struct SleeveGeometry {
  double radius = 0.0;       ///< mid-surface radius R, m
  double arc = 0.0;          ///< ψ, rad, in (0, 2π]
  double clamp_angle = 0.0;  ///< film angle φ of the clamped end, rad (from +x, with rotation)
};

/// Sleeve model: geometry, section, mesh and master stations.
struct SleeveModel {
  SleeveGeometry geometry;
  CurvedBeamSection section;
  int n_elements = 20;
  /// Master stations: node numbers counted from the clamp (node 0, clamped) to the free end
  /// (node n_elements); strictly increasing, each in [1, n_elements].
  std::vector<int> master_nodes = {7, 14, 20};
};

/// The paper's three-step Guyan condensation and everything needed to expand it again.
/// Full DOFs: (x_g, y_g, v_g) of nodes 1 … n_elements (node 0 clamped), 3 n_elements.
struct SleeveCondensation {
  SleeveModel model;
  CurvedBeamMesh mesh;                ///< the unconstrained arc (node 0 = clamp)
  Eigen::MatrixXd M_full, K_full;     ///< (3n, 3n) clamped full model
  Eigen::MatrixXd M_xy, K_xy;         ///< (2n, 2n) step 1: rotations eliminated (x1,y1,x2,…)
  Eigen::MatrixXd M_rt, K_rt;         ///< (2n, 2n) step 2: polar (r1,t1,r2,…), r inward
  Eigen::MatrixXd Ms, Ks;             ///< (n_m, n_m) step 3: radial masters (eq. 1)
  Eigen::MatrixXd T;                  ///< (3n, n_m) full DOFs = T · r_s
  Eigen::VectorXd freq_full_hz;       ///< (3n,) full model
  Eigen::VectorXd freq_xy_hz;         ///< (2n,) after step 1
  Eigen::VectorXd freq_condensed_hz;  ///< (n_m,) condensed
  Eigen::VectorXd master_angles;      ///< (n_m,) film angles φ of the masters, rad

  /// Full DOF vector(s) (3n, k) from master coordinates (n_m, k).
  Eigen::MatrixXd expand(const Eigen::MatrixXd& r_s) const;
  /// (n_phi, n_m) matrix W with w(φ_k) = Σ_j W_kj r_s,j: inward radial displacement of the
  /// sleeve centre line at film angles phi (rad, any real value, wrapped to the sleeve), from
  /// the exact element shape functions. Angles outside the sleeve's arc give zero rows (for a
  /// 360° sleeve the free end's angle is the clamp's and maps to the clamp, w = 0).
  Eigen::MatrixXd interpolation(const Eigen::VectorXd& phi) const;
  /// (n_phi, 3n) the same on the full DOFs: w(φ_k) = Σ_i W_full,ki q_i (interpolation =
  /// interpolation_full · T).
  Eigen::MatrixXd interpolation_full(const Eigen::VectorXd& phi) const;
  /// (n_m,) generalized force on the masters per unit chamber pressure (m²): c_s with
  /// C_s0 = p_c c_s (eq. 11), from the virtual work of a uniform pressure on the outer face
  /// (radius R + d/2, width b) over the film-angle interval [phi_start, phi_end] (rad, inside
  /// the sleeve's arc, measured from the clamp in the direction of rotation).
  Eigen::VectorXd chamber_load(double phi_start, double phi_end) const;
  /// (3n,) consistent load of the same pressure on the full DOFs, N/Pa (chamber_load =
  /// Tᵀ · chamber_load_full).
  Eigen::VectorXd chamber_load_full(double phi_start, double phi_end) const;
};

/// Validate the model (InputError naming the field and range), build, condense.
SleeveCondensation condense_sleeve(const SleeveModel& model);

}  // namespace rotordyn
