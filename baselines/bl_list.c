/* bl_list.c - the list of the baseline methods (bl_method.h), one row
 * each, in the order of scripts/methods.tsv; read by the Python binding.
 * The commands name their own row directly. */
#include <string.h>

#include "bl_method.h"

extern const bl_method bl_dart, bl_bs, bl_bridson, bl_fpo, bl_lfpo, bl_ccvt, bl_ccdt, bl_bnot, bl_white, bl_jitter,
    bl_sobol, bl_lloyd, bl_gbn, bl_wse, bl_pmj02bn;

const bl_method *const bl_methods[] = {&bl_dart, &bl_bs, &bl_bridson, &bl_fpo, &bl_lfpo,
                                       &bl_ccvt, &bl_ccdt, &bl_bnot, &bl_white, &bl_jitter,
                                       &bl_sobol, &bl_lloyd, &bl_gbn, &bl_wse, &bl_pmj02bn, NULL};

const bl_method *bl_method_find(const char *name)
{
    for (int i = 0; bl_methods[i]; i++)
        if (strcmp(bl_methods[i]->name, name) == 0) return bl_methods[i];
    return NULL;
}
