/* signal_cleanup_c.h - signal_cleanup.h's stopping signals for a C program (torusrt-genscenes).
 *
 * Usage:
 *   torusrt_stop_on_signals("torusrt-genscenes");      first thing in main
 *   size_t slot;
 *   int fd = torusrt_mkstemp_removed_on_signal(tmp, &slot);   mkstemp(tmp), removed on a signal
 *   ...  rename(tmp, path);
 *   torusrt_forget_on_signal(slot);                    the program's own file from now on
 * A stopping signal removes the registered files, prints "PROGRAM: stopped by SIGNAME" and exits
 * 128 + the signal's number, as the other executables end (signal_cleanup.h).
 */
#ifndef TORUSRT_SIGNAL_CLEANUP_C_H
#define TORUSRT_SIGNAL_CLEANUP_C_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Installs the handler of the stopping signals; PROGRAM starts its message. */
void torusrt_stop_on_signals(const char *program);
/* mkstemp(TMPL) with the stopping signals held back until the new file is registered in *SLOT
 * (so that no signal leaves it behind); returns the descriptor, or -1 with errno (no slot). */
int torusrt_mkstemp_removed_on_signal(char *tmpl, size_t *slot);
/* Drops the registration of SLOT (the file was renamed or removed by the program). */
void torusrt_forget_on_signal(size_t slot);

#ifdef __cplusplus
}
#endif

#endif
