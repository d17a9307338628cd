#pragma once

#include <deal.II/base/parameter_handler.h>

#include <liftoff/base/entry_quantity.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace liftoff
{
  using namespace dealii;

  /**
   * The unit system a scene is written in (`Units/System`). The solver
   * runs the dimensionless groups of doc/model.md; a scene in SI units
   * (`Units/System = SI`) gives the physical plate and bed in `Units` and
   * every other dimensional entry (loads, positions, times, expressions) in
   * SI, and convert() writes the dimensionless scene the parts parse. The
   * force scale of that scene is F0 = D / L, so its deflection is w / L.
   * The outputs ask scale() and unit() for each quantity, so a run reports
   * in the units its scene was written in.
   */
  class PhysicalUnits
  {
  public:
    enum class System
    {
      dimensionless,
      si
    };

    /// What a value is, for its scale and unit (base/entry_quantity.h).
    using Quantity = liftoff::Quantity;

    /// What the classes that own the plate's and the bed's entries say of
    /// the scene as written (each in a static `describe_for_units()`), so
    /// that the conversion reads no entry of theirs.
    struct SceneOutline
    {
      /// nu, for D (MindlinPlate).
      double poisson_ratio = 0;
      /// The plate is the rectangle Units/Length x Units/Width: points
      /// given in metres are checked against it (PlateGeometry).
      bool is_rectangle = true;
      /// The sums of the slabs' lengths and widths the scene gives in
      /// metres (PlateGeometry; 0: none), which Units/Length and Width
      /// left out are, so that a pavement of given slabs says its size once.
      double length_of_slabs = 0, width_of_slabs = 0;
      /// Entries of Units the scene must give (> 0), each with the choice
      /// that needs it, as the message ends ("a Foundation/Model other
      /// than none").
      std::vector<std::pair<std::string, std::string>> required;
      /// Entries of Units the scene must leave out, each with the message
      /// that says why.
      std::vector<std::pair<std::string, std::string>> refused;
    };

    /// The subsection `Units`.
    static void
    declare_parameters(ParameterHandler &prm);

    /// Counts, for parse_parameters(), how often `scene` sets each entry of
    /// Units, each dimensionless group an SI scene replaces and each entry
    /// converted only if set: ParameterHandler keeps only the value, and a
    /// group set to its default beside the entry that replaces it is a mix
    /// all the same. Called once every entry is declared and before the
    /// scene is read into `scene`; the counts are this object's.
    void
    watch(ParameterHandler &scene);

    /// In an SI scene, sets each entry the scene leaves out that has an
    /// SI default (si_default(): a steel's modulus, concrete's nu) to it,
    /// so that every part, used_parameters.prm and the checkpoint read the
    /// values the run uses. Called once the scene is read, before
    /// parse_parameters() and the outline.
    void
    take_si_defaults(ParameterHandler &scene) const;

    /// Reads `Units`; refuses a scene that mixes physical entries with
    /// the dimensionless ones they replace, naming both, or that lacks an
    /// entry of Units the `outline` requires or sets one it refuses.
    void
    parse_parameters(ParameterHandler &scene, const SceneOutline &outline);

    bool
    is_physical() const;

    /**
     * The scene the solver's parts read: `scene` itself if it is
     * dimensionless; else its dimensionless twin, declared by `declare` as
     * `scene` was, every entry converted (errors name the entry the user
     * wrote), and kept by this object. `scene` stays as written, for
     * used_parameters.prm and the checkpoint.
     */
    ParameterHandler &
    solver_scene(ParameterHandler                              &scene,
                 const std::function<void(ParameterHandler &)> &declare);

    /// Runs `read`, the parts reading solver_scene(); in an SI scene an
    /// error they raise, which quotes the dimensionless twin's numbers, is
    /// raised again in the scene's terms (in_scene_terms()) with the scales
    /// that convert them.
    void
    explain_errors_of(const std::function<void()> &read) const;

    /// Runs `run`, a run of solver_scene(); in an SI scene an error it
    /// raises is raised again in the scene's terms. Out of memory and the
    /// linear solver's own errors pass unchanged.
    void
    explain_run_errors_of(const std::function<void()> &run) const;

    /// `message`, an error or a warning of a run of solver_scene(), in the
    /// scene's terms: in an SI scene an entry quoted as the user wrote it,
    /// a time and a step (tau = X, dtau = X) in seconds, each group it
    /// names with the entries of Units and their values that give it, a
    /// time scale beyond what the solver integrates named. A dimensionless
    /// scene's as it is.
    std::string
    in_scene_terms(std::string message) const;

    /// used_parameters.prm: `scene_text` (the scene as written), and for
    /// an SI scene its dimensionless twin after it as comments.
    std::string
    record_of(const std::string &scene_text) const;

    /// The groups of an SI scene, each with its unit in its name: D, mu,
    /// Delta, Gamma, t0, the bed's radius of relative stiffness
    /// l = (D/k)^(1/4) (with a bed) and F0 (the start-up line and the
    /// summary).
    std::vector<std::pair<std::string, double>>
    groups() const;

    /// groups() on a line of their own after a new line, for the start of
    /// a run; empty for a dimensionless scene.
    std::string
    groups_line() const;

    /// The value in the scene's units of one unit of the solver's
    /// `quantity` (1 in a dimensionless scene).
    double
    scale(const Quantity quantity) const;

    /// " [m]" and so on in an SI scene, "" in a dimensionless one (whose
    /// headers stay as they are).
    std::string
    unit(const Quantity quantity) const;

    /// The unit of `quantity` as the field files' metadata name it: "m",
    /// "Pa", ... in an SI scene; the dimensionless scales it is made of
    /// ("F0*L^2/D", doc/model.md) in a dimensionless one.
    std::string
    unit_symbol(const Quantity quantity) const;

  private:
    System system = System::dimensionless;

    // The SI scene's plate and bed, as written.
    double length = 0, width = 0, thickness = 0, youngs_modulus = 0,
           density = 0, gravity = 0, subgrade_modulus = 0, dashpot = 0,
           shear_layer = 0, poisson_ratio = 0;
    /// SceneOutline::is_rectangle of the scene.
    bool is_rectangle = true;

    // The scales of the dimensionless scene: bending stiffness D, time t0,
    // force F0.
    double bending_stiffness = 1, t0 = 1, f0 = 1;

    /// The dimensionless twin of an SI scene and its text.
    std::shared_ptr<ParameterHandler> converted;
    std::string                       dimensionless_text;

  public:
    /// An entry the conversion changed: its value as the scene wrote it,
    /// in the twin, and its quantity.
    struct Converted
    {
      std::string si, twin;
      Quantity    quantity;
      /// The scene left it at its declared default.
      bool is_default = false;
    };

  private:
    /// How often the scene set each watched entry, by its path (watch():
    /// an action counts, run once with the default when it is added).
    std::map<std::string, std::shared_ptr<unsigned int>> set_counts;

    /// Each entry the conversion changed, by its path; the group each
    /// group entry is.
    std::map<std::string, Converted> twin_values;
    std::map<std::string, Quantity>  group_entries;

    /// Whether the scene gave the watched entry `path` a value.
    bool
    is_set(const std::string &path) const;

    /// `message` with each number quoted as <value> that rounds an
    /// entry's twin value replaced by the value the scene wrote.
    std::string
    with_written_numbers(const std::string &message) const;

    /// How the SI entries give `group`, with their values.
    std::string
    origin_of(const Quantity group) const;

    /// The value of `group` in this SI scene.
    double
    group_value(const Quantity group) const;

    /// D and the SI entries it comes from.
    std::string
    stiffness_origin() const;

    /// The solver's unit of `quantity` and the SI entries it comes from.
    std::string
    unit_origin(const Quantity quantity) const;

    void
    check_physical_values(const SceneOutline &outline) const;

    /// One unit of the solver's `quantity` in SI (the unit's symbol is
    /// si_symbol()).
    double
    si_scale(const Quantity quantity) const;

    /// Sets every entry of `dimensionless` (declared as `scene` is) to the
    /// SI scene's value, converted; its Units are left at their defaults.
    void
    convert(ParameterHandler &scene, ParameterHandler &dimensionless);
  };
} // namespace liftoff
