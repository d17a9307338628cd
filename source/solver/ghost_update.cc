#include <liftoff/solver/ghost_update.h>

#include <Epetra_BlockMap.h>
#include <Epetra_Import.h>

namespace liftoff
{
  GhostUpdate::GhostUpdate() = default;


  GhostUpdate::~GhostUpdate() = default;


  bool
  GhostUpdate::is_same_layout(const Epetra_BlockMap &source,
                              const Epetra_BlockMap &target)
  {
    for (const KnownLayouts &known : known_layouts)
      if (known.source->DataPtr() == source.DataPtr()
          && known.target->DataPtr() == target.DataPtr())
        return known.same;
    // The vectors of a run are few (a dozen); a new mesh brings new ones.
    if (known_layouts.size() >= 16)
      known_layouts.clear();
    known_layouts.push_back({std::make_unique<Epetra_BlockMap>(source),
                             std::make_unique<Epetra_BlockMap>(target),
                             target.SameAs(source)});
    return known_layouts.back().same;
  }


  void
  GhostUpdate::copy(const LA::MPI::Vector &owned, LA::MPI::Vector &ghosted)
  {
    const Epetra_BlockMap &source = owned.trilinos_vector().Map();
    const Epetra_BlockMap &target = ghosted.trilinos_vector().Map();
    // Vectors of one layout (one rank): a plain copy.
    if (is_same_layout(source, target))
      {
        copy_values(owned, ghosted);
        return;
      }
    AssertThrow(owned.size() == ghosted.size(),
                ExcDimensionMismatch(owned.size(), ghosted.size()));
    // SameAs is collective and its answer the same on every rank, so
    // every rank builds the import or none does.
    const bool is_current = importer != nullptr;
    if (!(is_current && is_same_layout(importer->SourceMap(), source)
          && is_same_layout(importer->TargetMap(), target)))
      importer = std::make_unique<Epetra_Import>(target, source);
    const int ierr = ghosted.trilinos_vector().Import(owned.trilinos_vector(),
                                                      *importer,
                                                      Insert);
    AssertThrow(ierr == 0, ExcTrilinosError(ierr));
  }


  void
  GhostUpdate::distribute(const AffineConstraints<double> &constraints,
                          LA::MPI::Vector                 &x,
                          LA::MPI::Vector                 &ghosted)
  {
    copy(x, ghosted);
    const IndexSet &owned = x.locally_owned_elements();
    for (const auto &line : constraints.get_lines())
      if (owned.is_element(line.index))
        {
          double value = line.inhomogeneity;
          for (const auto &[column, weight] : line.entries)
            value += ghosted(column) * weight;
          x(line.index) = value;
        }
    x.compress(VectorOperation::insert);
    copy(x, ghosted);
  }
} // namespace liftoff
