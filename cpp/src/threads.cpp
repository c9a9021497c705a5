#include "rotordyn/threads.hpp"

#include <Eigen/Core>

#include <atomic>
#include <string>

#include "rotordyn/errors.hpp"

namespace rotordyn {

namespace {
std::atomic<int> requested{0};  // Eigen's own default: OpenMP's count
}  // namespace

void set_eigen_threads(int n) {
  if (n < 0)
    throw InputError("eigen threads: expected an integer >= 0 (0: OpenMP's count), got " +
                     std::to_string(n));
  requested = n;
  Eigen::setNbThreads(n);
}

int eigen_threads() { return requested; }

}  // namespace rotordyn
