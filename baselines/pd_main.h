/* pd_main.h - the shared command line of cfpo-dart, cfpo-bs and
 * cfpo-bridson (pd_main.c). */
#ifndef CFPO_BASELINES_PD_MAIN_H
#define CFPO_BASELINES_PD_MAIN_H

#include "bl_method.h"

int pd_main(int argc, char **argv, const bl_method *m);

#endif
