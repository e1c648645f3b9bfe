/* main_bs.c - the `cfpo-bs` command; see pd_main.c. */
#include "pd_main.h"

extern const bl_method bl_bs;

int main(int argc, char **argv) { return pd_main(argc, argv, &bl_bs); }
