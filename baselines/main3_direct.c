/* main3_direct.c - the commands of the 3-D baselines (bl3.h): the method
 * BL3_METHOD (cfpo3d-white, -jitter, -dart, -bridson, -wse, -fpo). */
#include "bl3.h"

#ifndef BL3_METHOD
#define BL3_METHOD bl3_white
#endif

extern const bl3_method BL3_METHOD;

int main(int argc, char **argv) { return bl3_main(argc, argv, &BL3_METHOD); }
