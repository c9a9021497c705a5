// Minimal test registry for the C++ core tests (one executable, run by ctest).
#pragma once
#include <cmath>
#include <functional>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rdtest {

struct Case {
  std::string name;
  std::function<void()> fn;
};

inline std::vector<Case>& registry() {
  static std::vector<Case> r;
  return r;
}

struct Register {
  Register(const char* name, std::function<void()> fn) { registry().push_back({name, fn}); }
};

struct Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline void check_close(double got, double expected, double rtol, double atol, const char* expr,
                        const char* file, int line) {
  if (!(std::abs(got - expected) <= atol + rtol * std::abs(expected))) {
    std::ostringstream os;
    os.precision(12);
    os << file << ":" << line << ": " << expr << ": got " << got << ", expected " << expected
       << " (rtol " << rtol << ", atol " << atol << ")";
    throw Failure(os.str());
  }
}

}  // namespace rdtest

#define RD_CAT2(a, b) a##b
#define RD_CAT(a, b) RD_CAT2(a, b)
#define TEST_CASE(name)                                                     \
  static void RD_CAT(rd_test_fn_, __LINE__)();                              \
  static rdtest::Register RD_CAT(rd_test_reg_, __LINE__)(name, &RD_CAT(rd_test_fn_, __LINE__)); \
  static void RD_CAT(rd_test_fn_, __LINE__)()
#define CHECK(...)                                                                             \
  do {                                                                                         \
    if (!(__VA_ARGS__))                                                                             \
      throw rdtest::Failure(std::string(__FILE__) + ":" + std::to_string(__LINE__) + ": " #__VA_ARGS__); \
  } while (0)
#define CHECK_CLOSE(got, expected, rtol, atol) \
  rdtest::check_close((got), (expected), (rtol), (atol), #got, __FILE__, __LINE__)
#define CHECK_THROWS(stmt, ExcType)                                                          \
  do {                                                                                       \
    bool rd_thrown = false;                                                                  \
    try {                                                                                    \
      stmt;                                                                                  \
    } catch (const ExcType&) {                                                               \
      rd_thrown = true;                                                                      \
    }                                                                                        \
    if (!rd_thrown)                                                                          \
      throw rdtest::Failure(std::string(__FILE__) + ":" + std::to_string(__LINE__) +        \
                            ": expected " #ExcType " from " #stmt);                          \
  } while (0)
