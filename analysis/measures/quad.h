/* quad.h - the accumulation type of the exact measures.
 *
 * Owns: an_quad, the widest floating type at hand: IEEE binary128 (113
 * bits, __float128 in software on x86-64) where the compiler has it, else
 * long double (binary128 on AArch64 Linux, 64 bits on x87, only double's
 * 53 on some ABIs, where the discrepancies of large sets lose their
 * digits). The
 * discrepancies subtract sums of n^2 terms of size 1 to leave results near
 * n^-2 (1e-12 at a million points): in binary128 the rounding stays below
 * 1e-15 of the result; in x87 long double it reaches 1e-8 at a million
 * points; in double it would be all of it. AN_QUAD_NAME says which one a
 * build has (stats.json reports it). */
#ifndef AN_QUAD_H
#define AN_QUAD_H

#if defined(__SIZEOF_FLOAT128__) && (defined(__x86_64__) || defined(__i386__))
typedef __float128 an_quad;
#define AN_QUAD_NAME "binary128"
#else
typedef long double an_quad;
#include <float.h>
#define AN_QUAD_NAME (LDBL_MANT_DIG >= 113 ? "binary128" : LDBL_MANT_DIG >= 64 ? "x87 long double" : "double")
#endif

#endif
