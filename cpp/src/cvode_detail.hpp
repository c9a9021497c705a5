// Internal CVODE(S) plumbing shared by the transient (transient.cpp) and the shooting
// (periodic.cpp, continuation.cpp): C++ exceptions turned into CVODE return codes inside the
// callbacks, the error handler that stores CVODE's message, and an owning SUNContext.
#pragma once

#include <sundials/sundials_context.h>

#include <Eigen/Core>

#include <exception>
#include <sstream>
#include <string>

#include "rotordyn/errors.hpp"
#include "rotordyn/transient.hpp"

namespace rotordyn {

// cvode_flag_name: rotordyn/transient.hpp

namespace cvode_detail {

/// Run a CVODE callback's ``body`` (returning nothing) on a state with ``contact`` and
/// ``last_error`` members: 0 on success, 1 (recoverable: CVODE retries with a smaller step)
/// on a ContactError, −1 on any other exception. Nothing escapes into C.
template <class State, class Body>
int guarded(State& s, Body&& body) noexcept {
  try {
    body();
    return 0;
  } catch (const ContactError& e) {
    s.contact = true;
    s.last_error = e.what();
    return 1;
  } catch (const std::exception& e) {
    s.last_error = e.what();
    return -1;
  }
}

/// CVODE error handler: the message is stored in the state's ``cvode_message`` (never printed,
/// never aborts); the caller adds it to the status it reports.
template <class State>
void store_error(int error_code, const char* module, const char* function, char* msg,
                 void* user) {
  State& s = *static_cast<State*>(user);
  std::ostringstream os;
  os << module << "." << function << " (" << cvode_flag_name(error_code) << "): " << msg;
  s.cvode_message = os.str();
}

/// An input vector of the state's size n (or empty when ``allow_empty``), finite: else an
/// InputError naming ``name`` ("expected X, got Y").
inline void check_state_vector(const Eigen::VectorXd& v, const char* name, Eigen::Index n,
                               bool allow_empty) {
  require((allow_empty && v.size() == 0) || v.size() == n, shape_msg(name, n, 1, v.size(), 1));
  require(v.allFinite(), std::string(name) + ": expected finite values");
}

/// Owner of a heap-allocated SUNContext (freed if created).
struct SunContextDeleter {
  void operator()(SUNContext* p) const {
    if (p && *p) SUNContext_Free(p);
    delete p;
  }
};

}  // namespace cvode_detail
}  // namespace rotordyn
