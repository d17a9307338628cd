#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <liftoff/output_files.h>
#include <liftoff/scene_input.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <vector>

namespace liftoff
{
  namespace
  {
    // Swallows what is written to std::cerr while it lives: deal.II 9.4
    // prints every muParser error with the whole expression there before
    // it throws.
    class SilencedErrorStream
    {
    public:
      SilencedErrorStream()
          : saved(std::cerr.rdbuf(sink.rdbuf()))
      {}
      ~SilencedErrorStream()
      {
        std::cerr.rdbuf(saved);
      }

    private:
      std::ostringstream sink;
      std::streambuf    *saved;
    };

    // The file an include line names ("" if the line is none), read as
    // ParameterHandler reads it: comments and surrounding blanks dropped,
    // `include` or `INCLUDE` followed by a blank.
    std::string
    included_file(std::string line)
    {
      line = line.substr(0, line.find('#'));
      line = Utilities::trim(line);
      for (const std::string keyword : {"include", "INCLUDE"})
        if (line.size() > keyword.size() && line.rfind(keyword, 0) == 0
            && (line[keyword.size()] == ' ' || line[keyword.size()] == '\t'))
          return Utilities::trim(line.substr(keyword.size()));
      return "";
    }

    // Depth-first through the include lines of `text`; `chain` holds the
    // files from the scene down to `text`'s file.
    void
    follow_includes(const std::string        &text,
                    std::vector<std::string> &chain,
                    std::vector<std::string> &chain_names)
    {
      // Deeper than any sensible scene, far less than the stack allows.
      constexpr std::size_t max_depth = 64;
      std::istringstream    lines(text);
      std::string           line, joined;
      while (std::getline(lines, line))
        {
          // A line ending in a backslash continues on the next one.
          const std::string trimmed = Utilities::trim(line);
          if (!trimmed.empty() && trimmed.back() == '\\')
            {
              joined += trimmed.substr(0, trimmed.size() - 1);
              continue;
            }
          const std::string name = included_file(joined + line);
          joined.clear();
          if (name.empty())
            continue;
          std::ifstream in(name);
          if (!in)
            continue; // ParameterHandler names the file it cannot open.
          const std::string path =
            std::filesystem::weakly_canonical(name).string();
          std::string cycle;
          for (std::size_t i = 0; i < chain.size(); ++i)
            if (!cycle.empty() || chain[i] == path)
              cycle += chain_names[i] + " -> ";
          AssertThrow(cycle.empty(),
                      ExcMessage("The scene's include lines form a cycle: "
                                 + cycle + name
                                 + ". A file must not include itself, "
                                   "directly or through others."));
          AssertThrow(chain.size() < max_depth,
                      ExcMessage("The scene's include lines nest more than "
                                 + std::to_string(max_depth)
                                 + " files deep (at " + name + ")."));
          chain.push_back(path);
          chain_names.push_back(name);
          follow_includes(std::string(std::istreambuf_iterator<char>(in), {}),
                          chain,
                          chain_names);
          chain.pop_back();
          chain_names.pop_back();
        }
    }
  } // namespace


  std::string
  abbreviated(const std::string &text, const std::size_t max_length)
  {
    if (text.size() <= max_length)
      return text;
    return text.substr(0, max_length) + "... (" + std::to_string(text.size())
           + " characters)";
  }


  template <int dim>
  std::unique_ptr<FunctionParser<dim>>
  parse_expression(const std::string &parameter,
                   const std::string &expression,
                   const unsigned int n_components,
                   const std::string &variables,
                   const bool         time_dependent)
  {
    auto parser = std::make_unique<FunctionParser<dim>>(n_components);
    try
      {
        const SilencedErrorStream silenced;
        parser->initialize(variables,
                           expression,
                           {{"pi", M_PI}},
                           time_dependent);
        Vector<double> values(n_components);
        parser->vector_value(Point<dim>(), values);
      }
    catch (const std::exception &e)
      {
        const std::string separated =
          n_components > 1 ? std::to_string(n_components)
                               + " muParser expressions separated by ';'"
                           : "a muParser expression";
        AssertThrow(false,
                    ExcMessage(parameter + " = <" + abbreviated(expression)
                               + "> must be " + separated + " in (" + variables
                               + "): " + message_of(e)));
      }
    return parser;
  }


  void
  check_include_cycles(const std::string &text, const std::string &name)
  {
    std::vector<std::string> chain, chain_names;
    if (name != "-")
      {
        chain.push_back(std::filesystem::weakly_canonical(name).string());
        chain_names.push_back(name);
      }
    follow_includes(text, chain, chain_names);
  }


  template std::unique_ptr<FunctionParser<1>>
  parse_expression<1>(const std::string &,
                      const std::string &,
                      const unsigned int,
                      const std::string &,
                      const bool);
  template std::unique_ptr<FunctionParser<2>>
  parse_expression<2>(const std::string &,
                      const std::string &,
                      const unsigned int,
                      const std::string &,
                      const bool);
} // namespace liftoff
