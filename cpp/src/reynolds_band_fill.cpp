// ReynoldsSolver: assembly and factorisation of the masked operator (the banded path and the
// sparse path).
#include <algorithm>
#include <type_traits>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

void ReynoldsSolver::Impl::factor_spd(LinearSystem& S, const std::vector<char>* mask,
                                      const BandReuse* reuse) {
  if (band_factor && S.use_band) {
    // A ring whose unknowns are all decoupled (or that has none) opens the circle: the
    // ring asked for while it stays decoupled, else the first from j = 0.
    const char* mk = mask ? mask->data() : nullptr;
    auto decoupled = [&](int j) {
      bool all = true;
      for (int i = S.ring_first[j]; i < S.ring_first[j + 1] && all; ++i) all = mk && mk[i];
      return all;
    };
    // Full grid: the factor order runs against the rotation. The active-set iterations after
    // the first mostly move the reformation boundary (the film front creeping upstream a ring
    // per iteration), which then comes last among the film's columns, followed only by
    // cavitated (skipped) ones, and the factorisation resumes there (below); the opening is
    // kept through the iterations while its ring stays decoupled. The half grid keeps the
    // order +j from the first decoupled ring and full refactorisations (no gain measured
    // there; its answers stay those of that order bit for bit).
    const bool resumable = !S.half && omega != 0.0;
    const bool rev = resumable && omega > 0.0;
    const bool ckpt = resumable && reuse && reuse->checkpoints;
    int cut = -1;
    if (resumable && reuse && reuse->keep_cut >= 0 && decoupled(reuse->keep_cut))
      cut = reuse->keep_cut;
    for (int j = 0; j < N && cut < 0; ++j)
      if (decoupled(j)) cut = j;
    BandLDLT& B = S.band;
    if (cut >= 0 && ckpt && reuse->prev && band_resume && mk &&
        S.factor == LinearSystem::Factor::band && B.resumable(cut, rev)) {
      // Same film, a changed mask, the same opening: the factor's columns before the first
      // one the change touches stay (an unknown's couplings lie in its column and the b
      // before it); resumed at the last checkpoint c0 with columns c0 .. c0 + b − 1 untouched.
      const int b = B.bandwidth(), nu = S.n_unk;
      const char* pv = reuse->prev->data();
      int cmin = nu;  // < nu: the caller passes prev only for a changed mask
      for (int i = 0; i < nu; ++i)
        if (pv[i] != mk[i]) cmin = std::min(cmin, B.opened(i));
      const int ks = B.checkpoint_stride();
      const int c0 = cmin >= 2 * b ? ((cmin - 2 * b) / ks) * ks : 0;
      if (c0 > 0 && fill_band(S, mk, cut, rev, c0 + b) && B.refactorize_from(c0, ckpt)) {
        S.band_cut = cut;
        ++band_resumed;
        return;
      }
    }
    if (cut >= 0 && fill_band(S, mk, cut, rev) && B.factorize_assembled(ckpt)) {
      S.factor = LinearSystem::Factor::band;
      S.band_cut = cut;
      return;
    }
  }
  S.band_cut = -1;
  fill_spd(S, mask);
  // Decoupled (cavitated) unknowns have zero couplings: StaticLDLT skips their work.
  if (!S.ldlt.factorize(S.A.valuePtr()))
    throw ConvergenceError("Reynolds operator: sparse LDLT factorisation failed (zero pivot)");
  S.factor = LinearSystem::Factor::ldlt;
}

// The values of fill_spd(S, mask) written straight into the band, column by column: each
// coupling once, in the column of its west or south end (the earlier one in the opened order;
// equal values from both ends), a masked unknown an identity column. False when a coupling
// falls outside the band or across the opening (the caller then uses the sparse factor).
// The neighbours' forward distances (mod n, the same in every opened order) are tabulated
// once per system: a coupling to an unmasked neighbour at distance d lies in the band unless
// it crosses the opening, i.e. unless its column is within d of the end (forward), or before
// the d-th (reverse order: a coupling lies in its later unknown's column, which is the
// neighbour's, d columns before its own). c_from > 0: columns c_from .. n − 1 only (a resumed
// factorisation, the same opening; a reverse one also writes into the b columns before).
bool ReynoldsSolver::Impl::fill_band(LinearSystem& S, const char* mk, int cut, bool rev,
                                     int c_from) {
  BandLDLT& B = S.band;
  const int w = B.bandwidth() + 1, nu = S.n_unk;
  if (S.fill_tab.size() != static_cast<std::size_t>(nu)) {
    S.fill_tab.resize(nu);
    S.fill_tab_ok = true;
    for (int i = 0; i < nu; ++i) {
      const int n = S.node_of[i];
      LinearSystem::FillEntry& f = S.fill_tab[i];
      f.n = n;
      f.wn = west(n);
      f.has_s = S.has_s[i];
      f.has_n = S.has_n[i];
      f.seal = end_row(n);
      f.wp = S.wphi[i];
      const LinearSystem::ColPos& q = S.pos[i];
      const LinearSystem::Nbr& u = S.nbr[i];
      f.un = q.n >= 0 ? u.n : -1;
      f.ue = q.e >= 0 ? u.e : -1;
      f.dn = f.un >= 0 ? ((f.un - i) % nu + nu) % nu : 0;
      f.de = f.ue >= 0 ? ((f.ue - i) % nu + nu) % nu : 0;
      if ((f.un >= 0 && (f.dn <= 0 || f.dn >= w)) || (f.ue >= 0 && (f.de <= 0 || f.de >= w)))
        S.fill_tab_ok = false;
    }
  }
  if (!S.fill_tab_ok) return false;  // a coupling outside the band in every opening
  // the whole band cleared in one pass (not b + 1 values per column)
  if (c_from > 0)
    B.begin_from(c_from);
  else
    B.begin(cut, rev);
  const LinearSystem::FillEntry* tab = S.fill_tab.data();
  const double* ce = cE.data();
  const double* cn = cN.data();
  bool ok = true;
  // unknowns i0 .. i1 − 1 in columns c0, c0 + step, ...
  auto range = [&](int i0, int i1, int c0, auto step) {
    constexpr int st = decltype(step)::value;
    for (int i = i0, ci = c0; i < i1; ++i, ci += st) {
      double* col = B.column(ci);
      if (mk && mk[i]) {
        col[0] = 1.0;
        continue;
      }
      const LinearSystem::FillEntry& f = tab[i];
      const int n = f.n;
      double d;
      if (f.has_s)
        d = f.wp * (ce[n] + ce[f.wn]) + (f.has_n ? cn[n] : 0.0) + cn[n - 1];
      else
        d = f.wp * (ce[n] + ce[f.wn]) + cn[n];
      if (f.seal) d += gseal;
      col[0] = d;
      if (st > 0) {
        if (f.un >= 0 && !(mk && mk[f.un])) {
          if (ci + f.dn >= nu) ok = false;  // across the opening
          col[f.dn] = -cn[n];
        }
        if (f.ue >= 0 && !(mk && mk[f.ue])) {
          if (ci + f.de >= nu) ok = false;
          col[f.de] = -(f.wp * ce[n]);
        }
      } else {
        if (f.un >= 0 && !(mk && mk[f.un])) {
          if (ci - f.dn < 0) ok = false;  // across the opening
          else B.column(ci - f.dn)[f.dn] = -cn[n];
        }
        if (f.ue >= 0 && !(mk && mk[f.ue])) {
          if (ci - f.de < 0) ok = false;
          else B.column(ci - f.de)[f.de] = -(f.wp * ce[n]);
        }
      }
    }
  };
  using fwd = std::integral_constant<int, 1>;
  using bwd = std::integral_constant<int, -1>;
  if (!rev) {
    // unknowns shift..n-1 are columns 0..n-shift-1, unknowns 0..shift-1 the rest
    const int shift = S.ring_first[cut];
    if (c_from <= nu - shift) {
      range(shift + c_from, nu, c_from, fwd{});
      range(0, shift, nu - shift, fwd{});
    } else {
      range(c_from - (nu - shift), shift, c_from, fwd{});
    }
  } else {
    // unknowns shift−1..0 are columns 0..shift−1, unknowns n−1..shift the rest (shift one
    // past ring cut's last unknown); columns >= c_from are unknowns below shift − c_from
    // (first piece) or below n + shift − c_from (second)
    const int shift = S.ring_first[cut + 1];
    if (c_from <= shift) {
      range(0, shift - c_from, shift - 1, bwd{});
      range(shift, nu, nu - 1, bwd{});
    } else {
      range(shift, nu + shift - c_from, nu - 1, bwd{});
    }
  }
  return ok;
}

}  // namespace rotordyn
