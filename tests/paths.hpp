// Runs a test once per execution path this machine has: every SIMD target and the reference.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "simdphys/core.hpp"

namespace simdphys::test {

// A test fixture whose body runs on the path named by its parameter; the path is restored after.
class OnEveryPath : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    previous_ = activePath();
    setPath(GetParam());
  }
  void TearDown() override { setPath(previous_); }

 private:
  std::string previous_;
};

// Runs body() once on every path, in this process, naming the path in any failure. For tests
// whose inputs are expensive and path-independent (a full-size workload, its trees and its double
// reference): built once and shared, rather than once per path's process as OnEveryPath does.
template <class Body>
void forEveryPath(Body&& body) {
  for (const std::string& path : availablePaths()) {
    SCOPED_TRACE("path " + path);
    const ScopedPath on(path);
    body();
  }
}

}  // namespace simdphys::test

#define SIMDPHYS_ON_EVERY_PATH(Suite)                                                       \
  INSTANTIATE_TEST_SUITE_P(Paths, Suite, ::testing::ValuesIn(::simdphys::availablePaths()), \
                           [](const auto& p) { return p.param; })
