/* main_bridson.c - the `cfpo-bridson` command; see pd_main.c. */
#include "pd_main.h"

int main(int argc, char **argv) { return pd_main(argc, argv, PD_BRIDSON); }
