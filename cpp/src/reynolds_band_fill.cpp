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
bool ReynoldsSolver::Impl::fill_band(LinearSystem& S, const char* mk, int cut) {
  BandLDLT& B = S.band;
  B.begin(cut);  // the whole band cleared in one pass (not b + 1 values per column)
  const int w = B.bandwidth() + 1;
  for (int i = 0; i < S.n_unk; ++i) {
    const int ci = B.opened(i);
    double* col = B.column(ci);
    if (mk && mk[i]) {
      col[0] = 1.0;
      continue;
    }
    const int n = S.node_of[i];
    const int wn = west(n);
    const double wp = S.wphi[i];
    double d;
    if (S.has_s[i])
      d = wp * (cE[n] + cE[wn]) + (S.has_n[i] ? cN[n] : 0.0) + cN[n - 1];
    else
      d = wp * (cE[n] + cE[wn]) + cN[n];
    if (end_row(n)) d += gseal;
    col[0] = d;
    const LinearSystem::ColPos& q = S.pos[i];
    const LinearSystem::Nbr& u = S.nbr[i];
    if (q.n >= 0 && !(mk && mk[u.n])) {
      const int dn = B.opened(u.n) - ci;
      if (dn <= 0 || dn >= w) return false;
      col[dn] = -cN[n];
    }
    if (q.e >= 0 && !(mk && mk[u.e])) {
      const int de = B.opened(u.e) - ci;
      if (de <= 0 || de >= w) return false;
      col[de] = -(wp * cE[n]);
    }
  }
  return true;
}

}  // namespace rotordyn
