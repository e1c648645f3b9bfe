/* quad.h - the accumulation type of the exact measures.
 *
 * Owns: an_quad, a floating type of at least 64 significant bits: IEEE
 * binary128 (113 bits, __float128 in software on x86-64) where the compiler
 * has it, else long double (binary128 on AArch64, 64 bits on x87). The
 * discrepancies subtract sums of n^2 terms of size 1 to leave results near
 * n^-2 (1e-12 at a million points): in binary128 the rounding stays below
 * 1e-20 of the result; in double it would be all of it. */
#ifndef AN_QUAD_H
#define AN_QUAD_H

#if defined(__SIZEOF_FLOAT128__) && (defined(__x86_64__) || defined(__i386__))
typedef __float128 an_quad;
#define AN_QUAD_NAME "binary128"
#else
typedef long double an_quad;
#define AN_QUAD_NAME "long double"
#endif

#endif
