#include <liftoff/base/output_files.h>
#include <liftoff/output/run_summary.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace liftoff
{
  namespace
  {
    std::string
    quoted(const std::string &text)
    {
      std::ostringstream out;
      out << '"';
      for (const char c : text)
        if (c == '"' || c == '\\')
          out << '\\' << c;
        else if (static_cast<unsigned char>(c) < 0x20)
          out << "\\u" << std::hex << std::setw(4) << std::setfill('0')
              << int(c) << std::dec;
        else
          out << c;
      out << '"';
      return out.str();
    }

    // Counts read as counts (a million dofs is not 1e+06).
    std::string
    text_number(const double x)
    {
      std::ostringstream out;
      if (x == std::round(x) && std::abs(x) < 1e15)
        out << static_cast<long long>(x);
      else
        out << x;
      return out.str();
    }

    // JSON has no inf or nan; a value that is not finite is written as
    // null rather than making the file unreadable.
    std::string
    json_number(const double x)
    {
      if (!std::isfinite(x))
        return "null";
      std::ostringstream out;
      out << std::setprecision(12) << x;
      return out.str();
    }
  } // namespace


  void
  RunSummary::add(const std::string &key, const Value &value)
  {
    entries.emplace_back(key, value);
  }


  std::string
  RunSummary::text() const
  {
    std::ostringstream out;
    for (const auto &[key, value] : entries)
      {
        out << key << ':';
        if (const auto *section = std::get_if<Section>(&value))
          {
            out << '\n';
            for (const auto &[name, number] : *section)
              out << "  " << name << ": " << text_number(number) << '\n';
          }
        else if (const auto *number = std::get_if<double>(&value))
          out << ' ' << text_number(*number) << '\n';
        else
          out << ' ' << std::get<std::string>(value) << '\n';
      }
    return out.str();
  }


  std::string
  RunSummary::json() const
  {
    std::ostringstream out;
    out << "{";
    const char *separator = "\n  ";
    for (const auto &[key, value] : entries)
      {
        out << separator << quoted(key) << ": ";
        separator = ",\n  ";
        if (const auto *section = std::get_if<Section>(&value))
          {
            out << "{";
            const char *inner = "";
            for (const auto &[name, number] : *section)
              {
                out << inner << quoted(name) << ": " << json_number(number);
                inner = ", ";
              }
            out << "}";
          }
        else if (const auto *number = std::get_if<double>(&value))
          out << json_number(*number);
        else
          out << quoted(std::get<std::string>(value));
      }
    out << "\n}\n";
    return out.str();
  }


  void
  RunSummary::write(const std::string &directory, const MPI_Comm comm) const
  {
    collective_attempt(comm, "", [&]() {
      if (dealii::Utilities::MPI::this_mpi_process(comm) != 0)
        return;
      write_file_atomically(directory + "/summary.json",
                            [&](std::ostream &out) { out << json(); });
      write_file_atomically(directory + "/summary.txt",
                            [&](std::ostream &out) { out << text(); });
    });
  }
} // namespace liftoff
