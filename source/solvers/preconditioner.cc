#include <Amesos.h>
#include <Epetra_Map.h>
#include <Teuchos_ParameterList.hpp>
#include <algorithm>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <qsmpm/solvers/preconditioner.h>

namespace qsmpm
{
  namespace
  {
    /**
     * The coordinates of the grid's nodes whose dofs @p owned_map holds, one
     * entry per node in the order of the nodes' first dofs (ML's layout of
     * "x-coordinates" etc. with "PDE equations" = dofs per node).
     */
    template <int dim>
    std::array<std::vector<double>, dim>
    make_node_coordinates(const BackgroundGrid<dim> &grid,
                          const Epetra_Map          &owned_map)
    {
      const unsigned int node_dofs = grid.n_node_dofs();
      const unsigned int n_nodes   = owned_map.NumMyElements() / node_dofs;
      std::array<std::vector<double>, dim> x;
      for (auto &xd : x)
        xd.assign(n_nodes, 0.);
      const IndexSet &owned = grid.locally_owned_dofs();
      for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            {
              const auto dof = cell->vertex_dof_index(v, 0);
              if (!owned.is_element(dof))
                continue;
              const int lid = owned_map.LID(
                static_cast<TrilinosWrappers::types::int_type>(dof));
              Assert(lid % node_dofs == 0,
                     ExcMessage("The dofs of a node are not in a row."));
              for (unsigned int d = 0; d < dim; ++d)
                x[d][lid / node_dofs] = cell->vertex(v)[d];
            }
      return x;
    }
  } // namespace



  template <int dim>
  std::unique_ptr<Epetra_MultiVector>
  make_rigid_body_modes(const BackgroundGrid<dim> &grid,
                        const Epetra_Map          &owned_map)
  {
    // Each body of a multi-field grid moves on its own: its own modes,
    // the translations of all bodies first, then the rotations.
    const unsigned int n_rotations = dim * (dim - 1) / 2;
    const unsigned int n_bodies    = grid.n_bodies();
    const unsigned int node_dofs   = grid.n_node_dofs();
    auto               modes =
      std::make_unique<Epetra_MultiVector>(owned_map,
                                           n_bodies * (dim + n_rotations));
    const Point<dim> centre =
      0.5 * (grid.lower_corner() + Tensor<1, dim>(grid.upper_corner()));
    const IndexSet &owned = grid.locally_owned_dofs();

    for (const auto &cell : grid.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          {
            const Tensor<1, dim> x = cell->vertex(v) - centre;
            for (unsigned int bc = 0; bc < node_dofs; ++bc)
              {
                const unsigned int b = bc / dim, c = bc % dim;
                const auto         dof = cell->vertex_dof_index(v, bc);
                // ML's "PDE equations" (see setup()) needs the dofs of a
                // node in a row.
                Assert(dof == cell->vertex_dof_index(v, 0) + bc,
                       ExcMessage("The dofs of a vertex are not consecutive: "
                                  "AMG for elasticity needs them in a row."));
                if (!owned.is_element(dof))
                  continue;
                const int lid = owned_map.LID(
                  static_cast<TrilinosWrappers::types::int_type>(dof));
                // Translations (all modes are zero at first).
                (*modes)[b * dim + c][lid] = 1.;
                // Rotations: 2D about z: (-y, x); 3D about x, y, z.
                const unsigned int r0 = n_bodies * dim + b * n_rotations;
                if (dim == 2)
                  (*modes)[r0][lid] = (c == 0) ? -x[1] : x[0];
                else
                  {
                    // about x: (0, -z, y); about y: (z, 0, -x);
                    // about z: (-y, x, 0)
                    const double rx[3]    = {0., -x[2 % dim], x[1]};
                    const double ry[3]    = {x[2 % dim], 0., -x[0]};
                    const double rz[3]    = {-x[1], x[0], 0.};
                    (*modes)[r0 + 0][lid] = rx[c];
                    (*modes)[r0 + 1][lid] = ry[c];
                    (*modes)[r0 + 2][lid] = rz[c];
                  }
              }
          }
    return modes;
  }



  template <int dim>
  typename Preconditioner<dim>::Type
  Preconditioner<dim>::parse_type(const std::string &name)
  {
    if (name == "none")
      return Type::none;
    if (name == "jacobi")
      return Type::jacobi;
    if (name == "direct")
      return Type::direct;
    AssertThrow(name == "amg",
                ExcMessage("Unknown preconditioner <" + name +
                           ">: use none, jacobi, amg or direct."));
    return Type::amg;
  }



  template <int dim>
  Preconditioner<dim>::Preconditioner(const Type   type,
                                      const bool   rotations,
                                      const double anisotropy_threshold)
    : preconditioner_type(type)
    , with_rotations(rotations)
    , anisotropy_threshold(anisotropy_threshold)
  {
    AssertThrow(anisotropy_threshold >= 0. && anisotropy_threshold <= 0.5,
                ExcMessage("AMG anisotropy threshold: must lie in [0, 0.5]."));
  }



  template <int dim>
  typename Preconditioner<dim>::Type
  Preconditioner<dim>::type() const
  {
    return preconditioner_type;
  }



  template <int dim>
  bool
  Preconditioner<dim>::needs_matrix() const
  {
    return preconditioner_type != Type::none;
  }



  template <int dim>
  void
  Preconditioner<dim>::setup(const TrilinosWrappers::SparseMatrix &K,
                             const BackgroundGrid<dim>            &grid,
                             const unsigned int                    pattern)
  {
    if (preconditioner_type == Type::jacobi)
      jacobi.initialize(K);
    else if (preconditioner_type == Type::amg)
      {
        // Start from deal.II's settings for an elliptic problem with linear
        // elements, then replace the null space by the rigid-body modes.
        // A W-cycle keeps the GMRES iteration count nearly flat under
        // refinement, where a V-cycle's grows.
        // Free the hierarchy of the last build before making the new one:
        // otherwise both are alive during the setup, which raises the peak
        // memory of a run that rebuilds every step.
        amg.clear();
        rigid_body_modes.reset();
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic              = true;
        data.higher_order_elements = false;
        data.smoother_sweeps       = 2;
        data.aggregation_threshold = 1e-4;
        data.w_cycle               = true;
        Teuchos::ParameterList              parameters;
        std::unique_ptr<Epetra_MultiVector> unused;
        data.set_parameters(parameters, unused, K);

        const Epetra_Map &map = K.trilinos_matrix().DomainMap();
        rigid_body_modes      = make_rigid_body_modes(grid, map);
        parameters.set("null space: type", "pre-computed");
        // The translations are the first dim vectors of the modes (per
        // body).
        parameters.set("null space: dimension",
                       with_rotations ? rigid_body_modes->NumVectors() :
                                        static_cast<int>(grid.n_node_dofs()));
        // A rank that owns no rows has no storage for the modes (Values()
        // is null), which ML reads as "no null space given" and warns
        // about on every build; it reads nothing from a non-null pointer
        // of no rows.
        static double no_rows = 0.;
        parameters.set("null space: vectors",
                       rigid_body_modes->MyLength() > 0 ?
                         rigid_body_modes->Values() :
                         &no_rows);
        // The dim dofs of a node (consecutive in the grid's numbering, see
        // make_rigid_body_modes()) form one block: ML aggregates nodes
        // instead of single dofs, as smoothed aggregation for elasticity
        // assumes. ML's default of one equation lets an aggregate take the
        // x but not the y dof of a node; per node, GMRES needs fewer
        // iterations and the setup is faster and needs less memory.
        parameters.set("PDE equations", static_cast<int>(grid.n_node_dofs()));
        // On cells of equal sides the distances show no direction: the
        // aggregation stays with the stiffness, and the set-up does not
        // build the auxiliary matrix. Nor on a periodic grid: there the
        // stiffness couples nodes a period apart, which the distances
        // would drop (the polycrystal's periodic tests: 103-168 GMRES
        // iterations instead of 37-94).
        const Tensor<1, dim> h = grid.cell_size();
        const double h_max     = *std::max_element(h.begin_raw(), h.end_raw());
        if (anisotropy_threshold > 0. &&
            h_max > (1. + 1e-6) * grid.min_cell_size() &&
            grid.periodic_directions().empty())
          {
            // ML aggregates on a Laplacian of the nodes' distances, which
            // sees a stretched cell's weak direction whatever the material;
            // the stiffness's own entries mix the two with the material's
            // anisotropy and Poisson coupling.
            node_coordinates            = make_node_coordinates(grid, map);
            static const char *names[3] = {"x-coordinates",
                                           "y-coordinates",
                                           "z-coordinates"};
            for (unsigned int d = 0; d < dim; ++d)
              parameters.set(names[d],
                             node_coordinates[d].empty() ?
                               &no_rows :
                               node_coordinates[d].data());
            parameters.set("aggregation: aux: enable", true);
            parameters.set("aggregation: aux: threshold", anisotropy_threshold);
            // Aggregates in the plane of the strong couplings coarsen by
            // about 3 in the number of entries per level instead of about
            // 27 for cubes, and a W-cycle, which visits level l 2^l times,
            // then spends more on the coarse levels than it saves in
            // iterations: the polycrystal's tests need 151 GMRES
            // iterations with a V-cycle against 140, in about 4 % less
            // time (doc/example_polycrystal.md).
            parameters.set("prec type", "MGV");
          }
        amg.initialize(K, parameters);
      }
    else if (preconditioner_type == Type::direct)
      {
        // Amesos directly rather than deal.II's SolverDirect: the symbolic
        // factorization (ordering, block triangular form) depends on the
        // pattern only and is kept while it stays the same; a new K with
        // the same pattern only needs a numeric factorization.
        if (!direct || pattern == numbers::invalid_unsigned_int ||
            pattern != analysed_pattern)
          {
            analysed_pattern = pattern;
            direct.reset();
            direct_problem = std::make_unique<Epetra_LinearProblem>();
            direct_problem->SetOperator(
              const_cast<Epetra_CrsMatrix *>(&K.trilinos_matrix()));
            Amesos factory;
            direct.reset(factory.Create("Amesos_Klu", *direct_problem));
            AssertThrow(direct != nullptr,
                        ExcMessage("Preconditioner = direct: Trilinos was "
                                   "built without Amesos KLU."));
            // A new K with the same pattern is factored with the pivot
            // order of the last full factorization (klu_refactor); Amesos
            // factors anew, with pivoting, where that order leaves a
            // diagonal of U small against its largest entry. b15.prm: the
            // 102 factorizations take 0.33 s instead of 1.38 s, with the
            // same GMRES iterations.
            Teuchos::ParameterList list;
            list.set("Refactorize", true);
            direct->SetParameters(list);
            AssertThrow(direct->SymbolicFactorization() == 0,
                        ExcMessage("Preconditioner = direct: the symbolic "
                                   "factorization of the stiffness failed."));
          }
        // On every rank together (the factors live on one), so that a
        // caller may catch it and go on with another matrix.
        const bool failed = dealii::Utilities::MPI::logical_or(
          direct->NumericFactorization() != 0, grid.get_communicator());
        AssertThrow(!failed,
                    ExcMessage("Preconditioner = direct: the stiffness is "
                               "singular (KLU's numeric factorization "
                               "failed)."));
      }
  }



  template <int dim>
  void
  Preconditioner<dim>::vmult(TrilinosWrappers::MPI::Vector       &dst,
                             const TrilinosWrappers::MPI::Vector &src) const
  {
    switch (preconditioner_type)
      {
        case Type::none:
          dst = src;
          return;
        case Type::jacobi:
          jacobi.vmult(dst, src);
          break;
        case Type::amg:
          amg.vmult(dst, src);
          break;
        case Type::direct:
          {
            // Amesos takes the vectors through the problem; they are
            // released again so that it holds no pointer to them.
            Epetra_MultiVector &b = const_cast<Epetra_MultiVector &>(
              static_cast<const Epetra_MultiVector &>(src.trilinos_vector()));
            direct_problem->SetLHS(&dst.trilinos_vector());
            direct_problem->SetRHS(&b);
            const int ierr = direct->Solve();
            direct_problem->SetLHS(nullptr);
            direct_problem->SetRHS(nullptr);
            AssertThrow(ierr == 0,
                        ExcMessage("Preconditioner = direct: KLU's solve "
                                   "failed."));
          }
          break;
      }
    // J ~ -K.
    dst *= -1.;
  }



  template class Preconditioner<2>;
  template class Preconditioner<3>;
  template std::unique_ptr<Epetra_MultiVector>
  make_rigid_body_modes<2>(const BackgroundGrid<2> &, const Epetra_Map &);
  template std::unique_ptr<Epetra_MultiVector>
  make_rigid_body_modes<3>(const BackgroundGrid<3> &, const Epetra_Map &);
} // namespace qsmpm
