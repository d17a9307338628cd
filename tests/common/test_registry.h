#pragma once

// The compiled tests are one program, liftoff_tests, rather than one
// program each: a test adds one source to it and no link of its own.
// `liftoff_tests NAME` runs the test NAME (the file's name without .cc);
// tests/CMakeLists.txt gives each its ctest entry.

#include <map>
#include <string>

namespace liftoff_tests
{
  /// What a test file has in place of main(): it receives the command
  /// line without the test's name and returns the exit code.
  using TestMain = int (*)(int argc, char **argv);

  /// The tests of the program by name. A function's static, so that
  /// registrations from any source's static initialisers find it built.
  inline std::map<std::string, TestMain> &
  registered_tests()
  {
    static std::map<std::string, TestMain> tests;
    return tests;
  }

  /// Registers `test` under the stem of `file` (its __FILE__).
  inline bool
  register_test(const std::string &file, const TestMain test)
  {
    const std::size_t start = file.find_last_of('/') + 1;
    const std::size_t end   = file.rfind(".cc");
    registered_tests()[file.substr(start, end - start)] = test;
    return true;
  }
} // namespace liftoff_tests

/// Opens the test's main function, registered under its file's name:
///   LIFTOFF_TEST_MAIN(argc, argv) { ... return checks.exit_code(); }
#define LIFTOFF_TEST_MAIN(argc, argv)                           \
  static int        liftoff_test_main(int argc, char **argv);   \
  static const bool liftoff_test_registered =                   \
    liftoff_tests::register_test(__FILE__, &liftoff_test_main); \
  static int liftoff_test_main(int argc, char **argv)
