// Internal: the number format of the core's error messages (private to cpp/src).
#pragma once

#include <sstream>
#include <string>

namespace rotordyn::format_detail {

/// A number in error messages (6 significant digits).
inline std::string num(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

}  // namespace rotordyn::format_detail
