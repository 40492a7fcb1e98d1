// A path in the test temporary folder that no other test process shares: ctest runs each test of
// a program as its own process, two at a time, so a fixed name ("lab_bad.csv") is a race between
// two tests of one file that write it.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

namespace contensou::test {

// TempDir() + "<pid>_<name>": unique to this process.
inline std::string temp_path(const std::string& name) {
  return ::testing::TempDir() + std::to_string(::getpid()) + "_" + name;
}

}  // namespace contensou::test
