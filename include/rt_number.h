/* rt_number.h - the one strict decimal number syntax of every torusrt text format (motion files,
 * camera paths, map files, timing files) and of the options and machine files, whose C++ parser
 * (support/option_parsing.h) decides by these functions.
 *
 * Usage:
 *   double v;
 *   rt_number_fault f = rt_number_real(tok, strlen(tok), &v);
 *   if (f != RT_NUMBER_OK) printf("%s:%zu: '%s' %s\n", file, line, tok, rt_number_fault_text(f));
 *
 * A real is [-]DIGITS[.DIGITS][(e|E)[+-]DIGITS]; a whole number is DIGITS. The integer digits
 * have no leading zero ("0" itself and "0.5" are fine): "010" could be meant as octal 8. No "+",
 * no ".5" or "5.", no hexadecimal, inf or nan. A real whose value does not fit a double, too
 * large or so close to 0 that it would read as 0 ("1e-400"), is refused; a subnormal value
 * ("4e-320") is not 0 and is read.
 */
#ifndef RT_NUMBER_H
#define RT_NUMBER_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum rt_number_fault {
    RT_NUMBER_OK = 0,
    RT_NUMBER_SYNTAX,       /* not a decimal number of the syntax above */
    RT_NUMBER_HEX,          /* 0x... */
    RT_NUMBER_LEADING_ZERO, /* 010 */
    RT_NUMBER_TOO_LARGE,    /* beyond a double, or above the whole number's maximum */
    RT_NUMBER_UNDERFLOW     /* not 0 as written, but 0 as a double */
} rt_number_fault;

/* Reads text[0..len) as a real into *out (untouched on a fault). */
rt_number_fault rt_number_real(const char *text, size_t len, double *out);

/* Reads text[0..len) as a whole number in [0, max] into *out (untouched on a fault). */
rt_number_fault rt_number_whole(const char *text, size_t len, unsigned long long max, unsigned long long *out);

/* What a fault means, to follow the quoted text: "is not a decimal number ...". */
const char *rt_number_fault_text(rt_number_fault fault);

#ifdef __cplusplus
}
#endif
#endif
