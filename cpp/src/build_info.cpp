#include "rotordyn/build_info.hpp"

#include <Eigen/Core>
#include <sundials/sundials_config.h>

#include <string>

namespace rotordyn {

std::map<std::string, std::string> build_info() {
  std::map<std::string, std::string> info;
  info["rotordyn"] = ROTORDYN_VERSION;
  info["eigen"] = std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) +
                  "." + std::to_string(EIGEN_MINOR_VERSION);
  info["sundials"] = SUNDIALS_VERSION;
  info["suitesparse"] = ROTORDYN_SUITESPARSE_VERSION;
#if defined(__clang__)
  info["compiler"] = std::string("clang ") + __clang_version__;
#elif defined(__GNUC__)
  info["compiler"] = std::string("gcc ") + __VERSION__;
#endif
  info["cxx_standard"] = std::to_string(__cplusplus);
  return info;
}

}  // namespace rotordyn
