#include <deal.II/lac/vector.h>

#include <liftoff/base/entry_quantity.h>
#include <liftoff/base/scene_input.h>
#include <liftoff/fem/patch_integrator.h>
#include <liftoff/fem/plate_fields.h>
#include <liftoff/loads/load_kinds.h>
#include <liftoff/loads/load_set.h>
#include <liftoff/loads/pressure.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace liftoff
{
  namespace
  {
    std::string
    subsection_name(const std::string &kind, const unsigned int i)
    {
      return kind + " " + std::to_string(i);
    }

    // "Point load 2" -> "point_load_2", the prefix of history columns.
    std::string
    column_name(const std::string &section)
    {
      std::string name = Utilities::replace_in_string(section, " ", "_");
      std::transform(name.begin(), name.end(), name.begin(), [](char c) {
        return static_cast<char>(std::tolower(c));
      });
      return name;
    }
  } // namespace


  void
  LoadSet::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Loads");
    prm.declare_entry(
      "Self weight",
      "0",
      Patterns::Double(0.0, 1e100),
      "q, the plate's weight per unit area in units of F0 / L^2, the unit "
      "of every pressure (>= 0, at most 1e100, beyond which its settled "
      "state overflows; 0: a weightless plate): a uniform pressure "
      "that acts from before tau = 0. "
      "A time integration starts from the static equilibrium under it (the "
      "slab settled on its bed, in contact wherever q pre-compresses the "
      "springs), with the initial displacement added to that equilibrium; "
      "the other loads act on top. A static analysis adds it to the loads."
        + quantity("self weight"));
    for (const LoadKind &kind : load_kinds())
      for (unsigned int i = 1; i <= max_loads_per_kind; ++i)
        kind.declare(prm, subsection_name(kind.section, i));
    prm.leave_subsection();
  }


  void
  LoadSet::parse_parameters(ParameterHandler &prm)
  {
    loads.clear();
    tracks.clear();
    prm.enter_subsection("Loads");
    for (const LoadKind &kind : load_kinds())
      for (unsigned int i = 1; i <= max_loads_per_kind; ++i)
        read_section(prm, kind, subsection_name(kind.section, i));
    // The pattern refuses a negative, nan or infinite weight.
    const double self_weight = prm.get_double("Self weight");
    if (self_weight != 0.0)
      loads.push_back(Pressure::self_weight(self_weight));
    prm.leave_subsection();
  }


  void
  LoadSet::read_section(ParameterHandler  &prm,
                        const LoadKind    &kind,
                        const std::string &section)
  {
    prm.enter_subsection(section);
    std::vector<std::unique_ptr<Load>> read = kind.read(prm, section);
    prm.leave_subsection();
    if (read.empty())
      return;
    // A moving load (a vehicle, also one that stands) is followed in
    // history.csv under its name.
    const LoadPath *path = read.front()->path();
    Track           track{column_name(section), {}};
    for (auto &load : read)
      {
        track.members.push_back(loads.size());
        loads.push_back(std::move(load));
      }
    if (kind.followed_when_standing || (path != nullptr && path->moves()))
      tracks.push_back(std::move(track));
  }


  bool
  LoadSet::has_permanent_loads() const
  {
    return std::any_of(loads.begin(), loads.end(), [](const auto &load) {
      return load->is_permanent();
    });
  }


  void
  LoadSet::assemble_permanent(LA::MPI::Vector &load_vector) const
  {
    assemble_selected(
      0.0, [](const Load &load) { return load.is_permanent(); }, load_vector);
  }


  namespace
  {
    bool
    is_of_rest(const Load &load)
    {
      return load.is_permanent() || load.bends_freely();
    }
  } // namespace


  bool
  LoadSet::has_rest_loads() const
  {
    return std::any_of(loads.begin(), loads.end(), [](const auto &load) {
      return is_of_rest(*load);
    });
  }


  void
  LoadSet::assemble_rest(LA::MPI::Vector &load_vector) const
  {
    assemble_selected(0.0, is_of_rest, load_vector);
  }


  bool
  LoadSet::is_empty() const
  {
    return loads.empty() && body_force == nullptr;
  }


  std::vector<std::vector<BoundingBox<2>>>
  LoadSet::regions_in_windows(const double       tau,
                              const double       window,
                              const unsigned int n_windows) const
  {
    std::vector<std::vector<BoundingBox<2>>> regions;
    for (unsigned int k = 0; k < n_windows; ++k)
      regions.push_back(
        regions_under_loads(tau + k * window, tau + (k + 1) * window));
    return regions;
  }


  std::vector<BoundingBox<2>>
  LoadSet::regions_under_loads(const double tau_begin,
                               const double tau_end) const
  {
    // A box off the meshed part touches no cell: a symmetric scene has
    // each load's image among its loads.
    std::vector<BoundingBox<2>> regions;
    for (const auto &load : loads)
      if (const auto region = load->region_between(tau_begin, tau_end))
        regions.push_back(*region);
    return regions;
  }


  std::vector<std::string>
  LoadSet::moving_load_names() const
  {
    std::vector<std::string> names;
    for (const Track &track : tracks)
      names.push_back(track.name);
    return names;
  }


  std::vector<double>
  LoadSet::moving_load_positions(const double tau) const
  {
    const PlateGeometry &geometry = discretization->geometry();
    std::vector<double>  values;
    for (const Track &track : tracks)
      {
        // The path's own point: a vehicle's wheels sit at offsets from it.
        const Point<2> p  = loads[track.members.front()]->path_point_at(tau);
        unsigned int   on = 0;
        for (const unsigned int k : track.members)
          on += loads[k]->touches(geometry, tau);
        values.insert(values.end(), {p[0], p[1], double(on)});
      }
    return values;
  }


  void
  LoadSet::require_path_on_plate(const Load                &load,
                                 const std::vector<double> &times,
                                 const PlateGeometry       &geometry) const
  {
    // The loads on this path: one, or a vehicle's wheels, of which one on
    // the plate is enough.
    const LoadPath &path    = *load.path();
    bool            touches = false;
    for (const double tau : times)
      {
        const Point<2> p = load.path_point_at(tau);
        AssertThrow(std::isfinite(p[0]) && std::isfinite(p[1]),
                    ExcMessage(path.owner() + "/Path = <" + path.expression()
                               + "> is not finite at "
                               + "tau = " + time_text(tau) + "."));
        for (const auto &other : loads)
          touches =
            touches
            || (other->path() == &path && other->touches(geometry, tau));
      }
    require_heading_kept(load, times);
    AssertThrow(touches,
                ExcMessage(path.owner() + "/Path = <"
                           + abbreviated(path.expression())
                           + "> keeps the load off the plate at every step "
                             "time from tau = 0 to the End time: it would "
                             "carry nothing. Move the path onto "
                           + plate_named(geometry) + "."));
  }


  void
  LoadSet::require_heading_kept(const Load                &load,
                                const std::vector<double> &times) const
  {
    // The loads on one path share its heading: the first one's is theirs.
    const auto &kept = load.kept_heading();
    if (!kept)
      return;
    const LoadPath &path = *load.path();
    for (const double tau : times)
      if (const auto heading = path.heading_at(tau);
          heading && (*heading - *kept).norm() > 1e-6)
        AssertThrow(
          false,
          ExcMessage(path.owner() + "/Path = <" + abbreviated(path.expression())
                     + "> turns: it heads " + LoadPath::heading_text(*kept)
                     + " at the start and " + LoadPath::heading_text(*heading)
                     + " at tau = " + time_text(tau)
                     + ", but the axles of Axles keep the direction they "
                       "start in. Give a straight path, or the wheels one "
                       "by one in Wheels."));
  }


  void
  LoadSet::check_against(const Discretization &disc,
                         const double          time_step,
                         const unsigned int    n_steps) const
  {
    std::vector<double> times(n_steps + 1);
    for (unsigned int k = 0; k <= n_steps; ++k)
      times[k] = k * time_step;
    require_on_plate(times, disc.geometry());
    if (disc.geometry().symmetry() == Symmetry::full)
      return;
    check_symmetry(times, disc);
  }


  void
  LoadSet::require_on_plate(const std::vector<double> &times,
                            const PlateGeometry       &geometry) const
  {
    for (const auto &load : loads)
      {
        const LoadPath *path = load->path();
        if (path == nullptr)
          load->require_on_plate(geometry);
        // Once per path (a vehicle's wheels share theirs).
        else if (std::find_if(loads.begin(),
                              loads.end(),
                              [&](const auto &other) {
                                return other->path() == path;
                              })
                   ->get()
                 == load.get())
          require_path_on_plate(*load, times, geometry);
      }
  }


  void
  LoadSet::check_symmetry(const std::vector<double> &times,
                          const Discretization      &disc) const
  {
    const BoundingBox<2> plate = disc.geometry().plate_box();
    // A reduced model is right only if what it integrates is symmetric: the
    // loads are compared where they are evaluated (every quadrature point of
    // the full plate's mesh) and when (every time the run visits), not at
    // samples, which a load can dodge.
    const std::string symmetry =
      (disc.geometry().symmetry() == Symmetry::half ? "half" : "quarter");
    for (const auto &load : loads)
      load->require_reducible(symmetry);
    // NaN equals nothing, not even its mirror image: a load that is not
    // finite somewhere is named as such before the comparison blames the
    // symmetry.
    for (const auto &load : loads)
      load->require_finite(times, plate, disc);
    for (const unsigned int axis : disc.geometry().symmetry_axes())
      for (const auto &load : loads)
        {
          bool has_image = false;
          for (const auto &other : loads)
            has_image =
              has_image
              || load->is_mirror_image(*other, axis, plate, times, disc);
          AssertThrow(has_image,
                      ExcMessage(
                        "Discretization/Symmetry = " + symmetry
                        + " needs symmetric loads, but " + load->name()
                        + " has no mirror image about the plane "
                        + (axis == 0 ? "x = 0" : "y = 0")
                        + " (compared at every quadrature point of the full "
                          "plate and every step time). Add the mirrored load "
                          "or model the full plate."));
        }
  }


  std::string
  LoadSet::non_finite_load(const double tau) const
  {
    LA::MPI::Vector scratch;
    for (const auto &load : loads)
      {
        const double h = load->history_at(tau);
        if (!std::isfinite(h))
          return load->non_finite_history(tau);
        LA::MPI::Vector part =
          load->spatial_part_at(*discretization, tau, scratch);
        if (!is_finite(part))
          return load->non_finite_spatial_part(tau);
        part *= h;
        if (!is_finite(part))
          return load->name() + ": Magnitude * Time history overflows at tau = "
                 + time_text(tau) + ".";
      }
    if (body_force != nullptr)
      return "the body force at tau = " + time_text(tau) + ".";
    return "the sum of the loads overflows at tau = " + time_text(tau) + ".";
  }


  void
  LoadSet::setup(const Discretization &disc)
  {
    discretization = &disc;
    for (auto &load : loads)
      load->setup(disc);
  }


  void
  LoadSet::assemble(const double tau, LA::MPI::Vector &load_vector) const
  {
    assemble_selected(
      tau, [](const Load &) { return true; }, load_vector);
    if (body_force != nullptr)
      add_body_force(tau, load_vector);
  }


  void
  LoadSet::assemble_selected(const double                             tau,
                             const std::function<bool(const Load &)> &selected,
                             LA::MPI::Vector &load_vector) const
  {
    load_vector = 0;
    LA::MPI::Vector scratch;
    for (const auto &load : loads)
      if (selected(*load))
        load_vector.add(load->history_at(tau),
                        load->spatial_part_at(*discretization, tau, scratch));
  }


  void
  LoadSet::use_plate(const MindlinPlate &plate)
  {
    for (auto &load : loads)
      load->use_plate(plate);
  }


  FreeBendingField
  LoadSet::free_bending(const double tau) const
  {
    std::vector<std::pair<const Load *, double>> bending;
    for (const auto &load : loads)
      if (load->bends_freely())
        bending.emplace_back(load.get(), load->history_at(tau));
    if (bending.empty())
      return {};
    return [bending, tau](const Point<2> &x) {
      FreeBending sum;
      for (const auto &[load, h] : bending)
        sum.add(load->free_bending_at(x, tau), h);
      return sum;
    };
  }


  void
  LoadSet::set_body_force(Function<2> *force)
  {
    Assert(force == nullptr || force->n_components == PlateFields::n_components,
           ExcDimensionMismatch(force->n_components,
                                PlateFields::n_components));
    body_force = force;
  }


  void
  LoadSet::add_body_force(const double tau, LA::MPI::Vector &load_vector) const
  {
    body_force->set_time(tau);
    // Functions may implement only vector_value(); ask for all components.
    Vector<double> values(PlateFields::n_components);
    PatchIntegrator(*discretization)
      .add(
        [&](const Point<2> &x) {
          body_force->vector_value(x, values);
          return std::array<double, 3>{{values[0], values[1], values[2]}};
        },
        load_vector);
  }

} // namespace liftoff
