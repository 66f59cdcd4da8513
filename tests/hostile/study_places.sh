#!/usr/bin/env bash
# study_places.sh - the study scripts (sweep.sh, the study.sh scripts) never write their page,
# plots or results where the run reads, nor through their streams into such a file:
# - `sweep.sh --doc` and `error_vs_runtime/study.sh --doc / --img-dir` naming a scene, a machine
#   file, experiments/lib.sh, a file of the results folder, a hard link to a scene, or a file
#   the command line names (an sshlogin file, TORUSRT_SCENE_IMAGE1): exit 2 naming the option,
#   the file unchanged, no img/ folder and no results folder made; and places of the wrong kind
#   (an --img-dir or --results that is a file, a --doc that is a folder or /dev/stdout, a
#   --results with a newline) refused before any point runs;
# - `--results scenes` (buffers, sweep.sh, fidelity) and `--results docs/x`: exit 2, nothing
#   made there; a relative --results works in the buffer study (its done files are absolute);
# - `error_vs_runtime/study.sh --quick --results DIR` writes its page and plots into DIR, never
#   docs/;
# - standard output appended through a hard link made outside to a scene (a study), to a point's
#   JSON (the sweep, report sweep-collect): exit 2, the file unchanged; the message names the
#   tree's folder as itself (not as the folder of the option before it); run_point.sh calls its
#   own log a file it writes;
# - a stopping signal that comes while lib.sh checks the streams: the message and 128 + N.
# Each run is a copy of the tree with a build whose executables fail at once (the checks come
# before any point), but for the error study's quick run, which uses the real build.
#
# Usage (CTest runs it so): bash tests/hostile/study_places.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-sim torusrt-render
for tool in python3 parallel gnuplot jq; do
    command -v "$tool" >/dev/null || { echo "$TEST_NAME: $tool is not installed; skipped"; exit 77; }
done
time_limit 120
cd "$TMP" || exit 1
mkdir tree fake
cp -r "$SRC/experiments" "$SRC/scenes" "$SRC/machines" "$SRC/timing" "$SRC/docs" tree/
find tree/experiments -maxdepth 2 -type d -name 'results*' -exec rm -rf {} +
for exe in torusrt-sim torusrt-render torusrt-genscenes; do printf '#!/bin/sh\nexit 1\n' >fake/$exe; done
chmod +x fake/*
T=$TMP/tree
cp -p "$T/scenes/paper-image1.nff" keep.nff

# refused NAME FILE PATTERN COMMAND...: COMMAND exits 2 with PATTERN on standard error, and FILE
# (if given) is byte for byte what it was.
refused() {
    local name=$1 file=$2 pattern=$3 f=$TMP/${1//[\/ \'.]/_} keep=""
    shift 3
    [ -z "$file" ] || { keep=$f.keep; cp -p "$file" "$keep"; }
    "${run_limited[@]}" "$@" >"$f.out" 2>"$f.err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected 2: $(tail -n 2 "$f.err" | head -c 300)" [ "$rc" -eq 2 ]
    check "$name: the message: $(head -c 300 "$f.err")" grep -q -- "$pattern" "$f.err"
    [ -z "$file" ] || check "$name: $file changed" cmp -s "$keep" "$file"
    [ -z "$file" ] || cmp -s "$keep" "$file" || cp -p "$keep" "$file"  # the next cases run on the tree as it was
}
sweep=(bash "$T/experiments/sweep.sh" --quick --build "$TMP/fake" -j 1 --no-clusters)
evr=(bash "$T/experiments/error_vs_runtime/study.sh" --build "$TMP/fake" -j 1 --quick)

# ---- pages and plots (N3) -----------------------------------------------------------------
refused "sweep --doc a scene" "$T/scenes/paper-image1.nff" "--doc '.*paper-image1.nff': is inside the folder" \
    "${sweep[@]}" --results "$TMP/sd" --doc "$T/scenes/paper-image1.nff"
check "sweep --doc a scene: no img/ beside it" [ ! -e "$T/scenes/img" ]
check "sweep --doc a scene: no results folder made" [ ! -e "$TMP/sd" ]
refused "sweep --doc a machine file" "$T/machines/paper-16.toml" "--doc '.*paper-16.toml': is inside" \
    "${sweep[@]}" --results "$TMP/sd" --doc "$T/machines/paper-16.toml"
refused "sweep --doc lib.sh" "$T/experiments/lib.sh" "--doc '.*lib.sh': is inside the folder .*experiments" \
    "${sweep[@]}" --results "$TMP/sd" --doc "$T/experiments/lib.sh"
mkdir -p sj && echo "my joblog" >sj/joblog
refused "sweep --doc its joblog" sj/joblog "--doc 'sj/joblog': is inside the --results folder" \
    "${sweep[@]}" --results sj --doc sj/joblog
ln "$T/scenes/paper-image2.nff" hl2.nff
refused "sweep --doc a hard link to a scene" hl2.nff "--doc 'hl2.nff': is a hard link to a file in .*scenes" \
    "${sweep[@]}" --results "$TMP/sd" --doc hl2.nff
echo ":" >hosts
refused "sweep --doc its sshlogin file" hosts "--doc 'hosts': is the --sshloginfile file hosts, an input" \
    "${sweep[@]}" --results "$TMP/sd" --sshloginfile hosts --doc hosts
cp keep.nff mine.nff
refused "sweep --doc TORUSRT_SCENE_IMAGE1" mine.nff "--doc 'mine.nff': is the file .*mine.nff, an input" \
    env TORUSRT_SCENE_IMAGE1="$TMP/mine.nff" "${sweep[@]}" --results "$TMP/sd" --doc mine.nff
# allowed: a page in docs/, and RESULTS/NAME.md (the quick sweep's own place): the run gets as
# far as its backend (here one that does not exist, refused without running a point)
for doc in "$T/docs/x.md" "$TMP/ok/reproduction.md"; do
    "${run_limited[@]}" "${sweep[@]}" --no-report --backend none --results "$TMP/ok" --doc "$doc" >ok.out 2>ok.err \
        </dev/null
    check "sweep --doc $doc: allowed: $(head -c 300 ok.err)" grep -q "backend must be" ok.err
done
refused "error study --doc a scene" "$T/scenes/paper-image2.nff" "--doc '.*paper-image2.nff': is inside the folder" \
    "${evr[@]}" --results "$TMP/ed" --doc "$T/scenes/paper-image2.nff" --img-dir "$TMP/eimg"
refused "error study --img-dir scenes/" "" "--img-dir '.*scenes': is inside the folder" \
    "${evr[@]}" --doc "$TMP/e.md" --img-dir "$T/scenes"
refused "error study --doc in its --img-dir" "" "--doc '.*eimg/error-quantum.png': is inside the --img-dir folder" \
    "${evr[@]}" --doc "$TMP/eimg/error-quantum.png" --img-dir "$TMP/eimg"
check "error study: no results folder made by a refused run" [ ! -e "$TMP/ed" ]
# a place of the wrong kind: refused before any point runs (the fake build would fail them all)
echo "a file" >afile && mkdir -p "$TMP/eimg2"
refused "error study --img-dir a file" afile "--img-dir 'afile': is a file, not a folder" \
    "${evr[@]}" --doc "$TMP/e.md" --img-dir afile
refused "error study --doc a folder" "" "--doc '.*eimg2': is a folder, not a regular file" \
    "${evr[@]}" --doc "$TMP/eimg2" --img-dir "$TMP/eimg"
refused "error study --doc /dev/stdout" "" "--doc '/dev/stdout': is a stream" \
    "${evr[@]}" --doc /dev/stdout --img-dir "$TMP/eimg"
refused "error study --results with a newline" "" "--results '.*\\x0ab': a control character in the name" \
    "${evr[@]}" --results "$TMP/a"$'\n'"b"
check "error study --results with a newline: not made" [ ! -e "$TMP/a"$'\n'"b" ]
refused "sweep --results a file" afile "--results 'afile': is a file, not a folder" "${sweep[@]}" --results afile

# ---- results folders -----------------------------------------------------------------------
cd "$T" || exit 1
refused "buffers --results scenes" "" "--results 'scenes': is inside .*scenes, whose files the run reads" \
    bash experiments/buffers/study.sh --quick --build "$TMP/fake" --results scenes
check "buffers --results scenes: nothing made there" [ ! -e scenes/points ] && [ ! -e scenes/buffers ]
refused "sweep --results machines/x" "" "--results 'machines/x': is inside" \
    "${sweep[@]}" --results machines/x
check "sweep --results machines/x: not made" [ ! -e machines/x ]
refused "fidelity --results docs/r" "" "--results 'docs/r': is inside .*docs, the tree's pages" \
    bash experiments/fidelity/study.sh --smoke --build "$TMP/fake" --results docs/r
check "fidelity --results docs/r: not made" [ ! -e docs/r ]
refused "buffers --results experiments/buffers" "" "--results 'experiments/buffers': is inside .*experiments, the code" \
    bash experiments/buffers/study.sh --quick --build "$TMP/fake" --results experiments/buffers
cd "$TMP" || exit 1
"${run_limited[@]}" bash "$T/experiments/buffers/study.sh" --quick --build "$TMP/fake" --results relq >relq.out \
    2>relq.err </dev/null
check "buffers --results relq: no refusal of its own done files: $(head -c 300 relq.err)" \
    test "$(grep -c 'absolute path' relq.err)" -eq 0
check "buffers --results relq: absolute done files" grep -q "^$TMP/relq/points/" relq/points/phase1.list

# ---- the error study's quick run keeps docs/ (N4) -------------------------------------------
cp -p "$T/docs/error-vs-runtime.md" evr-keep.md
"${run_limited[@]}" bash "$T/experiments/error_vs_runtime/study.sh" --quick --build "$BUILD" -j 2 \
    --results relx >evr.out 2>evr.err </dev/null
rc=$?
check "error study --quick --results relx: exit $rc: $(tail -n 3 evr.err | head -c 300)" [ "$rc" -eq 0 ]
check "error study --quick --results relx: docs/error-vs-runtime.md changed" cmp -s evr-keep.md "$T/docs/error-vs-runtime.md"
check "error study --quick --results relx: the page in relx" [ -s relx/error-vs-runtime.md ]
check "error study --quick --results relx: the plots in relx/img" [ -s relx/img/error-quantum.png ]

# ---- streams through a hard link (N1) -------------------------------------------------------
ln "$T/scenes/paper-image1.nff" hl1.nff
"${run_limited[@]}" bash "$T/experiments/buffers/study.sh" --quick --build "$TMP/fake" --results "$TMP/bh" \
    >>hl1.nff 2>hl.err </dev/null
rc=$?
check "buffers >> a hard link to a scene: exit $rc, expected 2" [ "$rc" -eq 2 ]
check "buffers >> a hard link to a scene: the scene changed" cmp -s keep.nff "$T/scenes/paper-image1.nff"
check "buffers >> a hard link to a scene: the message: $(head -c 300 hl.err)" \
    grep -q "standard output is redirected to .*hl1.nff, in the folder .*scenes" hl.err
scene=$T/scenes/paper-image2.nff
"${run_limited[@]}" "$T/experiments/sweep" --build "$BUILD" "$scene" --axis ips=1 --out R -- --size 8x8 \
    >/dev/null 2>R.err </dev/null
check "sweep into R: $(head -c 300 R.err)" [ -s R/points/ips_1.json ]
ln R/points/ips_1.json hlp.json
cp -p R/points/ips_1.json keep.json
for cmd in "sweep" "report sweep-collect"; do
    if [ "$cmd" = sweep ]; then
        c=("$T/experiments/sweep" --build "$BUILD" "$scene" --axis ips=1 --out R -- --size 8x8)
    else
        c=(python3 "$T/experiments/report" sweep-collect --out R --columns "" --y sim_time_s)
    fi
    "${run_limited[@]}" "${c[@]}" >>hlp.json 2>hlp.err </dev/null
    rc=$?
    check "$cmd >> a hard link to a point's JSON: exit $rc, expected 2" [ "$rc" -eq 2 ]
    check "$cmd >> a hard link to a point's JSON: the JSON changed" cmp -s keep.json R/points/ips_1.json
    check "$cmd >> a hard link: the message: $(head -c 300 hlp.err)" grep -q "in the --out folder R" hlp.err
done

# ---- messages name the tree's folders and run_point.sh's own files -------------------------
cp keep.nff "$T/scenes/paper-image1.nff"
"${run_limited[@]}" "${evr[@]}" >>"$T/scenes/paper-image1.nff" 2>w.err </dev/null
check "error study --quick >> a scene: the folder named as itself: $(head -c 300 w.err)" \
    grep -q "in the folder .*scenes, whose" w.err
check "error study --quick >> a scene: not '--quick folder'" test "$(grep -c -- '--quick folder' w.err)" -eq 0
mkdir -p rp && echo "my notes" >rp/g.log
"${run_limited[@]}" "$T/experiments/run_point.sh" rp/g.json -- "$BUILD/torusrt-sim" keep.nff --size 8x8 \
    >>rp/g.log 2>rp.err </dev/null
check "run_point >> its own log: a file it writes: $(head -c 300 rp.err)" grep -q "rp/g.log, a file the command writes" rp.err

# ---- a stopping signal during the stream check ----------------------------------------------
# python3 that sends TERM to the script that runs it when the script checks its streams: the
# signal comes while lib.sh waits for the check, every time.
mkdir -p wrap
cat >wrap/python3 <<EOF
#!/bin/sh
case " \$* " in *" --check-streams "*) kill -TERM \$PPID ;; esac
exec $(command -v python3) "\$@"
EOF
chmod +x wrap/python3
PATH=$TMP/wrap:$PATH "${run_limited[@]}" bash "$T/experiments/buffers/study.sh" --quick --build "$TMP/fake" \
    --results "$TMP/sig" >sig.out 2>sig.err </dev/null
rc=$?
check "TERM during the stream check: exit $rc, expected 143" [ "$rc" -eq 143 ]
check "TERM during the stream check: the message: $(head -c 300 sig.err)" grep -q "stopped by SIGTERM" sig.err
check "TERM during the stream check: nothing made" [ ! -e "$TMP/sig" ]
finish
