/* pd_main.h - the shared command line of cfpo-dart, cfpo-bs and
 * cfpo-bridson, and their default radii (README.md, "Radii", says how they
 * were measured). */
#ifndef CFPO_BASELINES_PD_MAIN_H
#define CFPO_BASELINES_PD_MAIN_H

enum { PD_DART = 0, PD_BS = 1, PD_BRIDSON = 2 };

/* Default relative radii r / Delta(n). */
#define PD_DART_REL 0.75
#define PD_BS_REL 0.8495
#define PD_BRIDSON_REL 0.7755
/* Dart throwing's saturation cap on consecutive rejected darts. */
#define PD_DART_MAX_FAILS 1000000

int pd_main(int argc, char **argv, int kind);

#endif
