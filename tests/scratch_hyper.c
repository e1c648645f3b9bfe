/* scratch_hyper.c - research prototype (not built by CMake): the constrained
 * low-frequency transport step on a point set of the unit torus.
 *
 *   cc -O2 -o /tmp/hyper tests/scratch_hyper.c -lm
 *   /tmp/hyper IN.txt OUT.txt STEPS THETA KC LAMBDA MODE
 *
 * One step: rho_hat(k) = sum_j exp(-2 pi i k.x_j) over 0 < |k| <= KC sqrt(n);
 * u(x) = sum_k -i k rho_hat(k) / (2 pi n |k|^2) exp(2 pi i k.x) (the
 * linearised transport that removes those modes); then every point in id
 * order (Gauss-Seidel) moves along LAMBDA u(x_j), stopped where it would come
 * nearer than THETA Delta(n) to another point (MODE 0), or, once stopped,
 * slides on along the blocking circle's tangent (MODE 1). THETA <= delta(X)
 * keeps delta(X) >= THETA Delta(n) through every step. Prints per step
 * dmin, davg (relative to Delta(n)), P0 (mean P over 25|k|^2 <= n). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int n;
static double *X;

static double wrap(double d) { return d - floor(d + 0.5); }

typedef struct { int kx, ky; } mode;

static mode *modes_upto(double kc, int *m)
{
    int K = (int)floor(kc), cnt = 0;
    mode *M = malloc(sizeof(mode) * (size_t)(2 * K + 1) * (2 * K + 1));
    for (int ky = 0; ky <= K; ky++)
        for (int kx = -K; kx <= K; kx++) {
            if (ky == 0 && kx <= 0) continue;
            if ((double)kx * kx + (double)ky * ky > kc * kc) continue;
            M[cnt].kx = kx;
            M[cnt].ky = ky;
            cnt++;
        }
    *m = cnt;
    return M;
}

/* e^{-2 pi i k x} for k = -K..K by recurrence from one sincos. */
static void powers(double x, int K, double *re, double *im)
{
    const double c = cos(2 * M_PI * x), s = -sin(2 * M_PI * x);
    re[K] = 1, im[K] = 0;
    for (int k = 1; k <= K; k++) {
        re[K + k] = re[K + k - 1] * c - im[K + k - 1] * s;
        im[K + k] = re[K + k - 1] * s + im[K + k - 1] * c;
        re[K - k] = re[K + k], im[K - k] = -im[K + k];
    }
}

static int KK;
static double *exr, *exi, *eyr, *eyi;

static void rho_hat(const mode *M, int m, double *re, double *im)
{
    memset(re, 0, sizeof(double) * m);
    memset(im, 0, sizeof(double) * m);
    for (int j = 0; j < n; j++) {
        powers(X[2 * j], KK, exr, exi);
        powers(X[2 * j + 1], KK, eyr, eyi);
        for (int q = 0; q < m; q++) {
            const double ar = exr[KK + M[q].kx], ai = exi[KK + M[q].kx];
            const double br = eyr[KK + M[q].ky], bi = eyi[KK + M[q].ky];
            re[q] += ar * br - ai * bi;
            im[q] += ar * bi + ai * br;
        }
    }
}

static double p0(void)
{
    int m;
    mode *M = modes_upto(sqrt(n / 25.0), &m);
    /* exact: 25|k|^2 <= n */
    double *re = malloc(sizeof(double) * m), *im = malloc(sizeof(double) * m);
    rho_hat(M, m, re, im);
    double s = 0;
    int c = 0;
    for (int q = 0; q < m; q++) {
        double k2 = (double)M[q].kx * M[q].kx + (double)M[q].ky * M[q].ky;
        if (25 * k2 > n) continue;
        s += (re[q] * re[q] + im[q] * im[q]) / n;
        c++;
    }
    free(M), free(re), free(im);
    return s / c;
}

static void deltas(double *dmin, double *davg)
{
    /* brute force over a cell grid of side >= 2 Delta */
    double D = sqrt(2 / (sqrt(3) * n));
    int g = (int)floor(1 / (2 * D));
    int *head = malloc(sizeof(int) * g * g), *next = malloc(sizeof(int) * n);
    for (int c = 0; c < g * g; c++) head[c] = -1;
    for (int j = 0; j < n; j++) {
        int cx = (int)(X[2 * j] * g) % g, cy = (int)(X[2 * j + 1] * g) % g;
        next[j] = head[cy * g + cx];
        head[cy * g + cx] = j;
    }
    double mn = 1e9, sum = 0;
    for (int j = 0; j < n; j++) {
        int cx = (int)(X[2 * j] * g) % g, cy = (int)(X[2 * j + 1] * g) % g;
        double best = 1e9;
        for (int dy = -1; dy <= 1; dy++)
            for (int dx = -1; dx <= 1; dx++) {
                int c = ((cy + dy + g) % g) * g + (cx + dx + g) % g;
                for (int i = head[c]; i >= 0; i = next[i]) {
                    if (i == j) continue;
                    double ex = wrap(X[2 * i] - X[2 * j]), ey = wrap(X[2 * i + 1] - X[2 * j + 1]);
                    double d = ex * ex + ey * ey;
                    if (d < best) best = d;
                }
            }
        best = sqrt(best);
        sum += best;
        if (best < mn) mn = best;
    }
    *dmin = mn / D;
    *davg = sum / n / D;
    free(head), free(next);
}

int main(int argc, char **argv)
{
    if (argc < 8) return 2;
    FILE *f = fopen(argv[1], "r");
    int cap = 1 << 16;
    X = malloc(sizeof(double) * 2 * cap);
    n = 0;
    while (fscanf(f, "%lf %lf", &X[2 * n], &X[2 * n + 1]) == 2) {
        if (++n == cap) X = realloc(X, sizeof(double) * 2 * (cap *= 2));
    }
    fclose(f);
    int steps = atoi(argv[3]), mode_ = atoi(argv[7]);
    double theta = atof(argv[4]), kc = atof(argv[5]) * sqrt(n), lam = atof(argv[6]);
    double D = sqrt(2 / (sqrt(3) * n)), th = theta * D, vmax = 0.3 * D;
    int m;
    mode *M = modes_upto(kc, &m);
    KK = (int)floor(fmax(kc, sqrt(n / 25.0))) + 1;
    exr = malloc(sizeof(double) * (2 * KK + 1)), exi = malloc(sizeof(double) * (2 * KK + 1));
    eyr = malloc(sizeof(double) * (2 * KK + 1)), eyi = malloc(sizeof(double) * (2 * KK + 1));
    double *re = malloc(sizeof(double) * m), *im = malloc(sizeof(double) * m);
    double *U = malloc(sizeof(double) * 2 * n);
    double dmin, davg;
    deltas(&dmin, &davg);
    printf("step 0 dmin %.4f davg %.4f P0 %.3g\n", dmin, davg, p0());
    if (theta < 0) th = dmin * D * (1 - 1e-12); /* THETA < 0: delta(X) itself */
    int g = (int)floor(1 / (th + 2 * vmax));
    int *head = malloc(sizeof(int) * g * g), *next = malloc(sizeof(int) * n);
    double *Y0 = malloc(sizeof(double) * 2 * n);
    for (int st = 1; st <= steps; st++) {
        rho_hat(M, m, re, im);
        for (int j = 0; j < n; j++) {
            double ux = 0, uy = 0;
            powers(X[2 * j], KK, exr, exi);
            powers(X[2 * j + 1], KK, eyr, eyi);
            for (int q = 0; q < m; q++) {
                double k2 = (double)M[q].kx * M[q].kx + (double)M[q].ky * M[q].ky;
                const double ar = exr[KK + M[q].kx], ai = -exi[KK + M[q].kx];
                const double br = eyr[KK + M[q].ky], bi = -eyi[KK + M[q].ky];
                double c = ar * br - ai * bi, s = ar * bi + ai * br; /* e^{ia} */
                double t = (re[q] * s + im[q] * c) / (2 * M_PI * n * k2);
                ux += 2 * M[q].kx * t;
                uy += 2 * M[q].ky * t;
            }
            double l = lam * sqrt(ux * ux + uy * uy);
            double sc = l > vmax ? vmax / l : 1;
            U[2 * j] = lam * ux * sc;
            U[2 * j + 1] = lam * uy * sc;
        }
        memcpy(Y0, X, sizeof(double) * 2 * n);
        for (int c = 0; c < g * g; c++) head[c] = -1;
        for (int j = 0; j < n; j++) {
            int cx = (int)(X[2 * j] * g) % g, cy = (int)(X[2 * j + 1] * g) % g;
            next[j] = head[cy * g + cx];
            head[cy * g + cx] = j;
        }
        for (int j = 0; j < n; j++) {
            int cx = (int)(Y0[2 * j] * g) % g, cy = (int)(Y0[2 * j + 1] * g) % g;
            double vx = U[2 * j], vy = U[2 * j + 1];
            for (int pass = 0; pass < (mode_ ? 2 : 1); pass++) {
                double a = vx * vx + vy * vy, s = 1;
                int block = -1;
                if (a == 0) break;
                for (int dy = -1; dy <= 1; dy++)
                    for (int dx = -1; dx <= 1; dx++) {
                        int cc = ((cy + dy + g) % g) * g + (cx + dx + g) % g;
                        for (int i = head[cc]; i >= 0; i = next[i]) {
                            if (i == j) continue;
                            double ex = wrap(X[2 * j] - X[2 * i]), ey = wrap(X[2 * j + 1] - X[2 * i + 1]);
                            double b = 2 * (ex * vx + ey * vy), c0 = ex * ex + ey * ey - th * th;
                            if (b >= 0) continue;
                            double disc = b * b - 4 * a * c0;
                            if (disc <= 0) continue;
                            double s1 = (-b - sqrt(disc)) / (2 * a);
                            if (s1 < 0) s1 = 0;
                            if (s1 < s) s = s1, block = i;
                        }
                    }
                s *= 1 - 1e-9;
                X[2 * j] += s * vx;
                X[2 * j + 1] += s * vy;
                X[2 * j] -= floor(X[2 * j]);
                X[2 * j + 1] -= floor(X[2 * j + 1]);
                if (block < 0) break;
                /* rest of the move, tangential to the blocking circle */
                double ex = wrap(X[2 * j] - X[2 * block]), ey = wrap(X[2 * j + 1] - X[2 * block + 1]);
                double e2 = ex * ex + ey * ey, rx = (1 - s) * vx, ry = (1 - s) * vy;
                double pr = (rx * ex + ry * ey) / e2;
                vx = rx - pr * ex;
                vy = ry - pr * ey;
            }
        }
        deltas(&dmin, &davg);
        printf("step %d dmin %.4f davg %.4f P0 %.3g\n", st, dmin, davg, st == steps ? p0() : NAN);
        fflush(stdout);
    }
    f = fopen(argv[2], "w");
    for (int j = 0; j < n; j++) fprintf(f, "%.17g %.17g\n", X[2 * j], X[2 * j + 1]);
    fclose(f);
    return 0;
}
