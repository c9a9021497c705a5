// Eigen's own threads (its OpenMP matrix products), one process-wide setting.
#pragma once

namespace rotordyn {

/// Threads Eigen may use inside one matrix product (one process-wide value): n >= 1, or 0 for
/// OpenMP's count (Eigen's default). The core links OpenMP for its batches; Eigen then splits
/// every product above ~50³ over OpenMP threads, which spin-wait on a loaded machine (52 % of
/// an orbit solve's CPU, docs/performance.md). The Python package sets 1 at import
/// (rotordyn.set_eigen_threads). Not to be changed while a core call runs on another thread.
/// InputError for n < 0.
void set_eigen_threads(int n);
/// The value of set_eigen_threads (0: OpenMP's count).
int eigen_threads();

}  // namespace rotordyn
