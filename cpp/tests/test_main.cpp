// Runs every registered C++ test case; prints "N passed, N failed" for the CI summary.
#include <cstring>

#include "testing.hpp"

int main(int argc, char** argv) {
  const char* filter = argc > 1 ? argv[1] : nullptr;
  int passed = 0, failed = 0;
  for (const auto& c : rdtest::registry()) {
    if (filter && c.name.find(filter) == std::string::npos) continue;
    try {
      c.fn();
      ++passed;
      std::cout << "[ ok ] " << c.name << "\n";
    } catch (const std::exception& e) {
      ++failed;
      std::cout << "[FAIL] " << c.name << ": " << e.what() << "\n";
    }
  }
  std::cout << passed << " passed, " << failed << " failed\n";
  return failed == 0 ? 0 : 1;
}
