#pragma once
// The message of the exception an action throws, for asserting messages by their text.

#include <string>

#include <gtest/gtest.h>

namespace cbbg::testing {

// Runs `action`, which must throw E, and returns what(); records a failure when it does not.
template <typename E = std::invalid_argument, typename F>
std::string error_of(F&& action) {
  try {
    action();
  } catch (const E& error) {
    return error.what();
  }
  ADD_FAILURE() << "no exception";
  return "";
}

}  // namespace cbbg::testing
