/* fuzz_csv.c - libFuzzer harness: the CSV point-file reader (fuzz_points.h). */
#include "fuzz_points.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) { return fuzz_points(PF_CSV, data, size); }
