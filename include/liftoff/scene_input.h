#pragma once

#include <deal.II/base/function_parser.h>

#include <cstddef>
#include <memory>
#include <string>

namespace liftoff
{
  using namespace dealii;

  /// User text for a message: as it is when short, otherwise its start,
  /// "..." and its length, so that a huge expression gives a short message.
  std::string
  abbreviated(const std::string &text, const std::size_t max_length = 80);

  /**
   * A FunctionParser of `n_components` muParser expressions (separated by
   * ';') in `variables`, evaluated once so that an error shows now and not
   * in the middle of a run (muParser in deal.II 9.4 parses lazily). A bad
   * expression is refused in one line that names `parameter`, shows the
   * start of the text and says what muParser found; deal.II's own echo of
   * the whole expression to std::cerr is suppressed.
   */
  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_expression(const std::string &parameter,
                   const std::string &expression,
                   const unsigned int n_components,
                   const std::string &variables,
                   const bool         time_dependent);

  /**
   * Follow the `include` lines of a scene (as ParameterHandler does: file
   * names relative to the working directory) and refuse an include cycle,
   * which ParameterHandler would follow until the stack overflows, naming
   * the files in the cycle. `name` is the scene's file name ("-" for
   * standard input). Files that cannot be opened are left to
   * ParameterHandler, which names them.
   */
  void
  check_include_cycles(const std::string &text, const std::string &name);
} // namespace liftoff
