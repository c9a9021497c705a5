#pragma once
#include <map>
#include <string>

namespace rotordyn {
/// Versions of rotordyn and of the libraries the core was compiled against.
std::map<std::string, std::string> build_info();
}  // namespace rotordyn
