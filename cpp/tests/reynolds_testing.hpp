// Checks shared by the Reynolds solver's C++ tests.
#pragma once
#include "rotordyn/reynolds.hpp"
#include "testing.hpp"

namespace rdtest {

// K and C of the analytic perturbation solve against central finite differences of the forces
// (step 1e-6), entry by entry within 1e-3 of each matrix's norm.
inline void check_coefficients_match_fd(rotordyn::ReynoldsSolver& s, double x, double y,
                                        double speed) {
  const rotordyn::DynamicCoefficients a = s.coefficients(x, y, speed);
  const rotordyn::DynamicCoefficients b = s.coefficients_fd(x, y, speed, 1e-6);
  const double ks = a.K.norm(), cs = a.C.norm();
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      CHECK_CLOSE(a.K(i, j), b.K(i, j), 0.0, 1e-3 * ks);
      CHECK_CLOSE(a.C(i, j), b.C(i, j), 0.0, 1e-3 * cs);
    }
}

}  // namespace rdtest
