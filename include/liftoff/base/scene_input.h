#pragma once

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

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
   * A scene as ParameterHandler reads it, its `include` lines replaced by
   * the files they name: ParameterHandler would look an included file up
   * from the working directory, so that a scene whose includes lie beside
   * it could only be run from its own folder. Here an include is relative
   * to the folder of the file that holds the include line (to the working
   * directory for standard input), and so is the file of a line `set Mesh
   * file = NAME`.
   */
  struct SceneText
  {
    /// Read `name` ("-" for standard input) and the files its include
    /// lines name. Refused by name: a file that cannot be read or is a
    /// directory, an include cycle (which ParameterHandler would follow
    /// until the stack overflows), includes more than 64 deep. A UTF-8 byte
    /// order mark at the start of a file is dropped.
    static SceneText
    read(const std::string &name);

    /// ParameterHandler::parse_input on the text; its messages name the
    /// file and line a bad line came from.
    void
    parse_into(ParameterHandler &prm, const std::string &name) const;

    /// `message` with ParameterHandler's "Line <n> of file <name>" (a line
    /// of `text`) replaced by the file and line that line came from.
    std::string
    located(const std::string &message, const std::string &name) const;

    std::string text;
    /// File and line number of each line of `text`.
    std::vector<std::pair<std::string, unsigned int>> origins;
  };
} // namespace liftoff
