#pragma once

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <liftoff/base/archive_types.h>
#include <liftoff/base/linear_algebra.h>

#include <vector>

/**
 * The archives every part of the state saves itself to and loads itself
 * from, and the helpers for vectors and matrices. They sit below every
 * layer, so that a class with state to checkpoint (the foundation, the
 * linear solver, the outputs, the plate state) needs no header of run/,
 * where Checkpoint writes and reads the files.
 */
namespace liftoff
{
  using namespace dealii;


  /// This rank's entries of a distributed vector, bit for bit.
  void
  save_vector(OutputArchive &archive, const LA::MPI::Vector &vector);
  void
  load_vector(InputArchive &archive, LA::MPI::Vector &vector);

  /// save_vector() or load_vector(), as the archive goes: one list of items
  /// in a serialize() serves both directions.
  template <class Archive>
  void
  serialize_entries(Archive &archive, LA::MPI::Vector &vector)
  {
    if constexpr (Archive::is_saving::value)
      save_vector(archive, vector);
    else
      load_vector(archive, vector);
  }

  /// part.save(archive) or part.load(archive), as the archive goes, for
  /// the parts whose loading checks what it reads.
  template <class Archive, class Part>
  void
  transfer(Archive &archive, Part &part)
  {
    if constexpr (Archive::is_saving::value)
      part.save(archive);
    else
      part.load(archive);
  }

  /// The values of this rank's rows of a matrix, bit for bit, and back;
  /// setting them requires the same sparsity pattern and row distribution.
  std::vector<double>
  matrix_values(const LA::MPI::SparseMatrix &A);
  void
  set_matrix_values(const std::vector<double> &values,
                    LA::MPI::SparseMatrix     &A);
} // namespace liftoff
