/* A UMAT that fails on purpose, for the test umat_bad_input: isotropic
 * linear elasticity (PROPS(1) = E, PROPS(2) = nu) that
 *  - asks for a smaller increment (PNEWDT = 0.5) when a component of
 *    DSTRAN exceeds PROPS(4) in magnitude, and
 *  - returns a stress of NaN when a component of the total strain
 *    STRAN + DSTRAN exceeds PROPS(3) in magnitude. */
#include <math.h>
#include <stddef.h>

void
umat_(double *stress, double *statev, double *ddsdde, double *sse,
      double *spd, double *scd, double *rpl, double *ddsddt, double *drplde,
      double *drpldt, double *stran, double *dstran, double *time,
      double *dtime, double *temp, double *dtemp, double *predef,
      double *dpred, char *cmname, int *ndi, int *nshr, int *ntens,
      int *nstatv, double *props, int *nprops, double *coords, double *drot,
      double *pnewdt, double *celent, double *dfgrd0, double *dfgrd1,
      int *noel, int *npt, int *layer, int *kspt, int *kstep, int *kinc,
      size_t cmname_length)
{
  const int    n = *ntens, nd = *ndi;
  const double E = props[0], nu = props[1];
  const double G   = E / (2. * (1. + nu));
  const double lam = E * nu / ((1. + nu) * (1. - 2. * nu));
  int          i, j;

  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j)
      ddsdde[i + n * j] = (i < nd && j < nd) ? lam : 0.;
  for (i = 0; i < n; ++i)
    ddsdde[i + n * i] += i < nd ? 2. * G : G;
  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j)
      stress[i] += ddsdde[i + n * j] * dstran[j];

  for (i = 0; i < n; ++i)
    {
      if (fabs(dstran[i]) > props[3])
        *pnewdt = 0.5;
      if (fabs(stran[i] + dstran[i]) > props[2])
        for (j = 0; j < n; ++j)
          stress[j] = NAN;
    }
}
