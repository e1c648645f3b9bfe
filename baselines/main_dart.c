/* main_dart.c - the `cfpo-dart` command; see pd_main.c. */
#include "pd_main.h"

extern const bl_method bl_dart;

int main(int argc, char **argv) { return pd_main(argc, argv, &bl_dart); }
