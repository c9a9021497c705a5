// Turbulent lubrication coefficients (Ng & Pan 1965; Elrod & Ng 1967; curve fits of Taylor &
// Dowson 1974, J. Lubr. Technol. 96(1) 36-46) and the film's turbulent conductances.
#include <cmath>

#include "reynolds_impl.hpp"
#include "rotordyn/errors.hpp"

namespace rotordyn {

Turbulence parse_turbulence(const std::string& name) {
  if (name == "laminar") return Turbulence::laminar;
  if (name == "ng_pan") return Turbulence::ng_pan;
  throw InputError("turbulence: expected one of 'laminar', 'ng_pan', got '" + name + "'");
}

const char* turbulence_name(Turbulence t) {
  switch (t) {
    case Turbulence::laminar:
      return "laminar";
    case Turbulence::ng_pan:
      return "ng_pan";
  }
  return "?";
}

double couette_shear_factor(Turbulence model, double re, double onset, double full) {
  if (model == Turbulence::laminar || !(re > 0.0)) return 1.0;  // Re = 0: exactly laminar
  const double g = turbulence_weight(re, onset, full, nullptr);
  if (g == 0.0) return 1.0;  // below the transition's onset: exactly laminar
  const double inc = 0.0012 * std::pow(re, 0.94);
  return g == 1.0 ? 1.0 + inc : 1.0 + g * inc;
}

TurbulenceFactors turbulence_factors(Turbulence model, double re) {
  TurbulenceFactors f;
  if (model == Turbulence::laminar || !(re > 0.0)) return f;  // Re = 0: exactly laminar
  // k = 12 + a Re^b; Re dk/dRe = a b Re^b (the h-derivative of the conductance h³/k)
  const double ax = 0.0136 * std::pow(re, 0.90), az = 0.0043 * std::pow(re, 0.96);
  f.kx = 12.0 + ax;
  f.kz = 12.0 + az;
  f.cf = couette_shear_factor(model, re);
  f.re_dkx = 0.90 * ax;
  f.re_dkz = 0.96 * az;
  return f;
}

double turbulence_weight(double re, double onset, double full, double* re_dweight) {
  if (re_dweight) *re_dweight = 0.0;
  if (std::isnan(onset) || std::isnan(full)) {
    if (std::isnan(onset) && std::isnan(full)) return 1.0;  // no transition
    throw InputError("turbulence_onset_re, turbulence_full_re: expected both or neither, got " +
                     std::string(std::isnan(onset) ? "turbulence_full_re" : "turbulence_onset_re") +
                     " alone");
  }
  if (!(re > onset)) return 0.0;
  if (re >= full) return 1.0;
  const double w = full - onset, t = (re - onset) / w;
  if (re_dweight) *re_dweight = re * 6.0 * t * (1.0 - t) / w;
  return t * t * (3.0 - 2.0 * t);
}

TurbulenceFactors turbulence_factors(Turbulence model, double re, double onset, double full) {
  double rg = 0.0;
  const double g = turbulence_weight(re, onset, full, &rg);
  if (g == 1.0 && rg == 0.0) return turbulence_factors(model, re);  // today's numbers
  TurbulenceFactors f;
  if (model == Turbulence::laminar || g == 0.0) return f;  // exactly laminar below the onset
  // k = 12 + γ a Re^b; Re dk/dRe = γ a b Re^b + (Re γ') a Re^b
  const double ax = 0.0136 * std::pow(re, 0.90), az = 0.0043 * std::pow(re, 0.96);
  f.kx = 12.0 + g * ax;
  f.kz = 12.0 + g * az;
  f.cf = couette_shear_factor(model, re, onset, full);
  f.re_dkx = (0.90 * g + rg) * ax;
  f.re_dkz = (0.96 * g + rg) * az;
  return f;
}

// Conductance multipliers of a face with (effective) film h: m = 12/k (h³/(12μ) → h³/(kμ))
// and dm = d(h³ m)/dh / (3 h² ) = m (1 − Re dk/dRe / (3k)), the factor of the conductance's
// h-derivative (laminar: m = dm = 1).
void ReynoldsSolver::Impl::turb_face(double hf, bool axial, int q, double& m,
                                     double& dm) const {
  // only the coefficient this face needs (one pow), the same values as turbulence_factors;
  // a viscosity field: Re_h at the face's viscosity μ_face = μ / (μ/μ_face) (the field is
  // frozen, so dm, the h-derivative at fixed μ_face, keeps its form)
  const double re =
      visc_field ? re_per_h * hf * (axial ? vmN[q] : vmE[q]) : re_per_h * hf;
  double k = 12.0, rk = 0.0;
  if (geo.turbulence == Turbulence::ng_pan && re > 0.0) {
    // the transition's weight γ (1 without one: today's arithmetic); below the onset the
    // face is exactly laminar (m = dm = 1)
    double rg = 0.0;
    const double g = turbulence_weight(re, geo.turbulence_onset_re, geo.turbulence_full_re, &rg);
    if (g > 0.0) {
      const double a = axial ? 0.0043 * std::pow(re, 0.96) : 0.0136 * std::pow(re, 0.90);
      const double b = axial ? 0.96 : 0.90;
      if (g == 1.0 && rg == 0.0) {
        k = 12.0 + a;
        rk = b * a;
      } else {
        k = 12.0 + g * a;
        rk = (b * g + rg) * a;
      }
    }
  }
  m = 12.0 / k;
  dm = m * (1.0 - rk / (3.0 * k));
}

}  // namespace rotordyn
