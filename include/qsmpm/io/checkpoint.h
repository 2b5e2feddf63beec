#ifndef qsmpm_io_checkpoint_h
#define qsmpm_io_checkpoint_h

#include <deal.II/base/mpi.h>
#include <qsmpm/grid/background_grid.h>
#include <qsmpm/particles/material_point_set.h>
#include <string>

namespace qsmpm
{
  /**
   * Checkpoints of a run in its output directory, and reading them back.
   *
   * A checkpoint is a directory <tt>checkpoint-NNNNN</tt> (NNNNN: the number
   * of accepted load steps) holding
   * - the grid and the material points with all their properties, written
   *   by parallel::distributed::Triangulation::save() with the particles
   *   attached to their cells (Particles::ParticleHandler::
   *   prepare_for_serialization()), so that it can be read on any number of
   *   MPI ranks;
   * - <tt>state.txt</tt>: a description of the grid and the points (to
   *   refuse a checkpoint of another problem), followed by a text that the
   *   caller provides (QuasiStaticProblem: load stepper, step reports,
   *   output records, the user's state).
   *
   * A checkpoint is first written into <tt>checkpoint.tmp</tt> and renamed
   * (by rank 0, after all ranks have finished writing) only when complete.
   * The rename is atomic, so a run that is killed while writing leaves the
   * previous checkpoints intact and at worst a <tt>checkpoint.tmp</tt>,
   * which is ignored and overwritten. Of the complete checkpoints only the
   * newest @p keep are kept.
   *
   * The grid of qsmpm is never refined, so reading a checkpoint needs only
   * the same coarse grid: the caller builds grid and points exactly as for a
   * fresh run, and read() replaces the points (and the partition of the
   * cells) by those of the checkpoint.
   */
  template <int dim>
  class Checkpoint
  {
  public:
    /// Checkpoints in @p directory, written and read by all ranks of
    /// @p communicator.
    Checkpoint(const std::string &directory, const MPI_Comm communicator);

    /**
     * Write the checkpoint of step @p step (collective): grid, points and
     * @p state. Afterwards only the newest @p keep checkpoints are left.
     */
    void
    write(const unsigned int     step,
          BackgroundGrid<dim>   &grid,
          MaterialPointSet<dim> &points,
          const std::string     &state,
          const unsigned int     keep = 2) const;

    /**
     * The path of the newest complete checkpoint, or an empty string if
     * there is none (the same on all ranks).
     */
    std::string
    newest() const;

    /**
     * Read the checkpoint at @p path (collective): check that it belongs
     * to a problem with the grid and points of @p grid and @p points (set up
     * as for a fresh run; throws with a message if not), replace the points
     * by those of the checkpoint, distribute the degrees of freedom anew,
     * and return the caller's state text.
     */
    std::string
    read(const std::string     &path,
         BackgroundGrid<dim>   &grid,
         MaterialPointSet<dim> &points) const;

    /// The step number of a checkpoint directory name (e.g. checkpoint-00012
    /// gives 12), or numbers::invalid_unsigned_int if it is none.
    static unsigned int
    step_of(const std::string &name);

    /**
     * Keep the header line and the rows whose first field, the step, is at
     * most @p step of the CSV file @p filename (call on one rank only).
     * A resumed run then appends its rows instead of repeating steps.
     */
    static void
    truncate_csv(const std::string &filename, const unsigned int step);

  private:
    /// Grid and point facts that must agree between checkpoint and run.
    static std::string
    fingerprint(const BackgroundGrid<dim>   &grid,
                const MaterialPointSet<dim> &points);

    const std::string directory;
    const MPI_Comm    communicator;
  };
} // namespace qsmpm

#endif
