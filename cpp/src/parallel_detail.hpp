// Internal (bearing_table.cpp, unbalance.cpp): contiguous blocks of a batch on threads.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <thread>
#include <vector>

namespace rotordyn::detail {

/// work(b, e) over the contiguous blocks [b, e) of [0, n) on k threads (k <= 1: in the
/// caller's thread). Each block's caller-side state must be its own; the first block's
/// exception (in block order) is rethrown after every thread has joined.
template <class Work>
void run_blocks(Eigen::Index n, int k, Work&& work) {
  if (k <= 1) {
    work(Eigen::Index{0}, n);
    return;
  }
  std::vector<std::thread> pool;
  std::vector<std::exception_ptr> errs(static_cast<std::size_t>(k));
  const Eigen::Index chunk = (n + k - 1) / k;
  for (int t = 0; t < k; ++t) {
    const Eigen::Index b = t * chunk, e = std::min(n, b + chunk);
    if (b >= e) break;
    pool.emplace_back([&work, &errs, b, e, t] {
      try {
        work(b, e);
      } catch (...) {
        errs[static_cast<std::size_t>(t)] = std::current_exception();
      }
    });
  }
  for (auto& th : pool) th.join();
  for (auto& ep : errs)
    if (ep) std::rethrow_exception(ep);
}

}  // namespace rotordyn::detail
