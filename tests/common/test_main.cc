// liftoff_tests NAME [ARGS...]: runs the compiled test NAME
// (test_registry.h); without a known name, lists the tests and exits 2.

#include "test_registry.h"

#include <iostream>

int
main(int argc, char **argv)
{
  const auto &tests = liftoff_tests::registered_tests();
  const auto  test  = (argc > 1 ? tests.find(argv[1]) : tests.end());
  if (test == tests.end())
    {
      std::cerr << "usage: liftoff_tests NAME [ARGS...], NAME one of:";
      for (const auto &[name, function] : tests)
        std::cerr << ' ' << name;
      std::cerr << std::endl;
      return 2;
    }
  // The test sees its name as the program's name.
  return test->second(argc - 1, argv + 1);
}
