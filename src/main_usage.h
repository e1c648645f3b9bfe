/* main_usage.h - the `cfpo` command's help text (layer 5). */
#ifndef CFPO_MAIN_USAGE_H
#define CFPO_MAIN_USAGE_H

/* Prints `cfpo --help` on stdout. */
void cfpo_main_usage(void);

#endif
