/* nff_writer.h - deterministic numbers for torusrt-genscenes, and writing a scene as NFF.
 *
 * Usage:
 *   double r = q9(sqrt(2.0));            // 1.41421356: libm's last bits dropped
 *   lcg_seed(20240601); double u = lcg_next();
 *   writer wr = {f, 1e-6};               // positions and lengths times 1e-6
 *   write_scene(&wr, "scale-tiny", "one-line description", sc);
 *
 * Nothing here reads a clock or calls rand(): the same scene writes the same bytes. Errors
 * while writing are left in the FILE (check ferror).
 */
#ifndef GEN_NFF_WRITER_H
#define GEN_NFF_WRITER_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "scene.h"

/* Rounds to 9 significant digits, so values computed with libm do not carry its last bits. */
double q9(double x);
vec3 q9v(vec3 a);

/* Fixed-seed LCG (Knuth's MMIX constants); lcg_next returns a double in [0, 1). */
void lcg_seed(uint64_t seed);
double lcg_next(void);

/* Shortest "%.*g" decimal that reads back as x, without an exponent for 1e-4 <= |x| < 1e17
 * (30, not 3e+01); -0 prints as 0. Writes into buf (40 bytes is enough) and returns it. */
const char *num(char *buf, size_t n, double x);

typedef struct {
    FILE *f;
    double scale; /* applied to every position and length; not to colours or directions */
} writer;

/* Writes the header comment ("# torusrt scene NAME: DESC", the notes, the object count),
 * the view, background, ambient, lights and items of `sc` to wr->f. */
void write_scene(writer *wr, const char *name, const char *desc, const scene *sc);

#endif
