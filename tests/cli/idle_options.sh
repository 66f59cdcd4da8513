#!/usr/bin/env bash
# An option given on the command line that changes nothing in the machine asked for is run but
# warned about (--data, --arbiter, --dispatch without --cluster above 1; --link-us beside
# --link-bytes-per-us; --replica-choice without --replicate; --trace-ips without --vcd;
# --route-ties on a machine with no even ring, or a mesh), and not
# when it acts, nor when it comes from a --config file or goes to --dump-config. An option
# missing its value is named (--ips --map cost). --ips with one number says it builds a ring, on
# stderr and in the summary's system line; one processor per node prints no data mode; a paper
# machine file's timing table names the profile it equals (fitted).
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
sim=$BUILD/torusrt-sim
scene=$SRC/scenes/paper-image1.nff
# run NAME OPTION...: a small run; its exit status, stdout in $TMP/NAME.out, stderr in $TMP/NAME.err.
run() {
    local name=$1
    shift
    "$sim" "$scene" --size 8x8 -o "$TMP/$name.png" "$@" >"$TMP/$name.out" 2>"$TMP/$name.err" </dev/null
}
# warns NAME OPTION NEEDED ARGS...: the run succeeds and warns that OPTION needs NEEDED.
warns() {
    local name=$1 option=$2 needed=$3
    shift 3
    run "$name" "$@"
    check "$name: runs (exit $?: $(head -c 200 "$TMP/$name.err"))" test $? -eq 0
    check "$name: warns that $option changes nothing ($(head -c 300 "$TMP/$name.err"))" \
        grep -qxF "torusrt-sim: warning: $option changes nothing here: it acts only with $needed" "$TMP/$name.err"
}
# quiet_run NAME ARGS...: the run succeeds with nothing at all on stderr.
quiet_run() {
    local name=$1
    shift
    run "$name" "$@"
    check "$name: runs (exit $?)" test $? -eq 0
    check "$name: no warning ($(head -c 300 "$TMP/$name.err"))" test ! -s "$TMP/$name.err"
}

warns data --data "--cluster above 1" --ips 2x2 --data shared
warns arbiter --arbiter "--cluster above 1" --ips 2x2 --arbiter fixed-priority
warns dispatch --dispatch "--cluster above 1" --ips 2x2 --dispatch=shortest-queue
warns link --link-us "--link-bytes-per-us 0 (it sets the link time)" --ips 2x2 --link-us 100 --link-bytes-per-us 10
warns replica --replica-choice "--replicate above 0" --ips 2x2 --replica-choice hash
warns trace --trace-ips --vcd --ips 2x2 --trace-ips 0,1
warns ties-odd --route-ties "an even ring (a dimension of --ips with an even number of nodes)" --ips 3x3 \
    --route-ties plus
warns ties-mesh --route-ties "--topology torus (a mesh has no way round)" --ips 2x2 --topology mesh --route-ties plus
check "-q: no warning" test -z "$("$sim" "$scene" --size 8x8 -o "$TMP/q.png" --data shared -q 2>&1)"
quiet_run cluster --ips 2x2 --cluster 2 --data shared --arbiter fixed-priority --dispatch shortest-queue
quiet_run traced --ips 2x2 --trace-ips 0,1 --vcd "$TMP/t.vcd"
quiet_run linkus --ips 2x2 --link-us 100
quiet_run ties-even --ips 3x2 --route-ties plus
# A machine file holds every key: what it sets is never warned about.
"$sim" --dump-config --ips 2x2 --data shared --arbiter fixed-priority >"$TMP/m.toml" 2>"$TMP/dump.err"
check "--dump-config with idle options: exit 0 and no warning ($(head -c 200 "$TMP/dump.err"))" \
    test $? -eq 0 -a ! -s "$TMP/dump.err"
quiet_run config --config "$TMP/m.toml"

# An option missing its value is named, not the word after the next option.
"$sim" "$scene" -o "$TMP/x.png" --ips --map cost >"$TMP/missing.out" 2>"$TMP/missing.err"
check "--ips --map cost: exit 2 ($?)" test $? -eq 2
check "--ips --map cost: --ips is named as missing its value ($(head -n 1 "$TMP/missing.err"))" \
    grep -qF "torusrt-sim: --ips: missing its value (the next word, --map, is an option)" "$TMP/missing.err"
check "--ips --map cost: no image" test ! -e "$TMP/x.png"

# --ips 16 is a ring: a note on stderr and the system line.
run ring --ips 16
check "--ips 16 runs" test $? -eq 0
check "--ips 16: a note on stderr ($(head -c 300 "$TMP/ring.err"))" \
    grep -qF "torusrt-sim: note: --ips 16 builds a 16x1x1 torus: a ring of 16" "$TMP/ring.err"
check "--ips 16: the system line says it is a ring ($(grep system "$TMP/ring.out"))" \
    grep -qF "system       16x1x1 torus: a ring of 16 (ties " "$TMP/ring.out"
quiet_run square --ips 4x4
check "--ips 4x4: no ring on the system line" grep -qE "system       4x4x1 torus \(ties [a-z]+\), " "$TMP/square.out"
run line --ips 8 --topology mesh
check "--ips 8 --topology mesh: a line" grep -qF "system       8x1x1 mesh: a line of 8, " "$TMP/line.out"

# One processor per node has no data mode; a cluster names it.
check "one processor per node: no data mode ($(grep system "$TMP/square.out"))" \
    grep -qE "system .*, 1 processor per node,$" "$TMP/square.out"
check "a cluster: processors and data ($(grep system "$TMP/cluster.out"))" \
    grep -qE "system .*, 2 processors per node, shared data,$" "$TMP/cluster.out"

# A paper machine file: the timing table is the profile fitted, and the summary says so.
run paper --config "$SRC/machines/paper-16.toml"
check "paper-16.toml runs ($(head -c 200 "$TMP/paper.err"))" test $? -eq 0
check "paper-16.toml: the timing line names the profile fitted ($(grep timing "$TMP/paper.out"))" \
    grep -qF "timing       profile fitted = calibrated + " "$TMP/paper.out"
finish
