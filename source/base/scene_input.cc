#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <liftoff/base/output_files.h>
#include <liftoff/base/scene_input.h>

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

    // The line `line` of a file in `folder`; if it is `set Mesh file =
    // NAME` with a relative NAME, the line with NAME relative to `folder`,
    // as include lines are, so that a scene and its mesh beside it can be
    // run from anywhere. Empty `folder` (standard input, or a file in the
    // working directory): the line as it is.
    std::string
    with_mesh_file_resolved(const std::string           &line,
                            const std::filesystem::path &folder)
    {
      const std::string head = "set Mesh file";
      const std::string statement =
        Utilities::trim(line.substr(0, line.find('#')));
      if (folder.empty() || statement.rfind(head, 0) != 0)
        return line;
      const std::string rest = Utilities::trim(statement.substr(head.size()));
      if (rest.empty() || rest[0] != '=')
        return line;
      const std::filesystem::path name(Utilities::trim(rest.substr(1)));
      if (name.empty() || name.is_absolute())
        return line;
      return head + " = " + (folder / name).lexically_normal().string();
    }

    // A UTF-8 byte order mark, which some editors put first, is no part of
    // a parameter's name.
    std::string
    without_byte_order_mark(std::string text)
    {
      const std::string mark = "\xEF\xBB\xBF";
      if (text.rfind(mark, 0) == 0)
        text.erase(0, mark.size());
      return text;
    }

    std::string
    read_file(const std::string &name, const std::string &named_by)
    {
      AssertThrow(!std::filesystem::is_directory(name),
                  ExcMessage(name + named_by
                             + " is a directory, not a scene file."));
      std::ifstream in(name, std::ios::binary);
      AssertThrow(in,
                  ExcMessage("Cannot read the scene file " + name + named_by
                             + "."));
      std::string text;
      try
        {
          text.assign(std::istreambuf_iterator<char>(in), {});
        }
      catch (const std::exception &)
        {
          AssertThrow(false,
                      ExcMessage("Cannot read the scene file " + name + named_by
                                 + "."));
        }
      return without_byte_order_mark(text);
    }

    // The lines of `group`, the last of them line `last_line` of `file`,
    // appended to the scene; each keeps its number, for the messages of
    // ParameterHandler.
    void
    append_lines(const std::vector<std::string> &group,
                 const std::string              &file,
                 const unsigned int              last_line,
                 SceneText                      &scene)
    {
      for (std::size_t i = 0; i < group.size(); ++i)
        {
          scene.text += group[i] + '\n';
          scene.origins.emplace_back(file, last_line + 1 - group.size() + i);
        }
    }


    void
    expand_includes(const std::string        &text,
                    std::vector<std::string> &chain,
                    std::vector<std::string> &chain_names,
                    SceneText                &scene);


    // The file `name` that line `line_number` of the chain's last file
    // includes, expanded into the scene; a cycle or a chain too deep is
    // refused.
    void
    expand_included_file(const std::string        &name,
                         const unsigned int        line_number,
                         std::vector<std::string> &chain,
                         std::vector<std::string> &chain_names,
                         SceneText                &scene)
    {
      // Deeper than any sensible scene, far less than the stack allows.
      constexpr std::size_t max_depth = 64;
      const std::string     file =
        chain_names.empty() ? "standard input" : chain_names.back();
      const std::filesystem::path folder =
        chain_names.empty()
          ? std::filesystem::path()
          : std::filesystem::path(chain_names.back()).parent_path();
      const std::string named_by = " (named by the include line "
                                   + std::to_string(line_number) + " of " + file
                                   + ")";
      // Relative to the folder of the file that names it, so that a scene
      // and its includes can be run from anywhere.
      const std::string resolved =
        (folder / std::filesystem::path(name)).lexically_normal().string();
      const std::string contents = read_file(resolved, named_by);
      const std::string path =
        std::filesystem::weakly_canonical(resolved).string();
      std::string cycle;
      for (std::size_t i = 0; i < chain.size(); ++i)
        if (!cycle.empty() || chain[i] == path)
          cycle += chain_names[i] + " -> ";
      AssertThrow(cycle.empty(),
                  ExcMessage("The scene's include lines form a cycle: " + cycle
                             + resolved
                             + ". A file must not include itself, "
                               "directly or through others."));
      AssertThrow(chain.size() < max_depth,
                  ExcMessage("The scene's include lines nest more than "
                             + std::to_string(max_depth) + " files deep (at "
                             + resolved + ")."));
      chain.push_back(path);
      chain_names.push_back(resolved);
      expand_includes(contents, chain, chain_names, scene);
      chain.pop_back();
      chain_names.pop_back();
    }


    // Depth-first through the include lines of `text`, the contents of the
    // file `chain_names.back()` (of standard input if `chain` is empty),
    // appending every other line to `scene` with where it came from.
    void
    expand_includes(const std::string        &text,
                    std::vector<std::string> &chain,
                    std::vector<std::string> &chain_names,
                    SceneText                &scene)
    {
      const std::string file =
        chain_names.empty() ? "standard input" : chain_names.back();
      const std::filesystem::path folder =
        std::filesystem::path(chain_names.empty() ? "" : file).parent_path();
      std::istringstream       lines(text);
      std::string              line, joined;
      std::vector<std::string> group; // the lines of one continued line
      unsigned int             line_number = 0;
      while (std::getline(lines, line))
        {
          ++line_number;
          group.push_back(line);
          // A line ending in a backslash continues on the next one.
          const std::string trimmed = Utilities::trim(line);
          if (!trimmed.empty() && trimmed.back() == '\\')
            {
              joined += trimmed.substr(0, trimmed.size() - 1);
              continue;
            }
          const std::string name = included_file(joined + line);
          joined.clear();
          if (name.empty() && group.size() == 1)
            group.front() = with_mesh_file_resolved(line, folder);
          if (name.empty())
            append_lines(group, file, line_number, scene);
          else
            expand_included_file(name, line_number, chain, chain_names, scene);
          group.clear();
        }
      // A file that ends inside a continued line: its lines as they are.
      append_lines(group, file, line_number, scene);
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


  SceneText
  SceneText::read(const std::string &name)
  {
    SceneText                scene;
    std::vector<std::string> chain, chain_names;
    std::string              text;
    if (name == "-")
      text = without_byte_order_mark(
        std::string(std::istreambuf_iterator<char>(std::cin), {}));
    else
      {
        text = read_file(name, "");
        chain.push_back(std::filesystem::weakly_canonical(name).string());
        chain_names.push_back(name);
      }
    expand_includes(text, chain, chain_names, scene);
    return scene;
  }


  void
  SceneText::parse_into(ParameterHandler &prm, const std::string &name) const
  {
    std::istringstream in(text);
    try
      {
        prm.parse_input(in, name);
      }
    catch (const std::exception &e)
      {
        AssertThrow(false, ExcMessage(located(message_of(e), name)));
      }
  }


  std::string
  SceneText::located(const std::string &message, const std::string &name) const
  {
    const std::string key = "Line <";
    const std::string of  = "> of file <" + name + ">";
    std::string       result;
    std::size_t       from = 0;
    for (std::size_t at = message.find(key); at != std::string::npos;
         at             = message.find(key, from))
      {
                    const std::size_t number_end = message.find('>', at);
                    const std::string number =
                      message.substr(at + key.size(), number_end - at - key.size());
                    result += message.substr(from, at - from);
                    from = at + key.size();
                    if (number.empty()
            || number.find_first_not_of("0123456789") != std::string::npos
            || message.compare(number_end, of.size(), of) != 0)
          {
                        result += key;
                        continue;
          }
        const std::size_t line = std::stoul(number);
                    if (line == 0 || line > origins.size())
          {
                        result += key;
                        continue;
          }
        result += key + std::to_string(origins[line - 1].second) + "> of file <"
                              + origins[line - 1].first + ">";
                    from = number_end + of.size();
      }
    return result + message.substr(from);
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
