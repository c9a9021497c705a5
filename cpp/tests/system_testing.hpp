// Shared fixtures of the C++ system tests: a rigid journal's film on two coordinates, and the
// same film tilting with the journal on four (x, y, θx, θy).
#pragma once
#include <cmath>
#include <string>

#include "rotordyn/system.hpp"

namespace rdtest {

/// The film of a rigid journal on the system coordinates (0, 1) = (x, y): shape (−cos φ,
/// −sin φ) at the grid's n_circ angles.
inline rotordyn::FilmCoupling journal_film(const rotordyn::JournalBearingGeometry& g,
                                           rotordyn::FilmGrid grid, rotordyn::Cavitation cav,
                                           const std::string& name = "jb") {
  rotordyn::FilmCoupling f;
  f.name = name;
  f.geometry = g;
  f.grid = grid;
  f.cavitation = cav;
  f.coords = {0, 1};
  f.shape.resize(grid.n_circ, 2);
  for (int j = 0; j < grid.n_circ; ++j) {
    const double phi = 2 * M_PI * j / grid.n_circ;
    f.shape(j, 0) = -std::cos(phi);
    f.shape(j, 1) = -std::sin(phi);
  }
  return f;
}

/// journal_film with the journal's rotations as coordinates 2, 3 (shape sin φ, −cos φ; axial
/// weight z, z = 0 the mid-plane): h = c − (x + θy z) cos φ − (y − θx z) sin φ.
inline rotordyn::FilmCoupling tilting_journal_film(const rotordyn::JournalBearingGeometry& g,
                                                   rotordyn::FilmGrid grid,
                                                   rotordyn::Cavitation cav,
                                                   const std::string& name = "jb") {
  rotordyn::FilmCoupling f = journal_film(g, grid, cav, name);
  const int K1 = grid.n_axial + 1;
  f.coords = {0, 1, 2, 3};
  rotordyn::RowMatrixXd S(grid.n_circ, 4);
  for (int j = 0; j < grid.n_circ; ++j) {
    const double phi = 2 * M_PI * j / grid.n_circ;
    S.row(j) << -std::cos(phi), -std::sin(phi), std::sin(phi), -std::cos(phi);
  }
  f.shape = S;
  f.axial_weight = rotordyn::RowMatrixXd::Ones(4, K1);
  for (int k = 0; k < K1; ++k) {
    const double z = -0.5 * g.length_m + k * g.length_m / grid.n_axial;
    f.axial_weight(2, k) = f.axial_weight(3, k) = z;
  }
  return f;
}

}  // namespace rdtest
