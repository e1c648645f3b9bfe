/* solver_device.h - layer 1, device side: LocalCFPO on a CUDA device, from
 * the same source as the host solver (solver_impl.h). The first building
 * block of a CUDA backend (backend.h): a batch of independent local
 * problems, one device thread each, as the cells of one colour are.
 * Built only where the CUDA toolkit exists (CMake option CFPO_CUDA). */
#ifndef CFPO_SOLVER_DEVICE_H
#define CFPO_SOLVER_DEVICE_H

#include <stddef.h>

#include "geom.h"

#ifdef __cplusplus
extern "C" {
#endif

/* CUDA devices this process can use (0 when none, or no driver). */
int cfpo_cuda_devices(void);

/* Solves B independent problems on device 0. Problem b: the points
 * (yx[k], yy[k]) for k in [off[b], off[b + 1]), the index skip[b] among
 * them (-1: none), square S[b], hint (hx[b], hy[b]), floor2[b]; results in
 * val[b], cx[b], cy[b], exactly as cfpo_local_solve gives them on the host.
 * 0, or -1 with a one-line message (no device, out of memory, a CUDA
 * error). */
int cfpo_cuda_solve_batch(int B, const int *off, const double *yx, const double *yy, const int *skip,
                          const cfpo_square *S, const double *hx, const double *hy, const double *floor2,
                          double *val, double *cx, double *cy, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
