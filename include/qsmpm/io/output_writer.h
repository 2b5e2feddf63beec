#ifndef qsmpm_io_output_writer_h
#define qsmpm_io_output_writer_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_vector.h>
#include <fstream>
#include <memory>
#include <qsmpm/base/parameter_struct.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/particles/material_point_set.h>
#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * Everything a run writes to disk: the material points (all their named
   * properties) as PVTU files with a PVD time series, the grid displacement
   * increment of each step, and a CSV file with the reaction force on every
   * displacement condition, the applied load and the force of the held
   * nodes per step (see EquilibriumAudit). Only rank 0 writes the PVD and CSV
   * files.
   */
  template <int dim>
  class OutputWriter
  {
  public:
    /**
     * The subsection "Output" of a .prm file.
     */
    struct Parameters : ParameterStruct<Parameters>
    {
      std::string  directory       = "output";
      unsigned int interval        = 1;
      bool         write_increment = true;
      /// Write a checkpoint every this many accepted steps; 0: never.
      unsigned int checkpoint_interval = 0;
      /// Probe positions in the initial configuration, "x,y; x,y" (see
      /// ProbeWriter); empty: no probes.csv.
      std::string probe_points;

      /// The positions of probe_points.
      std::vector<Point<dim>>
      probe_positions() const;

      /// Declare the entries, bound to the members.
      void
      add_parameters(ParameterHandler &prm);
    };

    OutputWriter(const Parameters &parameters, const MPI_Comm communicator);

    /// Whether field output is due at @p step.
    bool
    fields_due(const unsigned int step) const;

    /// points-NNNNN.pvtu and the PVD record points.pvd.
    void
    write_points(const MaterialPointSet<dim> &points,
                 const unsigned int           step,
                 const double                 load_factor);

    /// increment-NNNNN.pvtu: the grid's displacement increment of the step.
    void
    write_increment(const BackgroundGrid<dim>           &grid,
                    const TrilinosWrappers::MPI::Vector &du,
                    const unsigned int                   step,
                    const double                         load_factor);

    /**
     * One line of reactions.csv (the header is written with the first):
     * the force vector of each name (columns <name>_Fx, ...), the further
     * columns @p column_names with @p columns (the motions that follow
     * from a load: a rigid plate's along its normal, plate_<boundary
     * id>_u, a rigid body's along its load direction, <name>_u; with a
     * pore fluid the degree of consolidation, consolidation_degree) and
     * the step's lost load, a fraction (column imbalance).
     */
    void
    write_reactions(const unsigned int                 step,
                    const double                       load_factor,
                    const std::vector<std::string>    &names,
                    const std::vector<Tensor<1, dim>> &forces,
                    const std::vector<std::string>    &column_names,
                    const std::vector<double>         &columns,
                    const double                       imbalance);

    const Parameters &
    get_parameters() const;

    /**
     * Write the PVD records of the steps so far to @p out (for a
     * checkpoint; any rank).
     */
    void
    save(std::ostream &out) const;

    /**
     * Continue a run from a checkpoint at @p step: read the records that
     * save() wrote and rewrite the PVD files with them, and cut
     * reactions.csv back to the rows of the steps up to @p step (a run
     * that went on after the checkpoint wrote more), so that the next
     * rows are appended to it.
     */
    void
    resume(std::istream &in, const unsigned int step);

  private:
    const Parameters                            parameters;
    const MPI_Comm                              communicator;
    std::vector<std::pair<double, std::string>> point_records;
    std::vector<std::pair<double, std::string>> increment_records;
    std::unique_ptr<std::ofstream>              reactions_file;
  };
} // namespace qsmpm

#endif
