/* certify.h - an exact certificate that a set on the unit torus is a
 * Farthest Point Distribution (FPD): no single point can be moved to
 * increase its distance to the rest.
 *
 * Two independent exact tests per point x, both built on the core's exact
 * LocalCFPO solver (cfpo_local_solve: the farthest point of a square from a
 * finite set), with neighbourhoods proven large enough (certify.c):
 *
 *  farthest point test: the largest empty circle of X \ {x} on the torus
 *    has radius <= d(x, X \ {x}) + tol. Violation = radius - d(x, X\{x}).
 *  Local Characterization Theorem (Chen & Gotsman, section 3.2), with
 *    delta = delta(X), D(x) = the square of half-side
 *    h = max(3 delta, delta + d(x, X\{x}), Delta(n)) around x and
 *    S(x) = D(x) eroded by delta:
 *    property 1 (local covering): every point of S(x) lies within
 *      delta + tol of a point of X in D(x);
 *    property 2 (local farthest point): no point of S(x) is farther than
 *      d(x, Y(x)) + tol from Y(x) = the points of X \ {x} in D(x).
 * X is an FPD iff every point passes the first test, iff every point
 * passes both properties (the theorem; this D(x) contains the disk of
 * radius delta + d(x, X\{x}) its proof needs). Violations are reported
 * divided by Delta(n); tol = tol_rel * Delta(n). */
#ifndef AN_CERTIFY_H
#define AN_CERTIFY_H

#include <stddef.h>

#define AN_CERT_TOL 1e-3 /* default tolerance, relative to Delta(n) */

typedef struct {
    size_t n;
    double tol_rel;
    double delta;            /* delta(X) / Delta(n) */
    double covering;         /* largest empty circle of X / Delta(n) */
    size_t fp_pass;          /* points passing the farthest point test */
    double fp_max_violation; /* / Delta(n); may be negative */
    size_t fp_worst;         /* index of the point with that violation */
    size_t p1_pass, p2_pass, lct_pass; /* lct: both properties */
    double p1_max_violation, p2_max_violation;
    int fpd;                 /* 1: every point passes both tests */
} an_certificate;

/* n >= 2. Optional outputs (NULL to skip): viol[i] = the farthest point
 * violation of point i / Delta(n); target[2i], target[2i+1] = a point of
 * the torus farthest from X \ {x_i} (where moving x_i would help most).
 * 0, or -1 with a message (out of memory, solver failure). */
int an_certify(const double *xy, size_t n, double tol_rel, an_certificate *c, double *viol,
               double *target, char *err, size_t errlen);

/* an_certify with each point's verdict too: pass[i] (n bytes, may be
 * NULL) holds AN_PASS_FP when point i passes the farthest point test,
 * AN_PASS_P1 / AN_PASS_P2 when it satisfies property 1 / 2. */
enum { AN_PASS_FP = 1, AN_PASS_P1 = 2, AN_PASS_P2 = 4 };
int an_certify_points(const double *xy, size_t n, double tol_rel, an_certificate *c, double *viol,
                      double *target, unsigned char *pass, char *err, size_t errlen);

/* Adds b into a (sums counts, keeps the largest violations; fpd = both). */
void an_certificate_merge(an_certificate *a, const an_certificate *b);

#endif
