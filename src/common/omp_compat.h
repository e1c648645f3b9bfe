/* omp_compat.h - layer 0 (includes nothing of the project): one source
 * for threaded and serial builds: without OpenMP the calls below become
 * their one-thread answers. */
#ifndef CFPO_OMP_COMPAT_H
#define CFPO_OMP_COMPAT_H
#ifdef _OPENMP
#include <omp.h>
#else
static inline int omp_get_thread_num(void) { return 0; }
static inline int omp_get_num_procs(void) { return 1; }
static inline int omp_get_max_threads(void) { return 1; }
static inline double omp_get_wtime(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
#endif
#endif
