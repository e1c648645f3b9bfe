/* main_bridson.c - the `cfpo-bridson` command; see pd_main.c. */
#include "pd_main.h"

extern const bl_method bl_bridson;

int main(int argc, char **argv) { return pd_main(argc, argv, &bl_bridson); }
