#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <qsmpm/base/utilities.h>
#include <qsmpm/grid/background_grid.h>

namespace qsmpm
{
  template <int dim>
  void
  BackgroundGrid<dim>::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      prm.declare_entry("Lower corner",
                        dim == 2 ? "0,0" : "0,0,0",
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Lower corner of the background grid box.");
      prm.declare_entry("Upper corner",
                        dim == 2 ? "1,1" : "1,1,1",
                        Patterns::List(Patterns::Double(), dim, dim),
                        "Upper corner of the background grid box.");
      prm.declare_entry("Subdivisions",
                        dim == 2 ? "8,8" : "8,8,8",
                        Patterns::List(Patterns::Integer(1), dim, dim),
                        "Number of grid cells in each coordinate direction.");
      prm.declare_entry("Periodic directions",
                        "",
                        Patterns::Anything(),
                        "Directions in which the box is periodic, as letters "
                        "(e.g. xy); empty for none. The displacement is then "
                        "periodic up to the macroscopic jump of <Boundary "
                        "conditions> (homogenization); with every direction "
                        "periodic one corner node is held.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    {
      lower_corner =
        Utils::parse_point<dim>(prm.get("Lower corner"), "Lower corner");
      upper_corner =
        Utils::parse_point<dim>(prm.get("Upper corner"), "Upper corner");
      subdivisions =
        Utils::parse_subdivisions<dim>(prm.get("Subdivisions"), "Subdivisions");
      periodic_directions.clear();
      const std::string letters = std::string("xyz").substr(0, dim);
      for (const char c : prm.get("Periodic directions"))
        {
          const auto d = letters.find(c);
          AssertThrow(d != std::string::npos,
                      ExcMessage("Geometry: <Periodic directions> = <" +
                                 prm.get("Periodic directions") +
                                 ">: use letters from " + letters + "."));
          if (std::find(periodic_directions.begin(),
                        periodic_directions.end(),
                        d) == periodic_directions.end())
            periodic_directions.push_back(d);
        }
      for (unsigned int d = 0; d < dim; ++d)
        AssertThrow(upper_corner[d] > lower_corner[d],
                    ExcMessage("Geometry: <Upper corner> must be larger than "
                               "<Lower corner> in every coordinate."));
    }
    prm.leave_subsection();
  }



  template <int dim>
  BackgroundGrid<dim>::BackgroundGrid(const MPI_Comm communicator)
    : communicator(communicator)
    , triangulation(communicator)
    , fe(FE_Q<dim>(1), dim)
    , dof_handler(triangulation)
  {
  }



  template <int dim>
  void
  BackgroundGrid<dim>::make_box(
    const Point<dim>                    &lower_corner,
    const Point<dim>                    &upper_corner,
    const std::array<unsigned int, dim> &subdivisions)
  {
    box_lower        = lower_corner;
    box_upper        = upper_corner;
    box_subdivisions = subdivisions;
    periodic.clear();
    triangulation.clear();
    const std::vector<unsigned int> n(subdivisions.begin(), subdivisions.end());
    GridGenerator::subdivided_hyper_rectangle(
      triangulation, n, lower_corner, upper_corner, /*colorize=*/true);
    distribute_dofs();
  }



  template <int dim>
  void
  BackgroundGrid<dim>::make_box(const Parameters &parameters)
  {
    make_box(parameters.lower_corner,
             parameters.upper_corner,
             parameters.subdivisions);
    if (!parameters.periodic_directions.empty())
      make_periodic(parameters.periodic_directions);
  }



  template <int dim>
  void
  BackgroundGrid<dim>::make_periodic(
    const std::vector<unsigned int> &directions)
  {
    AssertThrow(triangulation.n_active_cells() > 0,
                ExcMessage("Create the grid (make_box) before making it "
                           "periodic."));
    std::vector<
      GridTools::PeriodicFacePair<typename Triangulation<dim>::cell_iterator>>
      pairs;
    for (const unsigned int d : directions)
      {
        AssertThrow(d < dim,
                    ExcMessage("Periodic direction " + std::to_string(d) +
                               " does not exist in " + std::to_string(dim) +
                               "D."));
        if (std::find(periodic.begin(), periodic.end(), d) != periodic.end())
          continue;
        // A periodic direction needs two cells across the period, or a
        // node would be tied to itself.
        AssertThrow(box_subdivisions[d] >= 2,
                    ExcMessage("A periodic direction needs at least two "
                               "cells across the box."));
        GridTools::collect_periodic_faces(
          triangulation, 2 * d, 2 * d + 1, d, pairs);
        periodic.push_back(d);
      }
    std::sort(periodic.begin(), periodic.end());
    triangulation.add_periodicity(pairs);
    distribute_dofs();
  }



  template <int dim>
  const std::vector<unsigned int> &
  BackgroundGrid<dim>::periodic_directions() const
  {
    return periodic;
  }



  template <int dim>
  void
  BackgroundGrid<dim>::make_periodicity_constraints(
    AffineConstraints<double> &constraints) const
  {
    for (const unsigned int d : periodic)
      DoFTools::make_periodicity_constraints(
        dof_handler, 2 * d, 2 * d + 1, d, constraints);
  }



  template <int dim>
  void
  BackgroundGrid<dim>::distribute_dofs()
  {
    dof_handler.distribute_dofs(fe);
    owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, relevant_dofs);
  }



  template <int dim>
  const parallel::distributed::Triangulation<dim> &
  BackgroundGrid<dim>::get_triangulation() const
  {
    return triangulation;
  }



  template <int dim>
  parallel::distributed::Triangulation<dim> &
  BackgroundGrid<dim>::get_triangulation()
  {
    return triangulation;
  }



  template <int dim>
  const DoFHandler<dim> &
  BackgroundGrid<dim>::get_dof_handler() const
  {
    return dof_handler;
  }



  template <int dim>
  const FESystem<dim> &
  BackgroundGrid<dim>::get_fe() const
  {
    return fe;
  }



  template <int dim>
  const MappingQ1<dim> &
  BackgroundGrid<dim>::get_mapping() const
  {
    return mapping;
  }



  template <int dim>
  const IndexSet &
  BackgroundGrid<dim>::locally_owned_dofs() const
  {
    return owned_dofs;
  }



  template <int dim>
  const IndexSet &
  BackgroundGrid<dim>::locally_relevant_dofs() const
  {
    return relevant_dofs;
  }



  template <int dim>
  MPI_Comm
  BackgroundGrid<dim>::get_communicator() const
  {
    return communicator;
  }



  template <int dim>
  const Point<dim> &
  BackgroundGrid<dim>::lower_corner() const
  {
    return box_lower;
  }



  template <int dim>
  const Point<dim> &
  BackgroundGrid<dim>::upper_corner() const
  {
    return box_upper;
  }



  template <int dim>
  Tensor<1, dim>
  BackgroundGrid<dim>::cell_size() const
  {
    Tensor<1, dim> h;
    for (unsigned int d = 0; d < dim; ++d)
      h[d] = (box_upper[d] - box_lower[d]) / box_subdivisions[d];
    return h;
  }



  template class BackgroundGrid<2>;
  template class BackgroundGrid<3>;
} // namespace qsmpm
