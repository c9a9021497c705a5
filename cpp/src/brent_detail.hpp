// Internal root finder shared by the threshold search (threshold.cpp: SciPy's brentq, its
// steps and messages) and the starved film's groove state (reynolds_starved.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rotordyn::brent_detail {

/// A bad tolerance or no sign change (named "ValueError" by the threshold's messages, as
/// SciPy's brentq raises it).
struct ValueFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Brent's method as SciPy's brentq (xtol, rtol, maxiter; the same steps): the root of g in
/// [xa, xb]; ValueFailure on a bad tolerance or no sign change, std::runtime_error when
/// maxiter is exhausted. `ftol` > 0 also stops where |g| <= ftol (0: brentq's own test,
/// g == 0, the same steps bit for bit).
template <class G>
double brent(G&& g, double xa, double xb, double xtol, double rtol, int maxiter,
             double ftol = 0.0) {
  if (!(xtol > 0)) {
    std::ostringstream os;
    os << "xtol too small (" << xtol << " <= 0)";
    throw ValueFailure(os.str());
  }
  double xpre = xa, xcur = xb, xblk = 0.0, fblk = 0.0, spre = 0.0, scur = 0.0;
  double fpre = g(xpre), fcur = g(xcur);
  if (std::abs(fpre) <= ftol) return xpre;
  if (std::abs(fcur) <= ftol) return xcur;
  if (std::signbit(fpre) == std::signbit(fcur))
    throw ValueFailure("f(a) and f(b) must have different signs");
  for (int i = 0; i < maxiter; ++i) {
    if (fpre != 0 && fcur != 0 && std::signbit(fpre) != std::signbit(fcur)) {
      xblk = xpre;
      fblk = fpre;
      spre = scur = xcur - xpre;
    }
    if (std::abs(fblk) < std::abs(fcur)) {
      xpre = xcur;
      xcur = xblk;
      xblk = xpre;
      fpre = fcur;
      fcur = fblk;
      fblk = fpre;
    }
    const double delta = (xtol + rtol * std::abs(xcur)) / 2;
    const double sbis = (xblk - xcur) / 2;
    if (std::abs(fcur) <= ftol || std::abs(sbis) < delta) return xcur;
    if (std::abs(spre) > delta && std::abs(fcur) < std::abs(fpre)) {
      double stry;
      if (xpre == xblk) {
        stry = -fcur * (xcur - xpre) / (fcur - fpre);  // secant
      } else {  // inverse quadratic
        const double dpre = (fpre - fcur) / (xpre - xcur);
        const double dblk = (fblk - fcur) / (xblk - xcur);
        stry = -fcur * (fblk * dblk - fpre * dpre) / (dblk * dpre * (fblk - fpre));
      }
      if (2 * std::abs(stry) < std::min(std::abs(spre), 3 * std::abs(sbis) - delta)) {
        spre = scur;
        scur = stry;
      } else {
        spre = sbis;
        scur = sbis;
      }
    } else {
      spre = sbis;
      scur = sbis;
    }
    xpre = xcur;
    fpre = fcur;
    xcur += std::abs(scur) > delta ? scur : (sbis > 0 ? delta : -delta);
    fcur = g(xcur);
  }
  std::ostringstream os;
  os.precision(6);
  os << std::fixed << "Failed to converge after " << maxiter << " iterations, value is " << xcur;
  throw std::runtime_error(os.str());
}

}  // namespace rotordyn::brent_detail
