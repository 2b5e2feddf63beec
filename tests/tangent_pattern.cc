// The sparsity pattern of the stiffness (TangentAssembler::reinit() with
// linear shape functions), which inserts each row once from the nodes
// around it, against deal.II's own construction of the same couplings:
// DoFTools::make_sparsity_pattern() over the locally owned cells into a
// DynamicSparsityPattern, completed across ranks by
// SparsityTools::distribute_sparsity_pattern() (the step-40 recipe).
//
// Boxes of 5 x 4 and 5 x 4 x 3 cells, and the 3D box made of 2 x 2 x 1
// coarse cells refined once (BackgroundGrid's coarse mesh for subdivisions
// with a common factor 2). On 2 ranks the partition boundary runs through
// the box, so rows of nodes on it collect couplings from cells of both
// ranks. Checks, for every locally owned row: the same columns, none
// missing and none extra (a missing entry would stop the assembly, an
// extra one would enter AMG's aggregation as a coupling). The number of
// entries is also checked against the count on a regular grid: a node
// with k_d neighbouring node indices along direction d (2 on a boundary,
// 3 inside) couples with prod_d k_d nodes, dim^2 entries each.
#include "tests.h"

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <qsmpm/assembly/tangent_assembler.h>
#include <qsmpm/grid/background_grid.h>
#include <set>

namespace
{
  using namespace qsmpm;

  template <int dim>
  void
  test(const std::array<unsigned int, dim> &cells)
  {
    BackgroundGrid<dim> grid(MPI_COMM_WORLD);
    Point<dim>          upper;
    for (unsigned int d = 0; d < dim; ++d)
      upper[d] = cells[d];
    grid.make_box(Point<dim>(), upper, cells);

    TangentAssembler<dim> tangent;
    tangent.reinit(grid);
    const auto &K = tangent.matrix();

    const IndexSet        &owned    = grid.locally_owned_dofs();
    const IndexSet        &relevant = grid.locally_relevant_dofs();
    DynamicSparsityPattern reference(relevant);
    DoFTools::make_sparsity_pattern(grid.get_dof_handler(),
                                    reference,
                                    AffineConstraints<double>(),
                                    true,
                                    Utilities::MPI::this_mpi_process(
                                      MPI_COMM_WORLD));
    SparsityTools::distribute_sparsity_pattern(reference,
                                               owned,
                                               MPI_COMM_WORLD,
                                               relevant);

    unsigned int            different = 0;
    types::global_dof_index entries   = 0;
    for (const auto row : owned)
      {
        std::set<types::global_dof_index> columns, expected;
        for (auto entry = K.begin(row); entry != K.end(row); ++entry)
          columns.insert(entry->column());
        for (auto entry = reference.begin(row); entry != reference.end(row);
             ++entry)
          expected.insert(entry->column());
        different += (columns != expected);
        entries += columns.size();
      }
    different = Utilities::MPI::sum(different, MPI_COMM_WORLD);
    entries   = Utilities::MPI::sum(entries, MPI_COMM_WORLD);

    // The sum over the nodes of prod_d k_d factors by direction: along d
    // the n_d + 1 node indices have 2 + 3 (n_d - 1) + 2 = 3 (n_d + 1) - 2
    // neighbouring indices in all.
    types::global_dof_index regular = dim * dim;
    for (unsigned int d = 0; d < dim; ++d)
      regular *= 3 * (cells[d] + 1) - 2;

    std::ostringstream name;
    for (unsigned int d = 0; d < dim; ++d)
      name << (d ? " x " : "") << cells[d];
    deallog << dim << "D, " << name.str() << " cells, "
            << grid.get_dof_handler().n_dofs() << " dofs" << std::endl;
    deallog << "  rows whose columns differ from DoFTools': " << different
            << (different == 0 ? " PASS" : " FAIL") << std::endl;
    deallog << "  entries " << entries << ", on a regular grid " << regular
            << (entries == regular ? " PASS" : " FAIL") << std::endl;
  }
} // namespace

int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  qsmpm_tests::MPILogInitAll       log;
  test<2>({{5, 4}});
  test<3>({{5, 4, 3}});
  test<3>({{4, 4, 2}});
}
