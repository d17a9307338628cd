#include <deal.II/base/exceptions.h>

#include <boost/serialization/array_wrapper.hpp>

#include <liftoff/base/archives.h>

#include <Epetra_CrsMatrix.h>

#include <string>

namespace liftoff
{
  void
  save_vector(OutputArchive &archive, const LA::MPI::Vector &vector)
  {
    const std::size_t n = vector.locally_owned_size();
    archive << n << boost::serialization::make_array(vector.begin(), n);
  }


  void
  load_vector(InputArchive &archive, LA::MPI::Vector &vector)
  {
    std::size_t n = 0;
    archive >> n;
    AssertThrow(n == vector.locally_owned_size(),
                ExcMessage("The checkpoint holds " + std::to_string(n)
                           + " entries of a vector where this rank owns "
                           + std::to_string(vector.locally_owned_size())
                           + ": it was written for another mesh."));
    archive >> boost::serialization::make_array(vector.begin(), n);
  }


  // Both walk the owned rows in order and each row's entries in Epetra's
  // storage order. (deal.II's matrix iterator copies a row at every step
  // into a fresh vector: on a million unknowns that took minutes, at each
  // factorisation of a run that writes checkpoints and at each checkpoint.)
  std::vector<double>
  matrix_values(const LA::MPI::SparseMatrix &A)
  {
    const Epetra_CrsMatrix &matrix = A.trilinos_matrix();
    std::vector<double>     values;
    values.reserve(matrix.NumMyNonzeros());
    for (int row = 0; row < matrix.NumMyRows(); ++row)
      {
        int     n_in_row   = 0;
        double *row_values = nullptr;
        int    *columns    = nullptr;
        matrix.ExtractMyRowView(row, n_in_row, row_values, columns);
        values.insert(values.end(), row_values, row_values + n_in_row);
      }
    return values;
  }


  void
  set_matrix_values(const std::vector<double> &values, LA::MPI::SparseMatrix &A)
  {
    const Epetra_CrsMatrix &matrix = A.trilinos_matrix();
    const std::size_t       n      = matrix.NumMyNonzeros();
    AssertThrow(values.size() == n,
                ExcMessage(
                  "The checkpoint holds " + std::to_string(values.size())
                  + " matrix entries where this rank has " + std::to_string(n)
                  + ": it was written for another mesh."));
    auto                                          next = values.begin();
    std::vector<LA::MPI::SparseMatrix::size_type> global_columns;
    for (int row = 0; row < matrix.NumMyRows(); ++row)
      {
        int     n_in_row   = 0;
        double *row_values = nullptr;
        int    *columns    = nullptr;
        matrix.ExtractMyRowView(row, n_in_row, row_values, columns);
        global_columns.resize(n_in_row);
        for (int k = 0; k < n_in_row; ++k)
          global_columns[k] = matrix.ColMap().GID(columns[k]);
        A.set(matrix.RowMap().GID(row),
              n_in_row,
              global_columns.data(),
              &*next,
              /*elide_zero_values*/ false);
        next += n_in_row;
      }
    A.compress(VectorOperation::insert);
  }
} // namespace liftoff
