#ifndef qsmpm_materials_umat_library_h
#define qsmpm_materials_umat_library_h

#include <cstddef>
#include <string>

namespace qsmpm
{
  /**
   * The Abaqus/Standard UMAT interface as gfortran compiles
   *
   *   SUBROUTINE UMAT(STRESS,STATEV,DDSDDE,SSE,SPD,SCD,RPL,DDSDDT,DRPLDE,
   *  1 DRPLDT,STRAN,DSTRAN,TIME,DTIME,TEMP,DTEMP,PREDEF,DPRED,CMNAME,
   *  2 NDI,NSHR,NTENS,NSTATV,PROPS,NPROPS,COORDS,DROT,PNEWDT,CELENT,
   *  3 DFGRD0,DFGRD1,NOEL,NPT,LAYER,KSPT,KSTEP,KINC)
   *
   * with the default 4-byte INTEGER and 8-byte REAL (the Abaqus include
   * file ABA_PARAM.INC's IMPLICIT REAL*8(A-H,O-Z)): every argument by
   * reference, arrays in column-major order, and the length of the
   * CHARACTER*80 CMNAME appended as a hidden argument by value (size_t
   * since gfortran 8). A C UMAT is the same function with the name umat_
   * and extern "C" linkage.
   */
  using UmatFunction = void (*)(double     *stress,
                                double     *statev,
                                double     *ddsdde,
                                double     *sse,
                                double     *spd,
                                double     *scd,
                                double     *rpl,
                                double     *ddsddt,
                                double     *drplde,
                                double     *drpldt,
                                double     *stran,
                                double     *dstran,
                                double     *time,
                                double     *dtime,
                                double     *temp,
                                double     *dtemp,
                                double     *predef,
                                double     *dpred,
                                char       *cmname,
                                int        *ndi,
                                int        *nshr,
                                int        *ntens,
                                int        *nstatv,
                                double     *props,
                                int        *nprops,
                                double     *coords,
                                double     *drot,
                                double     *pnewdt,
                                double     *celent,
                                double     *dfgrd0,
                                double     *dfgrd1,
                                int        *noel,
                                int        *npt,
                                int        *layer,
                                int        *kspt,
                                int        *kstep,
                                int        *kinc,
                                std::size_t cmname_length);

  /**
   * The function @p symbol of the shared library @p library (a path, or a
   * name the dynamic linker finds), loaded with dlopen(RTLD_NOW). The
   * library stays loaded for the rest of the process (a Fortran runtime
   * does not like being unloaded). Throws, with a message naming the entry
   * "UMAT library" or "Symbol" and the linker's reason, if the library
   * cannot be loaded or has no such symbol.
   */
  UmatFunction
  load_umat(const std::string &library, const std::string &symbol);
} // namespace qsmpm

#endif
