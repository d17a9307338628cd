#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/loads/load.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * A kind of load as a scene names it: subsections "<section> 1" to
   * "<section> n" of Loads, their entries, and how one subsection is read
   * into loads (none if it is off; a vehicle: its wheels).
   */
  struct LoadKind
  {
    std::string                                                  section;
    std::function<void(ParameterHandler &, const std::string &)> declare;
    std::function<std::vector<std::unique_ptr<Load>>(ParameterHandler &,
                                                     const std::string &)>
      read;
    /// history.csv follows its loads even where they stand (a vehicle);
    /// otherwise only a load whose path moves.
    bool followed_when_standing = false;
  };

  /// The kinds of load, in the order in which LoadSet reads and adds them
  /// up. A new kind is a class of its own file and one line here.
  const std::vector<LoadKind> &
  load_kinds();
} // namespace liftoff
