// Shared fixtures of the C++ system tests: a rigid journal's film on two coordinates.
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

}  // namespace rdtest
