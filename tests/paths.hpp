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

}  // namespace simdphys::test

#define SIMDPHYS_ON_EVERY_PATH(Suite)                                                       \
  INSTANTIATE_TEST_SUITE_P(Paths, Suite, ::testing::ValuesIn(::simdphys::availablePaths()), \
                           [](const auto& p) { return p.param; })
