// ReynoldsSolver: assembly and factorisation of the masked operator (the banded path and the
// sparse path).
#include <algorithm>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

void ReynoldsSolver::Impl::factor_spd(LinearSystem& S, const std::vector<char>* mask) {
  if (band_factor && S.use_band) {
    // A ring whose unknowns are all decoupled (or that has none) opens the circle.
    const char* mk = mask ? mask->data() : nullptr;
    int cut = -1;
    for (int j = 0; j < N && cut < 0; ++j) {
      bool all = true;
      for (int i = S.ring_first[j]; i < S.ring_first[j + 1] && all; ++i) all = mk && mk[i];
      if (all) cut = j;
    }
    if (cut >= 0 && fill_band(S, mk, cut) && S.band.factorize_assembled()) {
      S.factor = LinearSystem::Factor::band;
      return;
    }
  }
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
// it crosses the opening, i.e. unless its column is within d of the end.
bool ReynoldsSolver::Impl::fill_band(LinearSystem& S, const char* mk, int cut) {
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
  B.begin(cut);  // the whole band cleared in one pass (not b + 1 values per column)
  const LinearSystem::FillEntry* tab = S.fill_tab.data();
  const double* ce = cE.data();
  const double* cn = cN.data();
  // unknowns shift..n-1 are columns 0..n-shift-1, unknowns 0..shift-1 the rest
  const int shift = S.ring_first[cut];
  bool ok = true;
  auto range = [&](int i0, int i1, int c0) {
    for (int i = i0, ci = c0; i < i1; ++i, ++ci) {
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
      if (f.un >= 0 && !(mk && mk[f.un])) {
        if (ci + f.dn >= nu) ok = false;  // across the opening
        col[f.dn] = -cn[n];
      }
      if (f.ue >= 0 && !(mk && mk[f.ue])) {
        if (ci + f.de >= nu) ok = false;
        col[f.de] = -(f.wp * ce[n]);
      }
    }
  };
  range(shift, nu, 0);
  range(0, shift, nu - shift);
  return ok;
}

}  // namespace rotordyn
