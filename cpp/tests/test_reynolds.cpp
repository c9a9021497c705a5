// Reynolds solver kernel tests: operator properties, closed-form limits (Ocvirk short bearing,
// Sommerfeld long bearing), perturbation vs finite-difference derivatives, complementarity,
// mass conservation of jfo, error paths. Python tests hold the published-table checks.
#include <Eigen/SparseCore>
#include <cmath>
#include <random>

#include "../src/reynolds_band.hpp"  // private solver classes, tested directly
#include "../src/reynolds_ldlt.hpp"
#include "rotordyn/errors.hpp"
#include "rotordyn/reynolds.hpp"
#include "reynolds_testing.hpp"
#include "testing.hpp"

using namespace rotordyn;

namespace {
constexpr double kPi = 3.14159265358979323846;

JournalBearingGeometry geom(double D, double L) {
  JournalBearingGeometry g;
  g.diameter_m = D;
  g.length_m = L;
  g.clearance_m = 1e-4;
  g.viscosity_pa_s = 0.02;
  return g;
}

// Periodic 5-point operator (N rings of M unknowns, ring-major, random conductances), as the
// film's: diagonally dominant, structurally symmetric.
Eigen::SparseMatrix<double> periodic_operator(int N, int M, std::mt19937& rng) {
  const int n = N * M;
  std::vector<Eigen::Triplet<double>> t;
  auto id = [&](int j, int k) { return ((j + N) % N) * M + k; };
  std::uniform_real_distribution<double> U(0.2, 2.0);
  for (int j = 0; j < N; ++j)
    for (int k = 0; k < M; ++k) {
      const double a = U(rng), b = U(rng);
      t.emplace_back(id(j, k), id(j, k), 4.0 + U(rng));
      t.emplace_back(id(j, k), id(j + 1, k), -a);
      t.emplace_back(id(j + 1, k), id(j, k), -a);
      if (k + 1 < M) {
        t.emplace_back(id(j, k), id(j, k + 1), -b);
        t.emplace_back(id(j, k + 1), id(j, k), -b);
      }
    }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// A with the masked unknowns decoupled (identity row and column), as the active set does.
Eigen::SparseMatrix<double> masked(const Eigen::SparseMatrix<double>& A,
                                   const std::vector<char>& mask) {
  Eigen::SparseMatrix<double> B = A;
  for (int c = 0; c < B.cols(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(B, c); it; ++it) {
      if (it.row() == c) {
        if (mask[c]) it.valueRef() = 1.0;
      } else if (mask[c] || mask[it.row()]) {
        it.valueRef() = 0.0;
      }
    }
  return B;
}
}  // namespace

TEST_CASE("reynolds: concentric journal without grooves carries no load; Petroff torque") {
  ReynoldsSolver s(geom(0.05, 0.04), FilmGrid{36, 8}, Cavitation::reynolds);
  const FilmSolution& f = s.rigid(0, 0, 0, 0, 100.0);
  CHECK(f.force_n.norm() < 1e-9);
  const double R = 0.025, L = 0.04, c = 1e-4;
  CHECK_CLOSE(f.friction_torque_nm, 2 * kPi * 0.02 * 100.0 * R * R * R * L / c, 1e-12, 0.0);
}

TEST_CASE("reynolds: full Sommerfeld long bearing approaches the closed form as 1/(L/D)") {
  // W∞ = 12π μ ω R³ L ε / (c² (2+ε²) √(1−ε²)), attitude 90°. End leakage lowers the finite
  // bearing's load by a deficit ∝ D/L: doubling L/D halves it.
  const double D = 0.05, c = 1e-4, mu = 0.02, w = 100.0, eps = 0.5, R = D / 2;
  double deficit[2];
  for (int m = 0; m < 2; ++m) {
    const double L = (m == 0 ? 4.0 : 8.0) * D;
    ReynoldsSolver s(geom(D, L), FilmGrid{96, m == 0 ? 32 : 64}, Cavitation::none);
    const FilmSolution& f = s.rigid(0, -eps * c, 0, 0, w);
    const double W = 12 * kPi * mu * w * R * R * R * L * eps /
                     (c * c * (2 + eps * eps) * std::sqrt(1 - eps * eps));
    deficit[m] = 1.0 - f.force_n.norm() / W;
    CHECK(std::abs(f.force_n.y()) < 1e-6 * W);  // no force along the line of centres
  }
  CHECK(deficit[1] > 0.0 && deficit[1] < 0.15);
  CHECK_CLOSE(deficit[0] / deficit[1], 2.0, 0.05, 0.0);
}

TEST_CASE("reynolds: short bearing (L/D = 1/16) approaches Ocvirk") {
  const double D = 0.16, L = 0.01, c = 1e-4, mu = 0.02, w = 100.0, eps = 0.5;
  ReynoldsSolver s(geom(D, L), FilmGrid{144, 16}, Cavitation::gumbel);
  const FilmSolution& f = s.rigid(0, -eps * c, 0, 0, w);
  const double R = D / 2;
  const double W = mu * w * R * L * L * L / (4 * c * c) * eps *
                   std::sqrt(16 * eps * eps + kPi * kPi * (1 - eps * eps)) /
                   std::pow(1 - eps * eps, 2);
  CHECK_CLOSE(f.force_n.norm(), W, 0.03, 0.0);
}

TEST_CASE("reynolds: Swift-Stieber solution is complementary and between gumbel and none") {
  JournalBearingGeometry g = geom(0.05, 0.05);
  g.grooves.push_back(Groove{90.0, 0.0, 0.0});
  ReynoldsSolver rs(g, FilmGrid{72, 16}, Cavitation::reynolds);
  const FilmSolution& f = rs.rigid(2e-5, -6e-5, 0, 0, 200.0);
  CHECK(f.p_pa.minCoeff() >= 0.0);
  CHECK(f.iterations >= 1);
  // No warm start: after another solve, the same call repeats the same iterations and the
  // same force bit for bit (the cavitation set is predicted from the call's own film).
  const Eigen::Vector2d f0 = f.force_n;
  const int it0 = f.iterations;
  rs.rigid(-4e-5, 3e-5, 1e-3, 0, 200.0);
  const FilmSolution& f1 = rs.rigid(2e-5, -6e-5, 0, 0, 200.0);
  CHECK(f1.iterations == it0);
  CHECK(f1.force_n == f0);
  ReynoldsSolver gs(g, FilmGrid{72, 16}, Cavitation::gumbel);
  const FilmSolution& fg = gs.rigid(2e-5, -6e-5, 0, 0, 200.0);
  // Reynolds pressures are lower than the clipped half-Sommerfeld ones only near the rupture;
  // both carry a load of the same size.
  CHECK_CLOSE(f.force_n.norm(), fg.force_n.norm(), 0.2, 0.0);
}

TEST_CASE("reynolds: perturbation K, C match central finite differences") {
  JournalBearingGeometry g = geom(0.05, 0.025);
  g.grooves.push_back(Groove{90.0, 0.0, 0.0});
  for (Cavitation cv : {Cavitation::none, Cavitation::gumbel, Cavitation::reynolds,
                        Cavitation::jfo}) {
    ReynoldsSolver s(g, FilmGrid{48, 12}, cv);
    rdtest::check_coefficients_match_fd(s, 3e-5, -5e-5, 150.0);
  }
}

TEST_CASE("reynolds: jfo conserves mass, reynolds does not when the film reforms") {
  JournalBearingGeometry g = geom(0.05, 0.04);
  g.grooves.push_back(Groove{90.0, 0.0, 0.0});
  ReynoldsSolver j(g, FilmGrid{72, 16}, Cavitation::jfo);
  const FilmSolution& fj = j.rigid(0, -0.6e-4, 0, 0, 300.0);
  CHECK(fj.inlet_flow_m3_s > 0.0);
  CHECK_CLOSE(fj.inlet_flow_m3_s, fj.side_flow_m3_s, 1e-9, 0.0);
  CHECK(fj.theta.minCoeff() < 0.99);
  CHECK(fj.theta.minCoeff() >= 0.0);
  ReynoldsSolver r(g, FilmGrid{72, 16}, Cavitation::reynolds);
  const FilmSolution& fr = r.rigid(0, -0.6e-4, 0, 0, 300.0);
  CHECK(std::abs(fr.inlet_flow_m3_s - fr.side_flow_m3_s) > 1e-3 * fr.side_flow_m3_s);
}

TEST_CASE("reynolds: bad input is an InputError, contact a ContactError") {
  JournalBearingGeometry g = geom(0.05, 0.04);
  g.clearance_m = 0.0;
  CHECK_THROWS(ReynoldsSolver(g, FilmGrid{72, 16}, Cavitation::reynolds), InputError);
  g.clearance_m = std::nan("");
  CHECK_THROWS(ReynoldsSolver(g, FilmGrid{72, 16}, Cavitation::reynolds), InputError);
  CHECK_THROWS(ReynoldsSolver(geom(0.05, 0.04), FilmGrid{8, 16}, Cavitation::reynolds),
               InputError);
  CHECK_THROWS(ReynoldsSolver(geom(0.05, 0.04), FilmGrid{72, 1}, Cavitation::reynolds),
               InputError);
  CHECK_THROWS(parse_cavitation("elrod"), InputError);
  ReynoldsSolver s(geom(0.05, 0.04), FilmGrid{24, 4}, Cavitation::reynolds);
  CHECK_THROWS(s.rigid(1e-4, 0, 0, 0, 10.0), InputError);
  RowMatrixXd h = RowMatrixXd::Constant(24, 5, 1e-4), hd = RowMatrixXd::Zero(24, 5);
  h(3, 2) = -1e-6;
  CHECK_THROWS(s.solve(h, hd, 10.0), ContactError);
  CHECK_THROWS(s.solve(RowMatrixXd::Constant(24, 4, 1e-4), hd, 10.0), InputError);
}

TEST_CASE("reynolds: integrate(p, -cos/-sin) is the journal force") {
  JournalBearingGeometry g = geom(0.05, 0.04);
  g.grooves.push_back(Groove{90.0, 0.0, 0.0});
  ReynoldsSolver s(g, FilmGrid{48, 12}, Cavitation::reynolds);
  const FilmSolution f = s.rigid(2e-5, -5e-5, 0, 0, 150.0);
  RowMatrixXd gc(48, 13), gs(48, 13);
  for (int j = 0; j < 48; ++j) {
    gc.row(j).setConstant(-std::cos(j * 2 * kPi / 48));
    gs.row(j).setConstant(-std::sin(j * 2 * kPi / 48));
  }
  CHECK_CLOSE(s.integrate(f.p_pa, gc), f.force_n.x(), 1e-12, 0.0);
  CHECK_CLOSE(s.integrate(f.p_pa, gs), f.force_n.y(), 1e-12, 0.0);
  CHECK_THROWS(s.integrate(f.p_pa, RowMatrixXd::Zero(48, 12)), InputError);
}

TEST_CASE("reynolds: StaticLDLT (LDLT and static LU) solves masked 5-point systems repeatedly") {
  // Periodic 5-point operator with random conductances; random sets of decoupled unknowns
  // (identity rows/columns, as the Swift-Stieber active set does), refactorised and solved
  // repeatedly with the same analysis: residual at round-off every time.
  const int N = 16, M = 5, n = N * M;
  std::mt19937 rng(7);
  const Eigen::SparseMatrix<double> A = periodic_operator(N, M, rng);
  StaticLDLT s;
  s.analyze(A);
  for (int trial = 0; trial < 8; ++trial) {
    std::vector<char> mask(n);
    for (auto& m : mask) m = trial > 0 && rng() % 3 == 0;
    const Eigen::SparseMatrix<double> B = masked(A, mask);
    CHECK(s.factorize(B.valuePtr()));
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0), x(n);
    s.solve(b.data(), x.data());
    CHECK((B * x - b).norm() < 1e-12 * b.norm());
    // non-symmetric, column-diagonally-dominant values on the same pattern (jfo-like): LU
    Eigen::SparseMatrix<double> C = B;
    for (int c = 0; c < n; ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(C, c); it; ++it)
        if (it.row() != c) it.valueRef() *= 0.3 + 0.7 * ((it.row() + 3 * c) % 5) / 4.0;
    CHECK(s.factorize_lu(C.valuePtr()));
    s.solve_lu(b.data(), x.data());
    CHECK((C * x - b).norm() < 1e-12 * b.norm());
  }
}

TEST_CASE("reynolds: BandLDLT opens the circle at a decoupled ring; equals StaticLDLT") {
  // Periodic 5-point operator (N rings of M unknowns, ring-major), random conductances. With
  // every unknown of ring `cut` decoupled (plus random others) the banded factor solves it to
  // round-off and agrees with the sparse one; a nonzero coupling across the opening is refused.
  const int N = 24, M = 6, n = N * M;
  auto id = [&](int j, int k) { return ((j + N) % N) * M + k; };
  std::mt19937 rng(11);
  const Eigen::SparseMatrix<double> A = periodic_operator(N, M, rng);
  std::vector<int> ring_first(N + 1);
  for (int j = 0; j <= N; ++j) ring_first[j] = j * M;
  StaticLDLT sparse;
  sparse.analyze(A);
  BandLDLT band;
  CHECK(band.analyze(A, ring_first));
  CHECK(band.bandwidth() == M);
  // a band costing more than max_flops (the sparse factor's work) is refused, unallocated
  const double band_flops = n * M * (M + 1) / 2.0;
  BandLDLT costly;
  CHECK(!costly.analyze(A, ring_first, band_flops - 1.0));
  CHECK(!costly.usable() && !costly.factorize(A.valuePtr(), 0));
  CHECK(costly.analyze(A, ring_first, band_flops));
  for (int cut : {0, 1, 7, N - 1}) {
    std::vector<char> mask(n);
    for (auto& m : mask) m = rng() % 4 == 0;
    for (int k = 0; k < M; ++k) mask[id(cut, k)] = 1;
    const Eigen::SparseMatrix<double> B = masked(A, mask);
    CHECK(band.factorize(B.valuePtr(), cut));
    CHECK(sparse.factorize(B.valuePtr()));
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0), x(n), y(n);
    for (int i = 0; i < n; ++i)
      if (mask[i]) b[i] = 0.0;
    band.solve(b.data(), x.data());
    sparse.solve(b.data(), y.data());
    CHECK((B * x - b).norm() < 1e-12 * b.norm());
    CHECK((x - y).lpNorm<Eigen::Infinity>() < 1e-12 * y.lpNorm<Eigen::Infinity>());
  }
  // ring 3 not decoupled: the couplings between rings 2 and 3 cross the opening
  std::vector<char> none(n, 0);
  const Eigen::SparseMatrix<double> B = masked(A, none);
  CHECK(!band.factorize(B.valuePtr(), 3));
}

TEST_CASE("reynolds: BandLDLT in reverse order; resumed factor equals the full one bit for bit") {
  // The circle opened at ring `cut` and numbered in −j solves the masked operator; a mask
  // change late in the opened order, refactorised from the last checkpoint before it, gives
  // the same solutions bit for bit as a full refactorisation of the new mask (both orders).
  const int N = 24, M = 6, n = N * M;
  auto id = [&](int j, int k) { return ((j + N) % N) * M + k; };
  std::mt19937 rng(5);
  const Eigen::SparseMatrix<double> A = periodic_operator(N, M, rng);
  std::vector<int> ring_first(N + 1);
  for (int j = 0; j <= N; ++j) ring_first[j] = j * M;
  BandLDLT band, full;
  CHECK(band.analyze(A, ring_first) && full.analyze(A, ring_first));
  for (const bool rev : {true, false}) {
    const int cut = 5;
    std::vector<char> mask(n);
    for (auto& m : mask) m = rng() % 4 == 0;
    for (int k = 0; k < M; ++k) mask[id(cut, k)] = 1;
    const Eigen::SparseMatrix<double> B = masked(A, mask);
    CHECK(band.factorize(B.valuePtr(), cut, rev));
    CHECK(band.reversed() == rev && band.opened(id(cut, rev ? M - 1 : 0)) == 0);
    Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0), x(n);
    for (int i = 0; i < n; ++i)
      if (mask[i]) b[i] = 0.0;
    band.solve(b.data(), x.data());
    CHECK((B * x - b).norm() < 1e-12 * b.norm());
    // direct assembly with checkpoints, then a change in ring cut ∓ 15 (opened position 15)
    auto assemble = [&](BandLDLT& f, const Eigen::SparseMatrix<double>& Bm, int c_from) {
      if (c_from > 0)
        f.begin_from(c_from);
      else
        f.begin(cut, rev);
      for (int c = 0; c < n; ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator it(Bm, c); it; ++it)
          if (it.row() >= c && std::min(f.opened(c), f.opened(it.row())) >= c_from)
            CHECK(f.set(static_cast<int>(it.row()), c, it.value()));
    };
    assemble(band, B, 0);
    CHECK(band.factorize_assembled(true) && band.resumable(cut, rev) &&
          !band.resumable(cut, !rev));
    std::vector<char> mask2 = mask;
    const int jc = rev ? cut - 15 : cut + 15;
    for (int k = 0; k < M; ++k) mask2[id(jc, k)] = !mask2[id(jc, k)];
    const Eigen::SparseMatrix<double> B2 = masked(A, mask2);
    const int cmin = band.opened(id(jc, rev ? M - 1 : 0));
    CHECK(cmin == 15 * M);
    // (a fallback to a full factorisation would refactorise the old factor's columns < c0)
    const int ks = band.checkpoint_stride();
    const int c0 = ((cmin - 2 * M) / ks) * ks;
    CHECK(ks == 4 * M && c0 == 12 * M);
    assemble(band, B2, c0 + M);
    CHECK(band.refactorize_from(c0));
    assemble(full, B2, 0);
    CHECK(full.factorize_assembled());
    Eigen::VectorXd b2 = Eigen::VectorXd::LinSpaced(n, 3.0, -1.0), x1(n), x2(n);
    for (int i = 0; i < n; ++i)
      if (mask2[i]) b2[i] = 0.0;
    band.solve(b2.data(), x1.data());
    full.solve(b2.data(), x2.data());
    CHECK((B2 * x2 - b2).norm() < 1e-12 * b2.norm());
    bool same = true;
    for (int i = 0; i < n; ++i) same = same && x1[i] == x2[i];
    CHECK(same);
  }
}

TEST_CASE("reynolds: banded and sparse factorisations give the same film (cavitated, no groove)") {
  // A groove-less film is periodic; a loaded journal cavitates whole rings, where the solver
  // opens the circle and factorises in the band. Pressures, force and K, C agree with the
  // sparse path to round-off; the full film (cavitation 'none', no ring to open) stays sparse.
  for (const int na : {8, 7}) {
    ReynoldsSolver band(geom(0.05, 0.03), FilmGrid{48, na}, Cavitation::reynolds);
    ReynoldsSolver sparse(geom(0.05, 0.03), FilmGrid{48, na}, Cavitation::reynolds);
    sparse.set_band_factor(false);
    CHECK(band.band_factor() && !sparse.band_factor());
    const double w = 2 * kPi * 60.0;
    const FilmSolution& fb = band.rigid(3e-5, -5e-5, 1e-3, 2e-3, w);
    const RowMatrixXd pb = fb.p_pa;
    const Eigen::Vector2d Fb = fb.force_n;
    CHECK(band.band_factor_used());
    const FilmSolution& fs = sparse.rigid(3e-5, -5e-5, 1e-3, 2e-3, w);
    CHECK(!sparse.band_factor_used());
    CHECK((pb - fs.p_pa).cwiseAbs().maxCoeff() < 1e-12 * fs.p_pa.cwiseAbs().maxCoeff());
    CHECK((Fb - fs.force_n).norm() < 1e-12 * fs.force_n.norm());
    const auto cb = band.coefficients(3e-5, -5e-5, w);
    const auto cs = sparse.coefficients(3e-5, -5e-5, w);
    CHECK((cb.K - cs.K).norm() < 1e-10 * cs.K.norm());
    CHECK((cb.C - cs.C).norm() < 1e-10 * cs.C.norm());
    ReynoldsSolver full(geom(0.05, 0.03), FilmGrid{48, na}, Cavitation::none);
    full.rigid(3e-5, -5e-5, 0.0, 0.0, w);
    CHECK(!full.band_factor_used());
  }
}

TEST_CASE("reynolds: the resumed active-set factorisations give the film bit for bit") {
  // Swift-Stieber on the half and the full grid and a z-dependent (tilted) film, both senses
  // of rotation: with the resume of the band factor (the full grid's iterations after the
  // first) the pressures, force and K, C are those of full refactorisations in every
  // iteration, bit for bit, and the resume happened in every case that runs on the full grid
  // (checked per case: the half grid's coefficients refactorise in full, the tilted film's
  // solve, full grid either way, resumes in 0 < r < iterations; observed 1-2 per solve).
  const int N = 72, K1 = 17;
  RowMatrixXd h(N, K1), hd = RowMatrixXd::Zero(N, K1);
  for (int j = 0; j < N; ++j)
    for (int k = 0; k < K1; ++k) {
      const double phi = 2.0 * kPi * j / N, z = (k - 8) / 16.0;
      h(j, k) = 1e-4 * (1.0 - (0.58 + 0.2 * z) * std::cos(phi - 0.5 - 0.3 * z));
    }
  for (const double w : {2 * kPi * 50.0, -2 * kPi * 50.0})
    for (const bool sym : {true, false}) {
      ReynoldsSolver a(geom(0.05, 0.04), FilmGrid{N, 16}, Cavitation::reynolds);
      ReynoldsSolver b(geom(0.05, 0.04), FilmGrid{N, 16}, Cavitation::reynolds);
      b.set_band_resume(false);
      CHECK(a.band_resume() && !b.band_resume());
      for (ReynoldsSolver* s : {&a, &b}) {
        s->set_use_axial_symmetry(sym);
        s->set_refine_prediction(false);  // the coarse start: iterations that resume
      }
      const auto ca = a.coefficients(3e-5, -5e-5, w), cb = b.coefficients(3e-5, -5e-5, w);
      CHECK(a.band_factor_used() && b.band_factor_used() && b.band_resumed() == 0);
      if (sym)
        CHECK(a.band_resumed() == 0);
      else
        CHECK(a.band_resumed() > 0);
      CHECK(ca.K == cb.K && ca.C == cb.C && ca.force_n == cb.force_n);
      const FilmSolution& fa = a.solve(h, hd, w);
      const RowMatrixXd pa = fa.p_pa;
      const int ia = fa.iterations;
      const int ra = a.band_resumed();  // read before b's solve: a's own last solve
      CHECK(ra > 0 && ra < ia);
      const FilmSolution& fb = b.solve(h, hd, w);
      CHECK(fb.iterations == ia && ia >= 2 && (pa.array() == fb.p_pa.array()).all());
    }
}

TEST_CASE("reynolds: the refined full-grid prediction gives the same film in fewer iterations") {
  // Tilted journals (h = c - (x + ty z) cos phi - (y - tx z) sin phi, not symmetric in z: the
  // full grid), both senses of rotation, several poses: with the relaxed start of the
  // active-set loop (refine_prediction) the pressures, the cavitated set, the forces and
  // moments and the linearised solves (dh of x, y, tx, ty) are those of the coarse start bit
  // for bit, and the loop takes fewer iterations in total (observed 2.9 -> 1.5 per solve).
  const int N = 72, K1 = 17;
  const double c = 1e-4, L = 0.04;
  ReynoldsSolver a(geom(0.05, L), FilmGrid{N, 16}, Cavitation::reynolds);
  ReynoldsSolver b(geom(0.05, L), FilmGrid{N, 16}, Cavitation::reynolds);
  b.set_refine_prediction(false);
  CHECK(a.refine_prediction() && !b.refine_prediction());
  RowMatrixXd h(N, K1), hd = RowMatrixXd::Zero(N, K1), zero = RowMatrixXd::Zero(N, K1);
  RowMatrixXd dh[4] = {h, h, h, h};
  int ia = 0, ib = 0;
  const double poses[4][4] = {{0.3, -0.5, 0.2, -0.3}, {-0.4, 0.2, 0.4, 0.3},
                              {0.1, 0.55, -0.3, 0.1}, {-0.2, -0.6, 0.0, 0.5}};
  for (const double w : {2 * kPi * 50.0, -2 * kPi * 50.0})
    for (const auto& q : poses) {
      const double x = q[0] * c, y = q[1] * c, tx = q[2] * c / L, ty = q[3] * c / L;
      for (int j = 0; j < N; ++j)
        for (int k = 0; k < K1; ++k) {
          const double phi = 2.0 * kPi * j / N, z = -0.5 * L + k * L / 16.0;
          h(j, k) = c - (x + ty * z) * std::cos(phi) - (y - tx * z) * std::sin(phi);
          dh[0](j, k) = -std::cos(phi);
          dh[1](j, k) = -std::sin(phi);
          dh[2](j, k) = z * std::sin(phi);
          dh[3](j, k) = -z * std::cos(phi);
        }
      const FilmSolution& fa = a.solve(h, hd, w);
      const RowMatrixXd pa = fa.p_pa;
      ia += fa.iterations;
      const FilmSolution& fb = b.solve(h, hd, w);
      ib += fb.iterations;
      CHECK((pa.array() == fb.p_pa.array()).all());
      CHECK(((pa.array() == 0.0) == (fb.p_pa.array() == 0.0)).all());
      for (int v = 0; v < 4; ++v) {
        CHECK(a.integrate(pa, dh[v]) == b.integrate(fb.p_pa, dh[v]));
        const RowMatrixXd da = a.linearize(dh[v], zero), db = b.linearize(dh[v], zero);
        CHECK((da.array() == db.array()).all());
        const RowMatrixXd ea = a.linearize(zero, dh[v]), eb = b.linearize(zero, dh[v]);
        CHECK((ea.array() == eb.array()).all());
      }
    }
  CHECK(ia < ib);
}

TEST_CASE("reynolds: linearize_many equals one linearize() per perturbation, bit for bit") {
  // A loaded journal (banded factor; Swift-Stieber and half-Sommerfeld) with perturbations
  // constant along z (the half system), zero fields (the squeeze-only branch), counts 1-10
  // (every remainder of the four-vector solves), and a z-dependent one (the fallback).
  for (Cavitation cav : {Cavitation::reynolds, Cavitation::gumbel}) {
    ReynoldsSolver s(geom(0.05, 0.04), FilmGrid{72, 16}, cav);
    const int N = 72, K1 = 17;
    RowMatrixXd h(N, K1), hd = RowMatrixXd::Zero(N, K1), zero = RowMatrixXd::Zero(N, K1);
    std::vector<RowMatrixXd> f(6, RowMatrixXd(N, K1));
    for (int j = 0; j < N; ++j) {
      const double phi = 2.0 * kPi * j / N;
      for (int k = 0; k < K1; ++k) {
        h(j, k) = 1e-4 * (1.0 - 0.6 * std::cos(phi - 0.3));
        hd(j, k) = 1e-3 * std::sin(phi);
        f[0](j, k) = -std::cos(phi);
        f[1](j, k) = -std::sin(phi);
        f[2](j, k) = std::cos(2.0 * phi);
        f[3](j, k) = std::sin(3.0 * phi) + 0.5;
        f[4](j, k) = -std::cos(phi) * std::sin(phi);
        f[5](j, k) = std::cos(phi) * (k - 8.0) / 8.0;  // odd in z
      }
    }
    for (int m = 1; m <= 10; ++m)
      for (bool with_odd : {false, true}) {
        std::vector<const RowMatrixXd*> a, b;
        for (int v = 0; v < m; ++v) {
          const RowMatrixXd* g = &f[static_cast<std::size_t>(v % 5)];
          if (with_odd && v == m - 1) g = &f[5];
          if (v % 2 == 0) {
            a.push_back(g);
            b.push_back(&zero);
          } else {
            a.push_back(&zero);
            b.push_back(g);
          }
        }
        s.solve(h, hd, 300.0);
        std::vector<RowMatrixXd> many;
        s.linearize_many(a, b, many);
        s.solve(h, hd, 300.0);
        CHECK(static_cast<int>(many.size()) == m);
        for (int v = 0; v < m; ++v) {
          const RowMatrixXd one = s.linearize(*a[static_cast<std::size_t>(v)],
                                              *b[static_cast<std::size_t>(v)]);
          CHECK((one.array() == many[static_cast<std::size_t>(v)].array()).all());
        }
      }
  }
}
