// Checks that a call throws simdphys::Error whose message contains a fragment: errors must say
// what and where.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "simdphys/core.hpp"

namespace simdphys::test {

template <class F>
void expectError(F&& f, const std::string& fragment) {
  try {
    f();
    FAIL() << "no error; expected one mentioning '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

}  // namespace simdphys::test
