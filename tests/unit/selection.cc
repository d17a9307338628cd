// liftoff::Selection, the {name, value} table of every enum parameter: the
// pattern it builds accepts exactly its names, in the table's order; each
// name parses to its own value; and a name outside the table (which a
// ParameterHandler that skipped the pattern could hand over) is an error
// naming the entry and the allowed names, never a silent default.

#include <liftoff/base/selection.h>

#include "test_tools.h"

LIFTOFF_TEST_MAIN(argc, argv)
{
  liftoff_tests::Checks checks(argc, argv);

  enum class Colour
  {
    red,
    green,
    blue
  };
  const liftoff::Selection<Colour> colours = {{"red", Colour::red},
                                              {"light green", Colour::green},
                                              {"blue", Colour::blue}};
  checks.less("names() is the table in order",
              colours.names() != "red|light green|blue",
              0.5);
  const auto   pattern = colours.pattern();
  unsigned int wrong   = 0;
  for (const std::string name : {"red", "light green", "blue"})
    wrong += !pattern.match(name);
  for (const std::string name : {"", "green", "Red", "red|blue", "purple"})
    wrong += pattern.match(name);
  checks.less("the pattern accepts the table's names and nothing else",
              wrong,
              0.5);
  checks.less("each name parses to its own value",
              (colours.parse("red", "X/Colour") != Colour::red)
                + (colours.parse("light green", "X/Colour") != Colour::green)
                + (colours.parse("blue", "X/Colour") != Colour::blue),
              0.5);
  std::string message;
  try
    {
      colours.parse("purple", "Section/Colour");
    }
  catch (const std::exception &e)
    {
      message = e.what();
    }
  checks.less("a name outside the table throws, naming the entry and the names",
              message.find(
                "Section/Colour = purple is not one of red|light green|blue")
                == std::string::npos,
              0.5);
  return checks.exit_code();
}
