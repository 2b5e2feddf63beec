#ifndef qsmpm_io_probe_writer_h
#define qsmpm_io_probe_writer_h

#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <fstream>
#include <memory>
#include <qsmpm/particles/material_point_set.h>
#include <string>
#include <vector>

namespace qsmpm
{
  /**
   * Results at a few places without a visualization program: probes.csv,
   * one line per step with the position, displacement and stress of the
   * material point nearest to each probe position. The probes are given in
   * the initial configuration and follow their points as the body deforms
   * (and the points migrate between cells and MPI ranks): each probe keeps
   * the id of the point nearest to it when select() is called. Only rank 0
   * writes.
   */
  template <int dim>
  class ProbeWriter
  {
  public:
    /// Probes at @p positions; probes.csv goes to @p directory.
    ProbeWriter(const std::vector<Point<dim>> &positions,
                const std::string             &directory,
                const MPI_Comm                 communicator);

    /// Whether there is any probe.
    bool
    empty() const;

    /**
     * Take, for each probe, the point of @p points nearest to it (in the
     * points' initial positions, x - u), and write the header of
     * probes.csv.
     */
    void
    select(const MaterialPointSet<dim> &points);

    /// One line of probes.csv.
    void
    write(const MaterialPointSet<dim> &points,
          const unsigned int           step,
          const double                 load_factor);

  private:
    const std::vector<Point<dim>>      positions;
    const std::string                  directory;
    const MPI_Comm                     communicator;
    std::vector<types::particle_index> ids;
    std::unique_ptr<std::ofstream>     file;
  };
} // namespace qsmpm

#endif
