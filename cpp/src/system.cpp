// Film forces of the multi-bearing system and their linearisation (paper eq. 12-13, 17-20).
#include "rotordyn/system.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "rotordyn/errors.hpp"

namespace rotordyn {

struct SystemSolver::Film {
  ReynoldsSolver solver;
  Eigen::VectorXd wz;  ///< trapezoid weights along z times R dφ dz, (n_axial + 1,)
  RowMatrixXd h, dhdt, p;
  // the inputs of the last solve (its pressures and factorisation are reused when unchanged)
  bool valid = false;
  Eigen::VectorXd last_rc, last_vc;
  double last_w = 0.0;
  /// ∂h/∂r_k of each coordinate (constant: h is affine in r) and a zero field, for the
  /// linearised solves.
  std::vector<RowMatrixXd> dh;
  RowMatrixXd zero;
  Film(const FilmCoupling& f)
      : solver(f.geometry, f.grid, f.cavitation),
        h(f.grid.n_circ, f.grid.n_axial + 1),
        dhdt(f.grid.n_circ, f.grid.n_axial + 1),
        zero(RowMatrixXd::Zero(f.grid.n_circ, f.grid.n_axial + 1)) {
    for (std::size_t k = 0; k < f.coords.size(); ++k)
      dh.push_back(f.thickness_derivative(static_cast<Eigen::Index>(k)));
    solver.set_pressure_only(true);  // the forces are ∫∫ p S dA here (integrate), not force_n
    if (f.viscosity_field.size()) solver.set_viscosity_field(f.viscosity_field);
    const int K1 = f.grid.n_axial + 1;
    const double R = 0.5 * f.geometry.diameter_m;
    const double dphi = 2.0 * M_PI / f.grid.n_circ, dz = f.geometry.length_m / f.grid.n_axial;
    wz = Eigen::VectorXd::Constant(K1, R * dphi * dz);
    wz(0) *= 0.5;
    wz(K1 - 1) *= 0.5;
  }
  /// ∫∫ p ∂h/∂r_k dA for every coordinate k of the film (n_coords,): S(·, k) with the
  /// axial weights W (n_coords, n_axial + 1; empty: 1). Coordinates whose weight is 1
  /// everywhere take the unweighted integral (the untilted film's arithmetic, bit for bit).
  Eigen::VectorXd integrate(const RowMatrixXd& pr, const RowMatrixXd& S,
                            const RowMatrixXd& W) const {
    const Eigen::VectorXd g = pr * wz;  // (n_circ,)
    Eigen::VectorXd out = S.transpose() * g;
    for (Eigen::Index k = 0; k < W.rows(); ++k) {
      if ((W.row(k).array() == 1.0).all()) continue;
      const Eigen::VectorXd gk = pr * W.row(k).transpose().cwiseProduct(wz);
      out(k) = S.col(k).dot(gk);
    }
    return out;
  }
};

namespace {

/// base + Σ_k ∂h/∂r_k rc_k on the grid (base: base_h or the clearance when with_base, else
/// 0). Coordinates of weight 1 first, as the untilted film sums them; then the weighted ones
/// (zero tilt adds exact zeros: the untilted film bit for bit).
RowMatrixXd affine_field(const FilmCoupling& fc, const Eigen::VectorXd& rc, bool with_base) {
  const int K1 = fc.grid.n_axial + 1;
  const RowMatrixXd& W = fc.axial_weight;
  Eigen::VectorXd ru = rc;
  for (Eigen::Index k = 0; k < W.rows(); ++k)
    if (!(W.row(k).array() == 1.0).all()) ru(k) = 0.0;
  const Eigen::VectorXd sphi = fc.shape * ru;
  RowMatrixXd h;
  if (!with_base)
    h = sphi.replicate(1, K1);
  else if (fc.base_h.size() == 0)
    h = (sphi.array() + fc.geometry.clearance_m).matrix().replicate(1, K1);
  else if (fc.base_h.cols() == 1)
    h = (fc.base_h.col(0) + sphi).replicate(1, K1);
  else
    h = fc.base_h + sphi.replicate(1, K1);
  for (Eigen::Index k = 0; k < W.rows(); ++k)
    if (!(W.row(k).array() == 1.0).all())
      h.noalias() += fc.shape.col(k) * (rc(k) * W.row(k));
  return h;
}

}  // namespace

RowMatrixXd FilmCoupling::thickness(const Eigen::VectorXd& rc) const {
  return affine_field(*this, rc, true);
}

RowMatrixXd FilmCoupling::thickness_derivative(Eigen::Index k) const {
  const int K1 = grid.n_axial + 1;
  if (axial_weight.size() == 0) return shape.col(k).replicate(1, K1);
  return shape.col(k) * axial_weight.row(k);
}

bool SystemModel::has_table_mass() const {
  for (const TableCoupling& t : tables)
    if (t.M.size()) return true;
  return false;
}

Eigen::MatrixXd SystemModel::mass_at(double omega) const {
  Eigen::MatrixXd out = M;
  Eigen::Matrix2d Kt, Ct, Mt;
  for (const TableCoupling& t : tables) {
    if (!t.M.size()) continue;
    t.at(omega, Kt, Ct, &Mt);
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) out(t.coords[a], t.coords[b]) += Mt(a, b);
  }
  return out;
}

void SystemModel::validate() const {
  const Eigen::Index nn = M.rows();
  require(nn > 0, "system: expected at least one coordinate");
  require(M.cols() == nn, shape_msg("M", nn, nn, M.rows(), M.cols()));
  require(K.rows() == nn && K.cols() == nn, shape_msg("K", nn, nn, K.rows(), K.cols()));
  require(C.rows() == nn && C.cols() == nn, shape_msg("C", nn, nn, C.rows(), C.cols()));
  require(G.rows() == nn && G.cols() == nn, shape_msg("G", nn, nn, G.rows(), G.cols()));
  require(Kc.size() == 0 || (Kc.rows() == nn && Kc.cols() == nn),
          shape_msg("Kc", nn, nn, Kc.rows(), Kc.cols()) + " (or empty: no rotating damping)");
  require(Kc.allFinite(), "Kc: expected finite entries");
  require(Q.size() == nn, shape_msg("Q", nn, 1, Q.size(), 1));
  require(chamber.size() == nn, shape_msg("chamber", nn, 1, chamber.size(), 1));
  for (std::size_t i = 0; i < films.size(); ++i) {
    const auto& f = films[i];
    const std::string w = "films[" + std::to_string(i) + "]";
    f.geometry.validate();
    f.grid.validate();
    require(!f.coords.empty(), w + ".coords: expected at least the journal's x and y");
    for (int c : f.coords)
      require(c >= 0 && c < nn, w + ".coords: expected indices in [0, " + std::to_string(nn - 1) +
                                    "], got " + std::to_string(c));
    require(f.shape.rows() == f.grid.n_circ && f.shape.cols() == static_cast<long>(f.coords.size()),
            shape_msg(w + ".shape", f.grid.n_circ, static_cast<long>(f.coords.size()),
                      f.shape.rows(), f.shape.cols()));
    require(f.base_h.size() == 0 ||
                (f.base_h.rows() == f.grid.n_circ &&
                 (f.base_h.cols() == 1 || f.base_h.cols() == f.grid.n_axial + 1) &&
                 f.base_h.allFinite() && f.base_h.minCoeff() > 0.0),
            w + ".base_h: expected (n_circ, 1) or (n_circ, n_axial + 1) finite values > 0, "
                "or empty");
    require(std::isfinite(f.spin_factor), w + ".spin_factor: expected a finite value");
    require(f.axial_weight.size() == 0 ||
                (f.axial_weight.rows() == static_cast<long>(f.coords.size()) &&
                 f.axial_weight.cols() == f.grid.n_axial + 1),
            shape_msg(w + ".axial_weight", static_cast<long>(f.coords.size()),
                      f.grid.n_axial + 1, f.axial_weight.rows(), f.axial_weight.cols()));
    require(f.axial_weight.allFinite(), w + ".axial_weight: expected finite values");
  }
  for (std::size_t i = 0; i < tables.size(); ++i)
    tables[i].validate("tables[" + std::to_string(i) + "]", nn);
  std::vector<int> group(static_cast<std::size_t>(nn), -1);
  require(pad_pitch.empty() || pad_pitch.size() == pad_coords.size(),
          "pad_pitch: expected one flag per pad group (" + std::to_string(pad_coords.size()) +
              ") or none, got " + std::to_string(pad_pitch.size()));
  for (std::size_t g = 0; g < pad_coords.size(); ++g) {
    const std::string w = "pad_coords[" + std::to_string(g) + "]";
    const auto& pc = pad_coords[g];
    const bool pitch = !pad_pitch.empty() && pad_pitch[g] != 0;
    require(pad_pitch.empty() || pad_pitch[g] == 0 || pad_pitch[g] == 1,
            "pad_pitch[" + std::to_string(g) + "]: expected 0 or 1");
    const std::size_t n_own = pc.size() - (pitch ? 1 : 0);
    require(!pc.empty() && (n_own == 1 || n_own == 2),
            w + (pitch ? ": expected 2 (tilt, pitch) or 3 (tilt, pivot, pitch) coordinates, got "
                       : ": expected 1 (tilt) or 2 (tilt, pivot) coordinates, got ") +
                std::to_string(pc.size()));
    int owner = -1;
    for (int c : pc) {
      require(c >= 0 && c < nn, w + ": expected indices in [0, " + std::to_string(nn - 1) +
                                    "], got " + std::to_string(c));
      require(group[static_cast<std::size_t>(c)] < 0,
              w + ": coordinate " + std::to_string(c) + " is in two pads");
      group[static_cast<std::size_t>(c)] = static_cast<int>(g);
      for (std::size_t i = 0; i < films.size(); ++i) {
        const auto& fc = films[i].coords;
        if (std::find(fc.begin(), fc.end(), c) == fc.end()) continue;
        require(owner < 0 || owner == static_cast<int>(i),
                w + ": coordinate " + std::to_string(c) + " enters more than one film");
        owner = static_cast<int>(i);
      }
      for (const auto& t : tables)
        require(t.coords[0] != c && t.coords[1] != c,
                w + ": coordinate " + std::to_string(c) + " enters a table bearing");
    }
    require(owner >= 0, w + ": the pad's coordinates enter no film");
    if (n_own == 2)
      require(K(pc[1], pc[1]) > 0, w + ": the pivot coordinate needs K(u, u) > 0");
    if (pitch)
      require(K(pc.back(), pc.back()) >= 0, w + ": the pitch coordinate needs K >= 0");
  }
  for (Eigen::Index a = 0; a < nn; ++a)
    for (Eigen::Index b = 0; b < nn; ++b) {
      const int ga = group[static_cast<std::size_t>(a)], gb = group[static_cast<std::size_t>(b)];
      require(ga < 0 || gb < 0 || ga == gb || K(a, b) == 0.0,
              "pad_coords: K couples pads " + std::to_string(ga) + " and " + std::to_string(gb));
    }
}

SystemSolver::SystemSolver(SystemModel model) : model_(std::move(model)) {
  model_.validate();
  for (const auto& f : model_.films) films_.push_back(std::make_unique<Film>(f));
  h_min_.assign(films_.size(), 0.0);
  h_min_angle_.assign(films_.size(), 0.0);
  h_min_z_.assign(films_.size(), 0.0);
  for (std::size_t gi = 0; gi < model_.pad_coords.size(); ++gi) {
    const auto& pc = model_.pad_coords[gi];
    PadGroup g;
    g.coords = pc;
    g.pitch = !model_.pad_pitch.empty() && model_.pad_pitch[gi] != 0;
    for (std::size_t i = 0; i < model_.films.size(); ++i) {
      const auto& fc = model_.films[i].coords;
      const auto it = std::find(fc.begin(), fc.end(), pc[0]);
      if (it == fc.end()) continue;
      g.film = i;
      for (int c : pc)
        g.local.push_back(static_cast<int>(std::find(fc.begin(), fc.end(), c) - fc.begin()));
    }
    pads_.push_back(std::move(g));
  }
}
SystemSolver::~SystemSolver() = default;
SystemSolver::SystemSolver(SystemSolver&&) noexcept = default;
SystemSolver& SystemSolver::operator=(SystemSolver&&) noexcept = default;

const RowMatrixXd& SystemSolver::last_pressure(int film) const {
  require(film >= 0 && film < static_cast<int>(films_.size()),
          "film: expected an index in [0, " + std::to_string(films_.size()) + ")");
  return films_[static_cast<std::size_t>(film)]->p;
}

void SystemSolver::solve_films(const Eigen::VectorXd& r, const Eigen::VectorXd& rdot,
                               double omega) {
  // (the messages are built only on failure: this runs once per transient right-hand side)
  if (r.size() != model_.n()) throw InputError(shape_msg("r", model_.n(), 1, r.size(), 1));
  if (rdot.size() != model_.n())
    throw InputError(shape_msg("rdot", model_.n(), 1, rdot.size(), 1));
  if (solved_ && omega == last_omega_ && r == last_r_ && rdot == last_rdot_) return;
  {  // a speed outside a bearing table is an InputError before any Reynolds solve
    Eigen::Matrix2d Kt, Ct;
    for (const TableCoupling& t : model_.tables) t.at(omega, Kt, Ct);
  }
  solved_ = false;  // stays false if a film throws (contact) below
  for (std::size_t i = 0; i < films_.size(); ++i) {
    const FilmCoupling& fc = model_.films[i];
    Eigen::VectorXd rc(fc.coords.size()), vc(fc.coords.size());
    for (std::size_t k = 0; k < fc.coords.size(); ++k) {
      rc(k) = r(fc.coords[k]);
      vc(k) = rdot(fc.coords[k]);
    }
    solve_one(i, rc, vc, omega);
  }
  solved_ = true;
  last_r_ = r;
  last_rdot_ = rdot;
  last_omega_ = omega;
}

void SystemSolver::solve_one(std::size_t i, const Eigen::VectorXd& rc,
                             const Eigen::VectorXd& vc, double omega) {
  const FilmCoupling& fc = model_.films[i];
  Film& f = *films_[i];
  if (f.valid && omega == f.last_w && rc == f.last_rc && vc == f.last_vc) return;
  f.valid = false;
  f.h = fc.thickness(rc);
  if (!(f.h.minCoeff() > 0.0) || !f.h.allFinite()) {
    std::ostringstream os;
    os << "film '" << fc.name << "': contact, the film thickness reaches " << f.h.minCoeff()
       << " m (clearance " << fc.geometry.clearance_m << " m)";
    throw ContactError(os.str());
  }
  f.dhdt = affine_field(fc, vc, false);  // ∂h/∂t = Σ_k ∂h/∂r_k ṙ_k
  // constant along z: no axial weights and a base film that is one column (or none)
  const bool z_const = fc.axial_weight.size() == 0 && fc.base_h.cols() <= 1;
  const FilmSolution& s = f.solver.solve(f.h, f.dhdt, fc.spin_factor * omega, z_const);
  ++solves_;
  iterations_ += s.iterations;
  f.p = s.p_pa;
  h_min_[i] = s.h_min_m;
  h_min_angle_[i] = s.h_min_angle_deg;
  {  // the axial position of the minimum: the first minimum node in row-major order (the
     // one whose angle the solver reports); 0 where h is uniform along z at that angle (to
     // round-off: a spherical pad's pitch at an aligned journal is a root at ~1e-19 rad)
    Eigen::Index jm = 0, km = 0;
    double best = f.h(0, 0);
    for (Eigen::Index j = 0; j < f.h.rows(); ++j)
      for (Eigen::Index k = 0; k < f.h.cols(); ++k)
        if (f.h(j, k) < best) {
          best = f.h(j, k);
          jm = j;
          km = k;
        }
    const double L = fc.geometry.length_m;
    const double hmax = f.h.row(jm).maxCoeff();
    h_min_z_[i] = hmax - f.h.row(jm).minCoeff() <= 1e-13 * hmax
                      ? 0.0
                      : -0.5 * L + static_cast<double>(km) * L / fc.grid.n_axial;
  }
  f.valid = true;
  f.last_rc = rc;
  f.last_vc = vc;
  f.last_w = omega;
}

Eigen::VectorXd SystemSolver::solve_film(std::size_t i, const Eigen::VectorXd& rc,
                                         double omega) {
  solved_ = false;  // the films no longer all sit at last_r_
  solve_one(i, rc, Eigen::VectorXd::Zero(rc.size()), omega);
  const FilmCoupling& fc = model_.films[i];
  return films_[i]->integrate(films_[i]->p, fc.shape, fc.axial_weight);
}

Eigen::MatrixXd SystemSolver::film_stiffness(std::size_t i, const std::vector<int>& cols) {
  const FilmCoupling& fc = model_.films[i];
  Film& f = *films_[i];
  const int K1 = fc.grid.n_axial + 1;
  const auto nc = static_cast<Eigen::Index>(fc.coords.size());
  const RowMatrixXd zero = RowMatrixXd::Zero(fc.grid.n_circ, K1);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(nc, nc);
  for (const int j : cols) {
    const RowMatrixXd dh = fc.thickness_derivative(j);
    out.col(j) = -f.integrate(f.solver.linearize(dh, zero), fc.shape, fc.axial_weight);
  }
  return out;
}

void SystemSolver::set_film_continuation(bool on) {
  for (auto& f : films_) {
    f->solver.set_continuation(on);
    f->valid = false;
  }
  solved_ = false;
  carry_ = on;
}

void SystemSolver::carry_sets(bool on) {
  for (auto& f : films_) f->solver.set_continuation(on);
}

void SystemSolver::set_film_carry(bool on) {
  carry_sets(on);
  carry_ = on;
}

void SystemSolver::set_refine_prediction(bool on) {
  for (auto& f : films_) {
    f->solver.set_refine_prediction(on);
    f->valid = false;
  }
  solved_ = false;
}

void SystemSolver::forget_state() {
  set_film_continuation(false);  // forgets the sets, invalidates each film's and the last solve
}

SystemSolver::ThinnestFilm SystemSolver::thinnest_film() const {
  ThinnestFilm t;
  for (std::size_t i = 0; i < h_min_.size(); ++i) {
    if (std::isnan(h_min_[i])) {
      t.film = static_cast<int>(i);
      break;
    }
    if (t.film < 0 || h_min_[i] < h_min_[static_cast<std::size_t>(t.film)])
      t.film = static_cast<int>(i);
  }
  if (t.film >= 0) {
    const auto i = static_cast<std::size_t>(t.film);
    t.h_min_m = h_min_[i];
    t.h_min_angle_deg = h_min_angle_[i];
    t.h_min_z_m = h_min_z_[i];
  }
  return t;
}

std::vector<double> SystemSolver::film_h_min(const Eigen::VectorXd& r) const {
  if (r.size() != model_.n()) throw InputError(shape_msg("r", model_.n(), 1, r.size(), 1));
  std::vector<double> out(model_.films.size());
  for (std::size_t i = 0; i < model_.films.size(); ++i) {
    const FilmCoupling& fc = model_.films[i];
    double hmin = INFINITY;
    if (fc.axial_weight.size() != 0) {  // h varies along z with the coordinates
      Eigen::VectorXd rc(fc.coords.size());
      for (std::size_t k = 0; k < fc.coords.size(); ++k) rc(k) = r(fc.coords[k]);
      out[i] = fc.thickness(rc).minCoeff();
      continue;
    }
    for (Eigen::Index j = 0; j < fc.shape.rows(); ++j) {
      // h = base_h + S r, as solve_one builds it (base_h: lobes, preload, pads, dam step)
      double base = fc.geometry.clearance_m;
      if (fc.base_h.size() != 0) base = fc.base_h.row(j).minCoeff();
      double h = base;
      for (std::size_t k = 0; k < fc.coords.size(); ++k)
        h += fc.shape(j, static_cast<Eigen::Index>(k)) * r(fc.coords[k]);
      hmin = std::min(hmin, h);
    }
    out[i] = hmin;
  }
  return out;
}

Eigen::VectorXd SystemSolver::film_forces(const Eigen::VectorXd& r, const Eigen::VectorXd& rdot,
                                          double omega) {
  solve_films(r, rdot, omega);
  Eigen::VectorXd H = Eigen::VectorXd::Zero(model_.n());
  for (std::size_t i = 0; i < films_.size(); ++i) {
    const FilmCoupling& fc = model_.films[i];
    const Eigen::VectorXd hk = films_[i]->integrate(films_[i]->p, fc.shape, fc.axial_weight);
    for (std::size_t k = 0; k < fc.coords.size(); ++k) H(fc.coords[k]) += hk(k);
  }
  add_table_forces(r, rdot, omega, H);
  return H;
}

void SystemSolver::linearize_last_solve(bool damping, Eigen::MatrixXd& KH,
                                        Eigen::MatrixXd* DH) {
  const Eigen::Index n = model_.n();
  ++linearizations_;
  KH = Eigen::MatrixXd::Zero(n, n);
  if (damping) *DH = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t i = 0; i < films_.size(); ++i) {
    const FilmCoupling& fc = model_.films[i];
    Film& f = *films_[i];
    // every column's linearised solve at once (the values of one linearize() call each)
    const std::size_t nc = fc.coords.size(), per = damping ? 2 : 1;
    std::vector<const RowMatrixXd*> a, b;
    for (std::size_t j = 0; j < nc; ++j) {
      a.push_back(&f.dh[j]);
      b.push_back(&f.zero);
      if (!damping) continue;
      a.push_back(&f.zero);
      b.push_back(&f.dh[j]);
    }
    std::vector<RowMatrixXd> dp;
    f.solver.linearize_many(a, b, dp, fc.axial_weight.size() == 0);  // dh = S(φ) along z
    for (std::size_t j = 0; j < nc; ++j) {
      const Eigen::VectorXd dk = -f.integrate(dp[per * j], fc.shape, fc.axial_weight);
      for (std::size_t k = 0; k < nc; ++k) KH(fc.coords[k], fc.coords[j]) += dk(k);
      if (!damping) continue;
      const Eigen::VectorXd dd = -f.integrate(dp[per * j + 1], fc.shape, fc.axial_weight);
      for (std::size_t k = 0; k < nc; ++k) (*DH)(fc.coords[k], fc.coords[j]) += dd(k);
    }
  }
  add_table_coefficients(last_omega_, KH, DH);
}

void SystemSolver::add_table_forces(const Eigen::VectorXd& r, const Eigen::VectorXd& rdot,
                                    double omega, Eigen::VectorXd& H) const {
  Eigen::Matrix2d Kt, Ct;
  for (const TableCoupling& t : model_.tables) {
    t.at(omega, Kt, Ct);
    const Eigen::Vector2d q(r(t.coords[0]), r(t.coords[1]));
    const Eigen::Vector2d v(rdot(t.coords[0]), rdot(t.coords[1]));
    const Eigen::Vector2d f = -Kt * q - Ct * v;
    H(t.coords[0]) += f(0);
    H(t.coords[1]) += f(1);
  }
  if (model_.Kc.size()) H.noalias() -= omega * (model_.Kc * r);  // rotating shaft damping
}

void SystemSolver::add_table_coefficients(double omega, Eigen::MatrixXd& KH,
                                          Eigen::MatrixXd* DH) const {
  Eigen::Matrix2d Kt, Ct;
  for (const TableCoupling& t : model_.tables) {
    t.at(omega, Kt, Ct);
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) {
        KH(t.coords[a], t.coords[b]) += Kt(a, b);
        if (DH) (*DH)(t.coords[a], t.coords[b]) += Ct(a, b);
      }
  }  if (model_.Kc.size()) KH += omega * model_.Kc;
}

Linearization SystemSolver::linearize(const Eigen::VectorXd& r, const Eigen::VectorXd& rdot,
                                      double omega) {
  Linearization out;
  out.film_force = film_forces(r, rdot, omega);
  linearize_last_solve(true, out.KH, &out.DH);
  return out;
}

Linearization SystemSolver::linearize_fd(const Eigen::VectorXd& r, double omega,
                                         double rel_step) {
  require(rel_step >= 1e-10 && rel_step < 0.1,
          "rel_step: expected 1e-10 <= rel_step < 0.1 (a smaller step is lost in round-off)");
  const Eigen::Index n = model_.n();
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(n);
  Linearization out;
  out.film_force = film_forces(r, zero, omega);
  out.KH = Eigen::MatrixXd::Zero(n, n);
  out.DH = Eigen::MatrixXd::Zero(n, n);
  const double wref = std::abs(omega) > 0 ? std::abs(omega) : 1.0;
  std::vector<char> differenced(static_cast<std::size_t>(n), 0);
  for (const FilmCoupling& fc : model_.films) {
    for (int j : fc.coords) {
      if (out.KH.col(j).cwiseAbs().sum() != 0.0) continue;  // already done (shared coordinate)
      differenced[static_cast<std::size_t>(j)] = 1;
      const double dx = rel_step * fc.geometry.clearance_m, dv = dx * wref;
      // A step lost in round-off (r ± dx == r) would give K_H = D_H = 0 with no error
      // (issue 13: rel_step = 1e-300): refuse steps that r(j) cannot resolve to 1 %.
      const double span = (r(j) + dx) - (r(j) - dx);
      require(std::abs(span - 2 * dx) <= 0.01 * 2 * dx && std::isfinite(dv) && dv > 0,
              "rel_step: the step " + std::to_string(dx) + " m is below the round-off of the "
              "coordinate " + std::to_string(r(j)) + " m; use rel_step >= 1e-10");
      Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
      e(j) = dx;
      out.KH.col(j) = -(film_forces(r + e, zero, omega) - film_forces(r - e, zero, omega)) /
                      (2 * dx);
      e(j) = dv;
      out.DH.col(j) = -(film_forces(r, e, omega) - film_forces(r, -e, omega)) / (2 * dv);
    }
  }
  // Tables are linear: their coefficients enter exactly (the differences above skip them
  // unless a film shares the coordinate, whose columns then hold both: subtract nothing).
  for (const TableCoupling& t : model_.tables) {
    Eigen::Matrix2d Kt, Ct;
    t.at(omega, Kt, Ct);
    for (int b = 0; b < 2; ++b) {
      const int j = t.coords[b];
      if (out.KH.col(j).cwiseAbs().sum() != 0.0) continue;  // differenced with a film above
      for (int a = 0; a < 2; ++a) {
        out.KH(t.coords[a], j) += Kt(a, b);
        out.DH(t.coords[a], j) += Ct(a, b);
      }
    }
  }
  // The shaft's circulatory Ω Kc (rotating damping) is linear too: exactly in every column
  // not differenced above (those hold it already, through H).
  if (model_.Kc.size())
    for (Eigen::Index j = 0; j < n; ++j)
      if (!differenced[static_cast<std::size_t>(j)]) out.KH.col(j) += omega * model_.Kc.col(j);
  film_forces(r, zero, omega);  // leave the solvers at the operating point
  return out;
}

void SystemSolver::set_film_viscosity(int film, double viscosity_pa_s) {
  if (film < 0 || film >= static_cast<int>(films_.size()))
    throw InputError("film: expected a film index in [0, " + std::to_string(films_.size()) +
                     "), got " + std::to_string(film));
  Film& f = *films_[static_cast<std::size_t>(film)];
  f.solver.set_viscosity(viscosity_pa_s);  // InputError naming viscosity_pa_s
  model_.films[static_cast<std::size_t>(film)].geometry.viscosity_pa_s = viscosity_pa_s;
  model_.films[static_cast<std::size_t>(film)].viscosity_field.resize(0, 0);  // uniform
  f.valid = false;
  solved_ = false;
}

void SystemSolver::set_film_viscosity_field(int film, const RowMatrixXd& viscosity_pa_s) {
  if (film < 0 || film >= static_cast<int>(films_.size()))
    throw InputError("film: expected a film index in [0, " + std::to_string(films_.size()) +
                     "), got " + std::to_string(film));
  Film& f = *films_[static_cast<std::size_t>(film)];
  f.solver.set_viscosity_field(viscosity_pa_s);  // InputError naming viscosity_pa_s
  model_.films[static_cast<std::size_t>(film)].viscosity_field = viscosity_pa_s;
  f.valid = false;
  solved_ = false;
}

}  // namespace rotordyn
