// Sparse factorisation choice for the Reynolds operator (issue 3): times the numeric
// factorisation and solve of a periodic 5-point operator (n_circ x n_interior_rows unknowns)
// with Eigen SimplicialLDLT/LLT (AMD, natural, COLAMD orderings) and CHOLMOD (simplicial LDL',
// supernodal LL', automatic), each analysed once and refactorised repeatedly as the solver does.
// Not part of the build; compile and run by hand:
//   g++ -O3 -DNDEBUG -I/usr/include/eigen3 -I/usr/include/suitesparse \
//       benchmarks/bench_reynolds_factor.cpp -o /tmp/bench_factor -lcholmod -lsuitesparseconfig
//   /tmp/bench_factor 72 15 && /tmp/bench_factor 144 31
#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

using SpMat = Eigen::SparseMatrix<double>;

template <class Solver>
void run(const char* name, const SpMat& A, Solver& s) {
  s.analyzePattern(A);
  Eigen::VectorXd b = Eigen::VectorXd::Ones(A.rows()), x;
  s.factorize(A);
  const int reps = std::max(20, static_cast<int>(3'000'000 / A.rows()));
  auto t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < reps; ++r) s.factorize(A);
  const double tf =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() /
      reps;
  t0 = std::chrono::steady_clock::now();
  for (int r = 0; r < reps; ++r) x = s.solve(b);
  const double ts =
      std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() /
      reps;
  std::printf("%-34s factor %8.1f us   solve %7.1f us\n", name, tf, ts);
}

int main(int argc, char** argv) {
  const int N = argc > 1 ? std::atoi(argv[1]) : 72, M = argc > 2 ? std::atoi(argv[2]) : 15;
  const int n = N * M;
  std::vector<Eigen::Triplet<double>> t;
  auto id = [&](int j, int k) { return ((j + N) % N) * M + k; };
  for (int j = 0; j < N; ++j)
    for (int k = 0; k < M; ++k) {
      const double a = 1.0 + 0.5 * std::cos(6.283185307 * j / N);  // h^3-like variation
      t.emplace_back(id(j, k), id(j, k), 4.0 * a + 0.1);
      t.emplace_back(id(j, k), id(j + 1, k), -a);
      t.emplace_back(id(j + 1, k), id(j, k), -a);
      if (k + 1 < M) {
        t.emplace_back(id(j, k), id(j, k + 1), -a);
        t.emplace_back(id(j, k + 1), id(j, k), -a);
      }
    }
  SpMat A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  std::printf("periodic 5-point operator, %d x %d = %d unknowns\n", N, M, n);
  { Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::AMDOrdering<int>> s; run("Eigen SimplicialLDLT, AMD", A, s); }
  { Eigen::SimplicialLLT<SpMat, Eigen::Lower, Eigen::AMDOrdering<int>> s; run("Eigen SimplicialLLT, AMD", A, s); }
  { Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::NaturalOrdering<int>> s; run("Eigen SimplicialLDLT, natural", A, s); }
  { Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::COLAMDOrdering<int>> s; run("Eigen SimplicialLDLT, COLAMD", A, s); }
  { Eigen::CholmodSimplicialLDLT<SpMat> s; run("CHOLMOD simplicial LDL'", A, s); }
  { Eigen::CholmodSupernodalLLT<SpMat> s; run("CHOLMOD supernodal LL'", A, s); }
  { Eigen::CholmodDecomposition<SpMat> s; run("CHOLMOD automatic", A, s); }
  return 0;
}
