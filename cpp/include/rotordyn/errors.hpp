// rotordyn error hierarchy. The pybind11 module maps each to rotordyn.errors.*,
// all subclasses of rotordyn.errors.RotordynError.
#pragma once
#include <stdexcept>
#include <string>

namespace rotordyn {

/// Bad input: a field out of range, a wrong shape. Message names the field.
class InputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// An iteration (equilibrium, complementarity, root finder) did not converge.
class ConvergenceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A thermal film's metered oil supply cannot feed it: the supply Q_f and all the hot oil
/// that reaches its inlet Q_r together fall short of the flow Q the film draws (a starved
/// film; docs/film-physics.md "A metered supply below the film's demand"). A
/// ConvergenceError (no thermal equilibrium of the full film exists); the callers that
/// report statuses report "starved".
class StarvedError : public ConvergenceError {
 public:
  using ConvergenceError::ConvergenceError;
};

/// The journal touched the bush or sleeve (film thickness below the allowed minimum).
class ContactError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A SUNDIALS call returned a failure flag.
class SundialsError : public std::runtime_error {
 public:
  SundialsError(int flag, const std::string& where, const std::string& what)
      : std::runtime_error(where + ": " + what), flag_(flag), where_(where) {}
  int flag() const noexcept { return flag_; }
  const std::string& where() const noexcept { return where_; }

 private:
  int flag_;
  std::string where_;
};

/// Throw InputError("<what>: expected <expected>, got <got>") unless cond holds.
inline void require(bool cond, const std::string& what) {
  if (!cond) throw InputError(what);
}

inline std::string shape_msg(const std::string& name, long expected_rows, long expected_cols,
                             long got_rows, long got_cols) {
  return name + ": expected shape (" + std::to_string(expected_rows) + ", " +
         std::to_string(expected_cols) + "), got (" + std::to_string(got_rows) + ", " +
         std::to_string(got_cols) + ")";
}

}  // namespace rotordyn
