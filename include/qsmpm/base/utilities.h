#ifndef qsmpm_base_utilities_h
#define qsmpm_base_utilities_h

#include <array>
#include <cstddef>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <exception>
#include <mpi.h>
#include <string>
#include <vector>

/**
 * Small helpers shared by all modules: parsing of the compact text formats
 * used in .prm files, and conversions between symmetric tensors and the flat
 * arrays in which material points store them.
 */
namespace qsmpm
{
  using namespace dealii;

  namespace Utils
  {
    /**
     * Parse "x,y" (2D) or "x,y,z" (3D) into a point. Throws with a message
     * naming @p what if the number of coordinates is not @p dim.
     */
    template <int dim>
    Point<dim>
    parse_point(const std::string &text, const std::string &what);

    /**
     * Parse a component string such as "xy", "x", "xyz" or "n" into a mask.
     * The letter "n" (normal component) is returned as an empty mask together
     * with @p normal_only = true.
     */
    template <int dim>
    std::array<bool, dim>
    parse_components(const std::string &text,
                     const std::string &what,
                     bool              &normal_only);

    /// Number of independent components of a symmetric rank-2 tensor.
    template <int dim>
    constexpr unsigned int n_symmetric_components =
      SymmetricTensor<2, dim>::n_independent_components;

    /// Read a symmetric tensor from @p data (deal.II's unrolled order).
    template <int dim>
    inline SymmetricTensor<2, dim>
    read_symmetric(const double *data)
    {
      SymmetricTensor<2, dim> t;
      for (unsigned int i = 0; i < n_symmetric_components<dim>; ++i)
        t.access_raw_entry(i) = data[i];
      return t;
    }

    /// Write a symmetric tensor to @p data (deal.II's unrolled order).
    template <int dim>
    inline void
    write_symmetric(const SymmetricTensor<2, dim> &t, double *data)
    {
      for (unsigned int i = 0; i < n_symmetric_components<dim>; ++i)
        data[i] = t.access_raw_entry(i);
    }

    /// Read a dim x dim tensor stored row by row from @p data.
    template <int dim>
    inline Tensor<2, dim>
    read_tensor(const double *data)
    {
      Tensor<2, dim> t;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          t[i][j] = data[i * dim + j];
      return t;
    }

    /// Write a dim x dim tensor to @p data row by row.
    template <int dim>
    inline void
    write_tensor(const Tensor<2, dim> &t, double *data)
    {
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          data[i * dim + j] = t[i][j];
    }

    /// Names of the unrolled components ("xx", "yy", "xy" in 2D).
    template <int dim>
    std::vector<std::string>
    symmetric_component_names();

    /// Split @p text at @p delimiter, trimming white space, dropping empties.
    std::vector<std::string>
    split(const std::string &text, const char delimiter);

    /**
     * The part of an exception's text meant for a user, on one line:
     * deal.II's exceptions carry the source file, line, violated condition
     * and a stack trace around the "Additional information"; programs print
     * only that information (or the whole text of other exceptions).
     */
    std::string
    error_message(const std::exception &exc);

    /**
     * Collective: if @p message is not empty on any rank of
     * @p communicator, throw on every rank an exception with the message of
     * the lowest such rank. For errors that only some ranks detect (in
     * their own points or cells), so that no rank waits forever in the
     * next collective call for one that has stopped.
     */
    void
    throw_if_any_rank(const std::string &message, const MPI_Comm communicator);

    /**
     * The entry "Dimension" (2 or 3, default 2) of the parameter file
     * @p filename, read before anything else can be declared: the dimension
     * is a template argument of everything else. All other entries and
     * subsections are skipped here and checked when the whole file is read.
     */
    unsigned int
    read_dimension(const std::string &filename);

    /**
     * Let the C library (glibc) serve blocks of at least @p smallest_block
     * bytes (clamped to [128 KiB, 32 MiB]) by mmap, so that freeing them
     * returns their memory to the system at once, and return the top of the
     * heap once more than twice that is free there. Without glibc, nothing
     * is done.
     *
     * This undoes what the static initializer of libsuperlu_dist (which
     * Debian's deal.II links through PETSc and Trilinos) does to every
     * process: mallopt(M_MMAP_MAX, 0) and mallopt(M_TRIM_THRESHOLD, -1),
     * i.e. every block from the heap and no memory ever returned. The
     * temporaries of ML's Galerkin products in an AMG setup and the copy of
     * all particle data that deal.II's sorting of the particles makes for a
     * moment then stay resident for the rest of the run, and the blocks
     * allocated later fragment the heap further, which raises the peak
     * memory of a run (figures in doc/benchmarks.md).
     *
     * Blocks below the threshold stay on the heap, where a block that is
     * freed and allocated again costs no page faults: choose it above the
     * size of the vectors that the Krylov solver and the preconditioner
     * allocate in every iteration (with glibc's default of 128 KiB, the
     * page faults of those slow the solver down noticeably).
     */
    void
    return_large_blocks_to_system(const std::size_t smallest_block);

    /**
     * Give the free pages inside the heap back to the system (glibc's
     * malloc_trim; nothing elsewhere). For after a phase that made and freed
     * many small blocks, such as the rows of a sparsity pattern that grow
     * while it is built: freed, they stay resident and are not reused by
     * the large arrays that follow, which come from mmap.
     */
    void
    release_free_heap();

    /**
     * Run gnuplot on the script @p script (a file name) if gnuplot is
     * installed (Debian: gnuplot-nox). Returns whether it ran and succeeded;
     * the example programs write their plots' scripts in any case and
     * make the pictures with this where they can.
     */
    bool
    run_gnuplot(const std::string &script);
  } // namespace Utils
} // namespace qsmpm

#endif
