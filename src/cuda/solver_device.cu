/* solver_device.cu - see solver_device.h. Built with --fmad=false and IEEE
 * division and square root (CMakeLists.txt), like the host's
 * -ffp-contract=off, so the device's bits are the host's. */
#include "solver_device.h"

#include <cuda_runtime.h>
#include <stdio.h>

#include "solver_impl.h"

/* One thread a problem; scratch of problem b starts at 8 (off[b] + 8 b),
 * cfpo_solver_scratch(m) doubles for its m points. */
__global__ static void solve_batch(int B, const int *off, const double *yx, const double *yy, const int *skip,
                                   const cfpo_square *S, const double *hx, const double *hy, const double *floor2,
                                   double *scratch, double *val, double *cx, double *cy)
{
    const int b = blockIdx.x * blockDim.x + threadIdx.x;
    if (b >= B) return;
    const int a = off[b], m = off[b + 1] - a;
    double *sc = scratch + 8 * ((size_t)a + 8 * (size_t)b);
    val[b] = cfpo_local_solve_hd(yx + a, yy + a, m, skip[b], S[b], hx[b], hy[b], floor2[b], &cx[b], &cy[b], sc);
}

extern "C" int cfpo_cuda_devices(void)
{
    int n = 0;
    if (cudaGetDeviceCount(&n) != cudaSuccess) return 0;
    return n;
}

/* Device buffers of one batch. */
struct batch {
    int *off, *skip;
    double *yx, *yy, *hx, *hy, *floor2, *scratch, *val, *cx, *cy;
    cfpo_square *S;
};

static void free_batch(batch *d)
{
    void *p[] = {d->off, d->skip, d->yx, d->yy, d->hx, d->hy, d->floor2, d->scratch, d->val, d->cx, d->cy, d->S};
    for (void *q : p) cudaFree(q);
}

static int fail(cudaError_t e, const char *what, char *err, size_t errlen)
{
    snprintf(err, errlen, "CUDA: %s: %s", what, cudaGetErrorString(e));
    return -1;
}

extern "C" int cfpo_cuda_solve_batch(int B, const int *off, const double *yx, const double *yy, const int *skip,
                                     const cfpo_square *S, const double *hx, const double *hy,
                                     const double *floor2, double *val, double *cx, double *cy, char *err,
                                     size_t errlen)
{
    if (cfpo_cuda_devices() == 0) {
        snprintf(err, errlen, "no CUDA device");
        return -1;
    }
    const size_t np = (size_t)off[B], nb = (size_t)B;
    batch d = {};
    cudaError_t e = cudaSuccess;
#define ALLOC(f, count) \
    if (e == cudaSuccess) e = cudaMalloc((void **)&d.f, (count) * sizeof *d.f)
    ALLOC(off, nb + 1); ALLOC(skip, nb); ALLOC(yx, np + 1); ALLOC(yy, np + 1); ALLOC(hx, nb); ALLOC(hy, nb);
    ALLOC(floor2, nb); ALLOC(val, nb); ALLOC(cx, nb); ALLOC(cy, nb); ALLOC(S, nb);
    ALLOC(scratch, 8 * (np + 8 * nb));
#undef ALLOC
    if (e != cudaSuccess) {
        free_batch(&d);
        return fail(e, "out of device memory", err, errlen);
    }
#define UP(f, src, count) \
    if (e == cudaSuccess) e = cudaMemcpy(d.f, src, (count) * sizeof *d.f, cudaMemcpyHostToDevice)
    UP(off, off, nb + 1); UP(skip, skip, nb); UP(yx, yx, np); UP(yy, yy, np); UP(hx, hx, nb); UP(hy, hy, nb);
    UP(floor2, floor2, nb); UP(S, S, nb);
#undef UP
    if (e == cudaSuccess) {
        solve_batch<<<(B + 127) / 128, 128>>>(B, d.off, d.yx, d.yy, d.skip, d.S, d.hx, d.hy, d.floor2, d.scratch,
                                             d.val, d.cx, d.cy);
        e = cudaGetLastError();
    }
    if (e == cudaSuccess) e = cudaDeviceSynchronize();
#define DOWN(dst, f) \
    if (e == cudaSuccess) e = cudaMemcpy(dst, d.f, nb * sizeof *d.f, cudaMemcpyDeviceToHost)
    DOWN(val, val); DOWN(cx, cx); DOWN(cy, cy);
#undef DOWN
    free_batch(&d);
    return e == cudaSuccess ? 0 : fail(e, "the solve kernel failed", err, errlen);
}
