/* The von Mises UMAT of umat_von_mises.f written in C, for the tests
 * umat_*: the same PROPS (E, nu, yield stress, H), STATEV(1) = alpha and
 * formulas, as an extern "C" function umat_ with Fortran's calling
 * convention (everything by reference, DDSDDE column-major, CMNAME's
 * length appended). */
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
  const double E = props[0], nu = props[1], sy0 = props[2], H = props[3];
  const double G    = E / (2. * (1. + nu));
  const double lam  = E * nu / ((1. + nu) * (1. - 2. * nu));
  const double K    = lam + 2. * G / 3.;
  double      *D    = ddsdde; /* D[i + n j] = DDSDDE(i+1, j+1) */
  double       s[6], N[6];
  int          i, j;

  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j)
      D[i + n * j] = 0.;
  for (i = 0; i < nd; ++i)
    {
      for (j = 0; j < nd; ++j)
        D[i + n * j] = lam;
      D[i + n * i] = lam + 2. * G;
    }
  for (i = nd; i < n; ++i)
    D[i + n * i] = G;
  {
    double trial[6];
    for (i = 0; i < n; ++i)
      {
        trial[i] = stress[i];
        for (j = 0; j < n; ++j)
          trial[i] += D[i + n * j] * dstran[j];
      }
    for (i = 0; i < n; ++i)
      stress[i] = trial[i];
  }

  const double p     = (stress[0] + stress[1] + stress[2]) / 3.;
  double       snrm2 = 0.;
  for (i = 0; i < n; ++i)
    {
      s[i] = i < nd ? stress[i] - p : stress[i];
      snrm2 += (i < nd ? 1. : 2.) * s[i] * s[i];
    }
  const double snrm  = sqrt(snrm2);
  const double q_tr  = sqrt(1.5) * snrm;
  const double alpha = statev[0];
  const double sy    = sy0 + H * alpha;
  const double phi   = q_tr - sy;
  if (!(phi > 1e-13 * sy))
    return;

  const double dgam = phi / (3. * G + H);
  const double fac  = 1. - 3. * G * dgam / q_tr;
  for (i = 0; i < n; ++i)
    {
      N[i]      = s[i] / snrm;
      stress[i] = fac * s[i] + (i < nd ? p : 0.);
    }
  statev[0] = alpha + dgam;
  *spd += dgam * (sy + 0.5 * H * dgam);

  const double c1 = 6. * G * G * (dgam / q_tr - 1. / (3. * G + H));
  for (i = 0; i < n; ++i)
    for (j = 0; j < n; ++j)
      D[i + n * j] = c1 * N[i] * N[j];
  for (i = 0; i < nd; ++i)
    {
      for (j = 0; j < nd; ++j)
        D[i + n * j] += K - 2. * G * fac / 3.;
      D[i + n * i] += 2. * G * fac;
    }
  for (i = nd; i < n; ++i)
    D[i + n * i] += G * fac;
}
