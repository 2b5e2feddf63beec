#ifndef qsmpm_particles_initial_measure_h
#define qsmpm_particles_initial_measure_h

#include <qsmpm/particles/material_point_set.h>

namespace qsmpm
{
  /**
   * A point's initial measure in the grid's plane (2D) or space (3D), from
   * its fields @p data: its initial volume, or in an axisymmetric problem,
   * whose volumes are per radian (R dA), its initial area dA, with the
   * initial radius R = x_0 - u_0 (@p x the point's material position, u its
   * displacement so far). The side of the square or cube of this measure is
   * the size of the point's box, with which it meets a body (RigidContact,
   * BodyContact).
   */
  template <int dim>
  inline double
  initial_measure(const double                                  *data,
                  const typename MaterialPointSet<dim>::Offsets &offsets,
                  const Point<dim>                              &x,
                  const bool                                     axisymmetric)
  {
    return axisymmetric ? data[offsets.initial_volume] /
                            (x[0] - data[offsets.displacement]) :
                          data[offsets.initial_volume];
  }
} // namespace qsmpm

#endif
