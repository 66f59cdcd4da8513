/* number.c - the strict decimal syntax every torusrt format reads its numbers with. */
#include "rt_number.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Longest number text read: far beyond any meaningful number, and the NUL-terminated copy
 * strtod needs fits on the stack. */
#define NUMBER_MAX_CHARS 400

static int is_digit(char c) { return c >= '0' && c <= '9'; }

/* Why the digits at s[i..] (the integer part) are not decimal, or RT_NUMBER_OK. */
static rt_number_fault integer_part(const char *s, size_t len, size_t i)
{
    if (i + 1 < len && s[i] == '0' && (s[i + 1] == 'x' || s[i + 1] == 'X')) return RT_NUMBER_HEX;
    if (i + 1 < len && s[i] == '0' && is_digit(s[i + 1])) return RT_NUMBER_LEADING_ZERO;
    return RT_NUMBER_OK;
}

/* The length of the real's syntax [-]DIGITS[.DIGITS][(e|E)[+-]DIGITS] at s, 0 if none. */
static size_t real_syntax(const char *s, size_t n)
{
    size_t i = 0, start;
    if (i < n && s[i] == '-') i++;
    start = i;
    while (i < n && is_digit(s[i])) i++;
    if (i == start) return 0;
    if (i < n && s[i] == '.') {
        size_t frac = ++i;
        while (i < n && is_digit(s[i])) i++;
        if (i == frac) return 0;
    }
    if (i < n && (s[i] == 'e' || s[i] == 'E')) {
        size_t exp;
        if (++i < n && (s[i] == '+' || s[i] == '-')) i++;
        exp = i;
        while (i < n && is_digit(s[i])) i++;
        if (i == exp) return 0;
    }
    return i;
}

/* Whether the mantissa digits of a real are all zero (its value is 0 whatever the exponent). */
static int zero_mantissa(const char *s, size_t n)
{
    for (size_t i = 0; i < n && s[i] != 'e' && s[i] != 'E'; i++)
        if (s[i] >= '1' && s[i] <= '9') return 0;
    return 1;
}

rt_number_fault rt_number_real(const char *text, size_t len, double *out)
{
    if (!text || len == 0) return RT_NUMBER_SYNTAX;
    rt_number_fault f = integer_part(text, len, text[0] == '-' ? 1 : 0);
    if (f != RT_NUMBER_OK) return f;
    if (real_syntax(text, len) != len) return RT_NUMBER_SYNTAX;
    if (len > NUMBER_MAX_CHARS) return RT_NUMBER_TOO_LARGE;
    char buf[NUMBER_MAX_CHARS + 1];
    memcpy(buf, text, len);
    buf[len] = '\0';
    errno = 0;
    double v = strtod(buf, NULL);
    if (!isfinite(v) || (errno == ERANGE && fabs(v) > 1.0)) return RT_NUMBER_TOO_LARGE;
    if (v == 0 && !zero_mantissa(text, len)) return RT_NUMBER_UNDERFLOW;
    *out = v;
    return RT_NUMBER_OK;
}

rt_number_fault rt_number_whole(const char *text, size_t len, unsigned long long max, unsigned long long *out)
{
    if (!text || len == 0) return RT_NUMBER_SYNTAX;
    rt_number_fault f = integer_part(text, len, 0);
    if (f != RT_NUMBER_OK) return f;
    unsigned long long v = 0;
    for (size_t i = 0; i < len; i++) {
        if (!is_digit(text[i])) return RT_NUMBER_SYNTAX;
        unsigned d = (unsigned)(text[i] - '0');
        if (d > max || v > (max - d) / 10) return RT_NUMBER_TOO_LARGE; /* v * 10 + d > max */
        v = v * 10 + d;
    }
    *out = v;
    return RT_NUMBER_OK;
}

const char *rt_number_fault_text(rt_number_fault fault)
{
    switch (fault) {
    case RT_NUMBER_OK: return "is a number";
    case RT_NUMBER_SYNTAX: return "is not a number (decimal, such as 2, -0.5 or 1e-3)";
    case RT_NUMBER_HEX: return "is not decimal (hexadecimal is not accepted)";
    case RT_NUMBER_LEADING_ZERO: return "has a leading zero (decimal only: it could be read as octal)";
    case RT_NUMBER_TOO_LARGE: return "is too large (not finite as a double)";
    case RT_NUMBER_UNDERFLOW: return "is too close to 0 for a double (it would read as 0)";
    }
    return "is not a number";
}
