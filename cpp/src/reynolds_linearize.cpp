// ReynoldsSolver: several frozen-set linearised solves at once (the K_H/D_H columns of a
// film, SystemSolver::linearize_last_solve): the same values as one linearize() each.
#include <algorithm>
#include <cmath>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

void ReynoldsSolver::Impl::residual_derivative_many(const LinearSystem& S,
                                                   const std::vector<const double*>& dh,
                                                   const std::vector<const double*>& dhdot,
                                                   const std::vector<Eigen::VectorXd*>& outv)
    const {
  const std::vector<double>& P =
      (cav == Cavitation::none || cav == Cavitation::gumbel) ? pfull : p;
  const double fE = 3.0 * dz / (12.0 * mu * R * dphi);
  const double fN = 3.0 * R * dphi / (12.0 * mu * dz);
  const double fq = 0.5 * omega * R * dz;
  const double fs = R * dphi * dz;
  const bool fwd = omega >= 0.0;
  const int nu = S.n_unk;
  // per unknown: the four faces' conductance derivatives (fE h_f², turbulence and viscosity
  // multipliers applied as residual_derivative_t does), their pressure differences, and the
  // fills the Couette terms take
  struct Row {
    int n, e, w;
    double ge, gw, gn, gs, pe, pw, pn, ps, ta, tb, wp;
  };
  std::vector<Row> rows(static_cast<std::size_t>(nu));
  auto tmul = [&](double hf, bool axial, int q) {
    double mm, dm;
    turb_face(hf, axial, q, mm, dm);
    return dm;
  };
  for (int i = 0; i < nu; ++i) {
    const int n = S.node_of[i];
    const int e = east(n), w = west(n);
    const double he = 0.5 * (h[n] + h[e]), hw = 0.5 * (h[w] + h[n]);
    const double hn = 0.5 * (h[n] + h[n + 1]), hs = 0.5 * (h[n - 1] + h[n]);
    double ge = fE * he * he, gw = fE * hw * hw, gn = fN * hn * hn, gs = fN * hs * hs;
    if (turb) {
      ge *= tmul(he, false, n);
      gw *= tmul(hw, false, w);
      gn *= tmul(hn, true, n);
      gs *= tmul(hs, true, n - 1);
    }
    if (visc_field) {
      ge *= vmE[n];
      gw *= vmE[w];
      gn *= vmN[n];
      gs *= vmN[n - 1];
    }
    rows[static_cast<std::size_t>(i)] =
        Row{n, e, w, ge, gw, gn, gs, P[n] - P[e], P[n] - P[w], P[n] - P[n + 1],
            P[n] - P[n - 1], fwd ? theta[n] : theta[e], fwd ? theta[w] : theta[n], S.wphi[i]};
  }
  for (std::size_t v = 0; v < dh.size(); ++v) {
    const double* d = dh[v];
    const double* dd = dhdot[v];
    Eigen::VectorXd& o = *outv[v];
    o.resize(nu);
    for (int i = 0; i < nu; ++i) {
      const Row& q = rows[static_cast<std::size_t>(i)];
      const int n = q.n;
      const double dhe = 0.5 * (d[n] + d[q.e]), dhw = 0.5 * (d[q.w] + d[n]);
      const double dhn = 0.5 * (d[n] + d[n + 1]), dhs = 0.5 * (d[n - 1] + d[n]);
      double r = q.ge * dhe * q.pe + q.gw * dhw * q.pw + q.gn * dhn * q.pn + q.gs * dhs * q.ps;
      r += fq * (dhe * q.ta - dhw * q.tb);
      r += fs * dd[n] * theta[n];
      o[i] = q.wp * r;
    }
  }
}

void ReynoldsSolver::linearize_many(const std::vector<const RowMatrixXd*>& dh,
                                    const std::vector<const RowMatrixXd*>& d_dhdt,
                                    std::vector<RowMatrixXd>& dp, bool z_constant) {
  Impl& s = *impl_;
  const std::size_t m = dh.size();
  if (d_dhdt.size() != m)
    throw InputError("linearize_many: expected as many d_dhdt fields as dh fields");
  dp.resize(m);
  for (std::size_t v = 0; v < m; ++v) {
    if (dh[v]->rows() != s.N || dh[v]->cols() != s.K1)
      throw InputError(shape_msg("dh", s.N, s.K1, dh[v]->rows(), dh[v]->cols()));
    if (d_dhdt[v]->rows() != s.N || d_dhdt[v]->cols() != s.K1)
      throw InputError(shape_msg("d_dhdt", s.N, s.K1, d_dhdt[v]->rows(), d_dhdt[v]->cols()));
  }
  bool fast = s.solved && !s.geo.short_bearing && s.cav != Cavitation::jfo && s.sys &&
              (s.sys->factor == LinearSystem::Factor::ldlt ||
               s.sys->factor == LinearSystem::Factor::band) &&
              !(s.cav == Cavitation::reynolds && s.n_biactive > 0);
  if (fast && s.sys->half && !z_constant) {  // linearize() would switch to the full system
    const RowMatrixXd* last = nullptr;
    for (std::size_t v = 0; v < m && fast; ++v) {
      if (dh[v] != last && !s.symmetric(dh[v]->data())) fast = false;
      if (fast && d_dhdt[v] != dh[v] && !s.symmetric(d_dhdt[v]->data())) fast = false;
      last = d_dhdt[v];
    }
  }
  if (!fast) {
    for (std::size_t v = 0; v < m; ++v) dp[v] = linearize(*dh[v], *d_dhdt[v]);
    return;
  }
  const LinearSystem& S = *s.sys;
  const int nu = S.n_unk;
  std::vector<Eigen::VectorXd> r(m);
  const double fs = s.R * s.dphi * s.dz;  // as residual_derivative_t
  std::vector<const double*> gdh, gdhd;  // the columns with a film-thickness change
  std::vector<Eigen::VectorXd*> gout;
  const RowMatrixXd* zero_seen = nullptr;  // a field found zero (callers pass one zero field)
  for (std::size_t v = 0; v < m; ++v) {
    const bool dh_zero = dh[v] == zero_seen || (dh[v]->array() == 0.0).all();
    if (dh_zero) zero_seen = dh[v];
    if (!s.sealed && dh_zero) {
      // dh = 0: every term of residual_derivative but the squeeze one is a product with a
      // face's dh (±0), so its value is the squeeze term alone (linearize_trig4)
      r[v].resize(nu);
      const double* hd = d_dhdt[v]->data();
      for (int i = 0; i < nu; ++i) {
        const int n = S.node_of[i];
        r[v][i] = S.wphi[i] * (fs * hd[n] * s.theta[n]);
      }
    } else if (!s.sealed && !s.has_pockets) {
      gdh.push_back(dh[v]->data());
      gdhd.push_back(d_dhdt[v]->data());
      gout.push_back(&r[v]);
    } else {
      s.residual_derivative(S, dh[v]->data(), d_dhdt[v]->data(), r[v]);
    }
  }
  if (gout.size() == 1)
    s.residual_derivative(S, gdh[0], gdhd[0], *gout[0]);
  else if (!gout.empty())
    s.residual_derivative_many(S, gdh, gdhd, gout);
  for (std::size_t v = 0; v < m; ++v) {
    if (s.cav == Cavitation::reynolds)
      for (int i = 0; i < nu; ++i)
        if (S.active[i]) r[v][i] = 0.0;
    r[v] = -r[v];
  }
  // the solves, four at a time (a remainder of two or three padded with zero vectors)
  Eigen::VectorXd pad[3];
  for (std::size_t v0 = 0; v0 < m; v0 += 4) {
    const std::size_t left = m - v0;
    if (left == 1) {
      S.solve_spd(r[v0].data(), r[v0].data());
      break;
    }
    double* x[4];
    for (std::size_t q = 0; q < 4; ++q) {
      if (q < left) {
        x[q] = r[v0 + q].data();
      } else {
        pad[q - 1].setZero(nu);
        x[q] = pad[q - 1].data();
      }
    }
    S.solve_spd4(x);
  }
  // as linearize(): gumbel's one-sided mean where p_full vanishes to round-off
  double pmax = 0.0;
  if (s.cav == Cavitation::gumbel)
    for (int n = 0; n < s.n_nodes; ++n) pmax = std::max(pmax, std::abs(s.pfull[n]));
  const double ptol = 1e-10 * pmax;
  for (std::size_t v = 0; v < m; ++v) {
    dp[v] = RowMatrixXd::Zero(s.N, s.K1);
    double* dpd = dp[v].data();
    for (int i = 0; i < nu; ++i) {
      const int n = S.node_of[i];
      double wgt = 1.0;
      if (s.cav == Cavitation::gumbel)
        wgt = s.pfull[n] > ptol ? 1.0 : (s.pfull[n] < -ptol ? 0.0 : 0.5);
      if (s.cav == Cavitation::reynolds && S.active[i]) wgt = 0.0;
      dpd[n] = wgt * r[v][i];
    }
    if (S.half)
      for (int j = 0; j < s.N; ++j)
        for (int k = s.Kh + 1; k < s.mirror_end(); ++k)
          dpd[j * s.K1 + k] = dpd[j * s.K1 + s.K1 - 1 - k];  // the mirror node
  }
}

}  // namespace rotordyn
