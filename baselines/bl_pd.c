/* bl_pd.c - the Poisson-disk samplers (pd.h) as baseline methods
 * (bl_method.h): dart throwing, boundary sampling and Bridson, their
 * options with ranges and defaults, and their default radii. The run is
 * pd_check.h's. */
#include "bl_method.h"
#include "pd_check.h"

#define RADIUS                                                                                                   \
    {.cli = "radius", .py = "radius", .letter = 'r', .type = BL_REAL, .min = 0, .max = 1, .open_min = 1,        \
     .def = -1, .bad = "is not a number in (0, 1]"}
#define REL_RADIUS                                                                                               \
    {.cli = "rel-radius", .py = "rel_radius", .type = BL_REAL, .min = 0, .max = 2, .open_min = 1, .def = -1,    \
     .bad = "is not a number in (0, 2]"}

static const bl_option DART_OPTS[] = {
    RADIUS, REL_RADIUS,
    {.cli = "max-fails", .py = "max_fails", .type = BL_INT, .lo = 1, .hi = INT64_MAX, .def = PD_DART_MAX_FAILS,
     .bad = "is not a positive whole number"},
};
static const bl_option BS_OPTS[] = {RADIUS, REL_RADIUS};
static const bl_option BRIDSON_OPTS[] = {
    RADIUS, REL_RADIUS,
    {.cli = "candidates", .py = "k", .letter = 'k', .type = BL_INT, .lo = 1, .hi = 1000000, .def = 30,
     .bad = "is not a whole number in 1..1e6"},
    {.cli = "plain", .py = "plain", .type = BL_FLAG, .def = 0},
};

const bl_method bl_dart = {
    .name = "dart", .prog = "cfpo-dart", .kind = BL_POISSON,
    .about = "Dart throwing (Cook 1986): uniform darts, each kept when no earlier point\n"
             "lies within r.",
    BL_OPTIONS(DART_OPTS), .pd_kind = PD_DART, .pd_rel = PD_DART_REL,
};
const bl_method bl_bs = {
    .name = "bs", .prog = "cfpo-bs", .kind = BL_POISSON,
    .about = "Boundary sampling (Dunbar & Humphreys 2006): a maximal Poisson-disk set grown\n"
             "on the uncovered boundary arcs of the samples' disks.",
    BL_OPTIONS(BS_OPTS), .pd_kind = PD_BS, .pd_rel = PD_BS_REL,
};
const bl_method bl_bridson = {
    .name = "bridson", .prog = "cfpo-bridson", .kind = BL_POISSON,
    .about = "Bridson's fast Poisson-disk sampling (2007), made maximal by an exact check\n"
             "of a sample's free boundary arcs before it is retired.",
    BL_OPTIONS(BRIDSON_OPTS), .pd_kind = PD_BRIDSON, .pd_rel = PD_BRIDSON_REL,
};
