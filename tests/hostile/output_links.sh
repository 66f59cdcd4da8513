#!/usr/bin/env bash
# output_links.sh - outputs named through links and the command's own standard streams: a link
# to /proc/self/fd/2 or fd/1 (and /dev/fd/2, and /dev/stderr itself as root in a private mount
# namespace) is written through that stream and stays a link, for every output option of both
# programs; a link to a file replaces the file, never the link; standard output appended to the
# scene (>> SCENE), with or without --stats /dev/stdout, is refused before anything is written;
# standard error appended to an input (2>> SCENE) is refused with nothing written into it;
# two outputs on one stream are refused naming both options; a null device takes any number.
#
# Usage (CTest runs it so): bash tests/hostile/output_links.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-render torusrt-sim
time_limit 60
f=$(source_scene paper-image1) || exit 1
sim=("$BUILD/torusrt-sim" -q --t1 1 --ips 2 --size 8x8)
sim_anim=("$BUILD/torusrt-sim" -q --ips 2 --size 8x8)  # an animation takes no --t1
render=("$BUILD/torusrt-render" -q --size 8x8)
cd "$TMP" || exit 1
cp "$f" scene.nff
ln -s /proc/self/fd/2 to_stderr
ln -s /proc/self/fd/1 to_stdout
mkdir out

# through_link NAME WHAT COMMAND...: the run (stderr into err.txt) exits 0, to_stderr is still a
# link and err.txt holds WHAT (a grep pattern), and out/ holds no temporary.
through_link() {
    local name=$1 what=$2
    shift 2
    rm -rf out && mkdir out
    "${run_limited[@]}" "$@" >/dev/null 2>err.txt </dev/null
    local rc=$?
    check "$name: exit $rc, expected 0: $(head -c 200 err.txt | tr -cd '[:print:]')" [ "$rc" -eq 0 ]
    check "$name: the link is still a link" [ -L to_stderr ]
    check "$name: standard error holds the output" grep -aq "$what" err.txt
    check "$name: a temporary left: $(ls -A out | grep '^\.' | head -c 100)" [ -z "$(ls -A out | grep '^\.')" ]
}
anim=(--frames 2 --orbit 10)
through_link "sim -o via a link to fd 2" PNG "${sim[@]}" scene.nff -o to_stderr
through_link "sim --stats via a link to fd 2" '"status"' "${sim[@]}" scene.nff -o out/a.png --stats to_stderr
through_link "sim --vcd via a link to fd 2" enddefinitions "${sim[@]}" scene.nff -o out/a.png --vcd to_stderr
through_link "sim --write-map via a link to fd 2" . "${sim[@]}" scene.nff -o out/a.png --write-map to_stderr
through_link "sim --frames-csv via a link to fd 2" frame "${sim_anim[@]}" scene.nff "${anim[@]}" -o "out/f%d.png" \
    --frames-csv to_stderr
through_link "render -o via a link to fd 2" PNG "${render[@]}" scene.nff -o to_stderr
through_link "render --stats via a link to fd 2" '"objects"' "${render[@]}" scene.nff -o out/a.png --stats to_stderr
through_link "render --cost-image via a link to fd 2" PNG "${render[@]}" scene.nff -o out/a.png --cost-image to_stderr
through_link "sim --stats /dev/fd/2" '"status"' "${sim[@]}" scene.nff -o out/a.png --stats /dev/fd/2

# A link to fd 1, standard output redirected to a file: the JSON lands in that file.
"${run_limited[@]}" "${sim[@]}" scene.nff -o out/a.png --stats to_stdout >stdout.json 2>err.txt </dev/null
check "sim --stats via a link to fd 1: exit $?: $(head -c 200 err.txt)" grep -q '"status"' stdout.json
check "sim --stats via a link to fd 1: still a link" [ -L to_stdout ]

# A link to a file, a link to a file not made yet, a relative link in another folder: the file
# the link names is written, the link stays.
echo old >real.json
ln -s real.json to_real
ln -s new.json to_new
mkdir sub && ln -s ../rel.json sub/to_rel
"${run_limited[@]}" "${sim_anim[@]}" scene.nff "${anim[@]}" -o "out/f%d.png" --stats to_real --write-map to_new \
    --frames-csv sub/to_rel >/dev/null 2>err.txt </dev/null
rc=$?
check "links to files: exit $rc: $(head -c 200 err.txt)" [ "$rc" -eq 0 ]
for link in to_real to_new sub/to_rel; do check "links to files: $link is still a link" [ -L "$link" ]; done
check "links to files: the linked file holds the JSON" grep -q '"status"' real.json
check "links to files: the file a dangling link names is made" [ -s new.json ]
check "links to files: a relative link names a file beside its folder" [ -s rel.json ]
check "links to files: no temporary left: $(ls -A . sub | grep '^\.[a-z]' | head -c 100)" \
    [ -z "$(ls -A . sub out | grep '^\.[a-z]')" ]

# Standard output appended to the scene: refused (exit 2), the scene as it was, no image.
cp scene.nff keep.nff
for stats in "" "--stats /dev/stdout"; do
    rm -rf out && mkdir out
    # shellcheck disable=SC2086 # the option and its file, or nothing
    "${run_limited[@]}" "$BUILD/torusrt-sim" --t1 1 --ips 2 --size 8x8 scene.nff -o out/a.png $stats \
        >>scene.nff 2>err.txt </dev/null
    rc=$?
    check "sim ${stats:-(summary)} >> SCENE: exit $rc, expected 2: $(head -c 200 err.txt)" [ "$rc" -eq 2 ]
    check "sim ${stats:-(summary)} >> SCENE: the message says so" grep -q "standard output.*scene" err.txt
    check "sim ${stats:-(summary)} >> SCENE: the scene unchanged" cmp -s scene.nff keep.nff
    check "sim ${stats:-(summary)} >> SCENE: no image" [ -z "$(ls -A out)" ]
    cp keep.nff scene.nff
done
"${run_limited[@]}" "$BUILD/torusrt-render" --size 8x8 scene.nff -o out/a.png --stats /dev/stdout \
    >>scene.nff 2>err.txt </dev/null
check "render --stats /dev/stdout >> SCENE: exit $?: $(head -c 200 err.txt)" cmp -s scene.nff keep.nff
cp keep.nff scene.nff

# Standard error appended to an input (the scene, a hard link to it, the machine file): refused
# (exit 2) with nothing written into the input, not the message, not a warning or note printed
# before the outputs are checked; no image.
printf 'ips = "4"\n' >m.toml
cp m.toml keep.toml
ln scene.nff hard.nff
for stats in "" "--stats /dev/stderr" "--ips 4" "--config m.toml"; do
    for target in scene.nff hard.nff m.toml; do
        [ "$target" = m.toml ] && [ "$stats" != "--config m.toml" ] && continue
        rm -rf out && mkdir out
        # shellcheck disable=SC2086 # the option and its file, or nothing
        "${run_limited[@]}" "$BUILD/torusrt-sim" --t1 1 --size 8x8 scene.nff -o out/a.png $stats \
            >out.txt 2>>"$target" </dev/null
        rc=$?
        check "sim ${stats:-(plain)} 2>> $target: exit $rc, expected 2" [ "$rc" -eq 2 ]
        check "sim ${stats:-(plain)} 2>> $target: the scene unchanged" cmp -s scene.nff keep.nff
        check "sim ${stats:-(plain)} 2>> $target: the machine file unchanged" cmp -s m.toml keep.toml
        check "sim ${stats:-(plain)} 2>> $target: no image" [ -z "$(ls -A out)" ]
        cp keep.nff scene.nff
        cp keep.toml m.toml
    done
done
rm -rf out && mkdir out
"${run_limited[@]}" "$BUILD/torusrt-render" --size 8x8 scene.nff -o out/a.png --stats /dev/stderr \
    >out.txt 2>>scene.nff </dev/null
rc=$?
check "render --stats /dev/stderr 2>> SCENE: exit $rc, expected 2" [ "$rc" -eq 2 ]
check "render --stats /dev/stderr 2>> SCENE: the scene unchanged" cmp -s scene.nff keep.nff
cp keep.nff scene.nff

# Two outputs on one stream: refused naming both options, nothing written.
# two_on_stream NAME OPTION_A OPTION_B COMMAND...: exit 2, both options named, out/ empty.
two_on_stream() {
    local name=$1 a=$2 b=$3
    shift 3
    rm -rf out && mkdir out
    "${run_limited[@]}" "$@" >stdout.txt 2>err.txt </dev/null
    local rc=$?
    check "$name: exit $rc, expected 2: $(head -c 200 err.txt | tr -cd '[:print:]')" [ "$rc" -eq 2 ]
    check "$name: names $a and $b: $(head -c 200 err.txt | tr -cd '[:print:]')" \
        bash -c 'grep -q -- "$1 " err.txt && grep -q -- "$2 " err.txt' _ "$a" "$b"
    check "$name: nothing written: $(head -c 100 stdout.txt | tr -cd '[:print:]') $(ls -A out)" \
        [ ! -s stdout.txt ] && [ -z "$(ls -A out)" ]
}
two_on_stream "sim -o and --stats on /dev/stdout" -o --stats "${sim[@]}" scene.nff -o /dev/stdout --stats /dev/stdout
two_on_stream "sim --stats /dev/stdout and --vcd /dev/fd/1" --stats --vcd \
    "${sim[@]}" scene.nff -o out/a.png --stats /dev/stdout --vcd /dev/fd/1
two_on_stream "render -o /dev/stdout and --cost-image via a link to fd 1" -o --cost-image \
    "${render[@]}" scene.nff -o /dev/stdout --cost-image to_stdout
# Into a pipe, as a user would run it: the same refusal.
rm -rf out && mkdir out
"${run_limited[@]}" "${sim[@]}" scene.nff -o /dev/stdout --stats /dev/stdout 2>err.txt </dev/null | cat >piped.txt
check "sim two outputs on a piped stdout: exit ${PIPESTATUS[0]}, nothing in the pipe" \
    bash -c '[ "$1" -eq 2 ] && [ ! -s piped.txt ]' _ "${PIPESTATUS[0]}"
# A null device is no stream: any number of outputs may go there.
"${run_limited[@]}" "${sim[@]}" scene.nff -o /dev/null --stats /dev/null --vcd /dev/null >/dev/null 2>err.txt </dev/null
check "sim: three outputs on /dev/null, stdout too: exit $?: $(head -c 200 err.txt)" [ ! -s err.txt ]

# /dev/stderr itself (as root, in a private mount namespace with its own /dev, never the real
# one): written through standard error, and /dev/stderr stays a link.
if [ "$(id -u)" -eq 0 ] && unshare -m true 2>/dev/null; then
    export TMP BUILD
    unshare -m --propagation private bash -c '
        cd "$TMP" || exit 90
        mount -t tmpfs tmpfs /dev || exit 90
        mknod -m 666 /dev/null c 1 3 && ln -s /proc/self/fd/2 /dev/stderr && ln -s /proc/self/fd/1 /dev/stdout || exit 90
        "$BUILD/torusrt-sim" -q --t1 1 --ips 2 --size 8x8 scene.nff -o out/b.png --stats /dev/stderr \
            </dev/null >/dev/null 2>ns_err.txt
        echo "rc $?"
        test -L /dev/stderr; echo "link $?"
        echo "dev $(ls -A /dev | tr "\n" " ")"
    ' >ns.out 2>ns.err
    ns() { awk -v k="$1" '$1 == k { $1 = ""; sub(/^ /, ""); print }' ns.out; }
    check "namespace set up: $(head -c 200 ns.err)" [ -n "$(ns rc)" ]
    check "sim --stats /dev/stderr: exit $(ns rc)" [ "$(ns rc)" = 0 ]
    check "sim --stats /dev/stderr: /dev/stderr stays a link" [ "$(ns link)" = 0 ]
    check "sim --stats /dev/stderr: nothing new in /dev: $(ns dev)" [ "$(ns dev)" = "null stderr stdout" ]
    check "sim --stats /dev/stderr: standard error holds the JSON" grep -q '"status"' ns_err.txt
else
    echo "$TEST_NAME: /dev/stderr itself needs root and unshare -m: that case skipped"
fi
finish
