#!/usr/bin/env bash
# Progress in a batch log: with standard error a file, a line every --progress-every seconds of
# wall time with the simulated time (rising), the packets done (rising) and the time left; none
# with --progress-every 0, with -q, or when standard error is itself an output (--stats). An
# animation's lines count each frame's packets. On a terminal (script(1)'s pseudo-terminal) the
# line is rewritten in place with the share and the time left.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
sim=("$BUILD/torusrt-sim" "$SRC/scenes/paper-image1.nff" --size 144x144 --ips 4x4x4 --t1 1)
line='^torusrt-sim: progress: simulated [0-9]+\.[0-9]{6} s, [0-9]+ packets done, [0-9]{1,3} %, about ([0-9]+ s|[0-9]+ min [0-9]{2} s|[0-9]+ h [0-9]{2} min) left$'

"${sim[@]}" -o "$TMP/a.png" --progress-every 20ms > "$TMP/a.out" 2> "$TMP/a.err" < /dev/null || fail "logged run"
grep 'progress' "$TMP/a.err" > "$TMP/a.lines"
check "progress lines in the log ($(wc -l < "$TMP/a.lines"))" test "$(wc -l < "$TMP/a.lines")" -ge 3
check "every progress line has its form: $(grep -Ev "$line" "$TMP/a.lines" | head -1)" \
    test -z "$(grep -Ev "$line" "$TMP/a.lines")"
check "the simulated time and the packets done rise" \
    awk '{ t = $4 + 0; p = $6 + 0; if (NR > 1 && (t < lt || p <= lp)) bad = 1; lt = t; lp = p } END { exit bad }' "$TMP/a.lines"
check "no carriage return in a log" test -z "$(tr -cd '\r' < "$TMP/a.err")"
check "the summary still goes to standard output" grep -q 'wrote' "$TMP/a.out"

"${sim[@]:0:6}" -o "$TMP/f_%d.png" --frames 2 --orbit 10 --progress-every 20ms > /dev/null 2> "$TMP/f.err" < /dev/null ||
    fail "logged animation"
grep -E "^torusrt-sim frame 1/2: progress: " "$TMP/f.err" | tail -1 | awk '{ print $8 }' > "$TMP/f1.last"
grep -E "^torusrt-sim frame 2/2: progress: " "$TMP/f.err" | head -1 | awk '{ print $8 }' > "$TMP/f2.first"
check "an animation: lines for both frames" test -s "$TMP/f1.last" -a -s "$TMP/f2.first"
check "an animation: frame 2 counts its own packets ($(cat "$TMP/f2.first") after $(cat "$TMP/f1.last"))" \
    test "$(cat "$TMP/f2.first")" -lt "$(cat "$TMP/f1.last")"
if command -v script > /dev/null; then
    script -qfec "$(printf '%q ' "${sim[@]}" -o "$TMP/t.png")" /dev/null > "$TMP/t.out" 2>&1 < /dev/null
    tr '\r' '\n' < "$TMP/t.out" | grep '%, about' > "$TMP/t.lines"
    check "a terminal: the progress line rewritten in place ($(wc -l < "$TMP/t.lines") times)" \
        test "$(wc -l < "$TMP/t.lines")" -ge 3
    check "a terminal: its form, share and time left: $(grep -Ev '^torusrt-sim: +[0-9]{1,3}%, about [0-9]+ (s|min [0-9]{2} s|h [0-9]{2} min) left +$' "$TMP/t.lines" | head -1)" \
        test -z "$(grep -Ev '^torusrt-sim: +[0-9]{1,3}%, about [0-9]+ (s|min [0-9]{2} s|h [0-9]{2} min) left +$' "$TMP/t.lines")"
fi

"${sim[@]}" -o "$TMP/b.png" --progress-every 0 > /dev/null 2> "$TMP/b.err" < /dev/null || fail "run without progress"
check "--progress-every 0: no progress" test -z "$(grep progress "$TMP/b.err")"
"${sim[@]}" -o "$TMP/q.png" --progress-every 20ms -q > /dev/null 2> "$TMP/q.err" < /dev/null || fail "quiet run"
check "-q: nothing on standard error" test ! -s "$TMP/q.err"
"${sim[@]}" -o "$TMP/s.png" --progress-every 20ms --stats /dev/stderr -q > /dev/null 2> "$TMP/s.err" < /dev/null ||
    fail "run with its statistics on standard error"
check "standard error an output: no progress in it" test -z "$(grep 'progress:' "$TMP/s.err")"
check "standard error an output: the JSON alone" jq -e .sim_time_s "$TMP/s.err" > /dev/null
"${sim[@]}" -o "$TMP/s.png" --progress-every 20ms --stats /dev/stderr > /dev/null 2> "$TMP/s.err" < /dev/null
check "standard error an output without -q: refused (exit $?)" grep -q "an output on standard error needs -q" "$TMP/s.err"

bad() {
    "${sim[@]}" -o "$TMP/x.png" --progress-every "$1" > /dev/null 2> "$TMP/x.err"
    check "--progress-every $1: exit 2" test $? = 2
    check "--progress-every $1: named" grep -q -- --progress-every "$TMP/x.err"
}
bad -1
bad 5x
bad 1e9
finish
