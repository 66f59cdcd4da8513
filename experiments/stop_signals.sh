# shellcheck shell=bash
# stop_signals.sh - the stopping signals of the shell tools of experiments/ (sourced by lib.sh and
# run_point.sh, not run): each ends the script as torusrt-sim ends on it (support/signal_cleanup.cpp,
# stop_signals.py for the Python tools), its running command stopped first.
# The signals that stop torusrt-sim but PIPE (support/signal_cleanup.cpp), NAME:NUMBER.
STOP_SIGNALS=(INT:2 TERM:15 HUP:1 QUIT:3 USR1:10 USR2:12 ALRM:14)
STOP_CHILD=""
# in_child COMMAND...: COMMAND in the background, waited for, its exit status: a stopping signal
# sent to the script meanwhile (to it alone, not to its process group) is taken at once rather
# than after COMMAND ends, and reaches COMMAND as TERM (a shell starts a background child ignoring
# INT and QUIT; the backend then stops its points).
in_child() {
    local rc=0
    "$@" &
    STOP_CHILD=$!
    wait "$STOP_CHILD" || rc=$?
    STOP_CHILD=""
    return $rc
}
# stop_script NAME NUMBER: the handler of the stopping signals in every script that sources this
# file (set below), whenever the signal comes: in_child's child is stopped and waited for, and
# the script ends with `STOP_PROGRAM: stopped by SIGNAMESTOP_NOTE` (the script's name and a note
# that the same command resumes, unless the script sets them) and 128 + the signal's number, its
# EXIT trap removing its temporaries. A signal the script was started ignoring (INT and QUIT for a
# shell's background job) stays ignored, as bash keeps it.
stop_script() {
    local sig
    for sig in "${STOP_SIGNALS[@]}"; do trap '' "${sig%:*}"; done
    if [ -n "$STOP_CHILD" ]; then  # `|| true`: a study runs under set -e, and wait gives the child's status
        kill -TERM "$STOP_CHILD" 2>/dev/null || true
        wait "$STOP_CHILD" 2>/dev/null || true
    fi
    echo "${STOP_PROGRAM:-$(basename "$0")}: stopped by SIG$1${STOP_NOTE-; the same command runs the points not done}" >&2
    exit $((128 + $2))
}
for stop_sig in "${STOP_SIGNALS[@]}"; do
    # shellcheck disable=SC2064  # the signal's name and number, set now
    trap "stop_script ${stop_sig%:*} ${stop_sig#*:}" "${stop_sig%:*}"
done
unset stop_sig
