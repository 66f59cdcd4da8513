#!/usr/bin/env bash
# outputs.sh - every output option of both programs naming one of the run's inputs (scene,
# --timing, --config, --map-file, --camera-path, --motion), directly or as a frame of an animation's -o
# pattern, or naming another output: refused before anything runs (exit 2), the input
# unchanged, nothing written. A 254-byte output name (NAME_MAX allows 255) is written, and its
# temporary fits too. A run with no packets writes a VCD with its header and signals.
#
# Usage (CTest runs it so): bash tests/hostile/outputs.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/../cli/common.bash" "$@"
need_exe torusrt-render torusrt-sim
time_limit 60
f=$(source_scene paper-image1) || exit 1
sim=("$BUILD/torusrt-sim" -q --t1 1 --size 8x8)
render=("$BUILD/torusrt-render" -q --size 8x8)
cd "$TMP" || exit 1
cp "$f" scene.nff
"$BUILD/torusrt-sim" --dump-config --ips 2 >m.toml || fail "--dump-config"
cp "$SRC/timing/literal.timing" t.timing
"${sim[@]}" scene.nff --ips 2 -o w.png --write-map w.map || fail "--write-map run"
printf '0 0 30 0 0 0 0 1 0 30\n0 0 31 0 0 0 0 1 0 30\n' >c.path
for input in scene.nff m.toml t.timing w.map c.path; do cp "$input" "keep.$input"; done
mkdir out

# refused NAME COMMAND...: exit 2, every input as it was, nothing new in out/.
refused() {
    local name=$1
    shift
    "${run_limited[@]}" "$@" >/dev/null 2>"$name.err" </dev/null
    local rc=$?
    check "$name: exit $rc, expected 2: $(head -c 300 "$name.err")" [ "$rc" -eq 2 ]
    local input
    for input in scene.nff m.toml t.timing w.map c.path; do
        check "$name: $input changed" cmp -s "$input" "keep.$input"
        cp "keep.$input" "$input"
    done
    check "$name: wrote $(ls -A out)" [ -z "$(ls -A out)" ]
}

# Every input a run of each program may read, as the options that read it.
sim_inputs=("scene.nff" "--timing t.timing" "--config m.toml" "--map-file w.map --ips 2" "--camera-path c.path")
render_inputs=("scene.nff" "--timing t.timing" "--camera-path c.path")
name_of() { local words=($1); echo "${words[${#words[@]} - 1]}"; }  # the file is the last word
file_of() { local words=($1); [ "${words[0]}" = scene.nff ] && echo scene.nff || echo "${words[1]}"; }

for input in "${sim_inputs[@]}"; do
    file=$(file_of "$input")
    # shellcheck disable=SC2086 # the input's words are an option and its file
    extra=($input)
    [ "${extra[0]}" = scene.nff ] && extra=()
    anim=(--frames 2 --orbit 10)
    [ "${extra[0]:-}" = --camera-path ] && anim=()
    for out in "-o" "--stats" "--vcd" "--write-map" "--load-map"; do
        if [ "$out" = -o ]; then
            if [ ${#anim[@]} -eq 0 ]; then continue; fi  # -o is a pattern with --camera-path
            refused "sim $out onto $file" "${sim[@]}" scene.nff "${extra[@]}" -o "$file"
        else
            o=(-o out/a.png)
            [ ${#anim[@]} -eq 0 ] && o=(-o "out/f%d.png")
            refused "sim $out onto $file" "${sim[@]}" scene.nff "${extra[@]}" "${o[@]}" "$out" "$file"
        fi
    done
    refused "sim --frames-csv onto $file" "${sim[@]}" scene.nff "${extra[@]}" "${anim[@]}" -o "out/f%d.png" \
        --frames-csv "$file"
    o=(-o out/a.png)
    [ ${#anim[@]} -eq 0 ] && o=(-o "out/f%d.png")
    refused "sim --stats-series onto $file" "${sim[@]}" scene.nff "${extra[@]}" "${o[@]}" --stats-interval 1ms \
        --stats-series "$file"
    # A frame of the pattern is the input: x%d.EXT with the input copied to x1.EXT.
    ext=${file##*.}
    cp "$file" "x1.$ext" && cp "$file" "keep.x1.$ext"
    if [ "$file" = scene.nff ]; then xin=(x1.nff); else xin=("${extra[0]}" "x1.$ext" "${extra[@]:2}"); fi
    [ ${#anim[@]} -eq 0 ] && anim=(--frames 2)
    "${run_limited[@]}" "${sim[@]}" "${xin[@]}" --orbit 10 --frames 3 -o "x%d.$ext" >/dev/null 2>"frame.err" </dev/null
    rc=$?
    [ "${xin[0]}" = --camera-path ] && { "${run_limited[@]}" "${sim[@]}" scene.nff "${xin[@]}" -o "x%d.$ext" \
        >/dev/null 2>"frame.err" </dev/null; rc=$?; }
    check "sim: frame 1 of -o x%d.$ext is the ${extra[0]:-scene} x1.$ext: exit $rc: $(head -c 200 frame.err)" [ "$rc" -eq 2 ]
    check "sim: x1.$ext unchanged" cmp -s "x1.$ext" "keep.x1.$ext"
    check "sim: no other frame written" [ ! -e "x0.$ext" ] && [ ! -e "x2.$ext" ]
    rm -f "x1.$ext" "keep.x1.$ext" x0."$ext" x2."$ext"
done

# The series' name made from --stats (X.series.csv beside X.json) is judged as any output.
cp t.timing t.series.csv
refused "sim: the series beside --stats t.json is the --timing t.series.csv" "${sim[@]}" scene.nff \
    --timing t.series.csv -o out/a.png --stats out/../t.json --stats-interval 1ms
rm -f t.series.csv
refused "sim: --stats-series is --stats" "${sim[@]}" scene.nff -o out/a.png --stats out/s.json --stats-interval 1ms \
    --stats-series out/s.json

for input in "${render_inputs[@]}"; do
    file=$(file_of "$input")
    extra=($input)
    [ "${extra[0]}" = scene.nff ] && extra=()
    if [ "${extra[0]:-}" = --camera-path ]; then
        refused "render --stats onto $file" "${render[@]}" scene.nff "${extra[@]}" -o "out/f%d.png" --stats "$file"
        cp c.path x1.path && cp c.path keep.x1.path
        "${run_limited[@]}" "${render[@]}" scene.nff --camera-path x1.path -o "x%d.path" >/dev/null 2>frame.err </dev/null
        check "render: frame 1 of -o x%d.path is the --camera-path: exit $?" [ -s frame.err ]
        check "render: x1.path unchanged" cmp -s x1.path keep.x1.path
        rm -f x1.path keep.x1.path x0.path
        continue
    fi
    for out in -o --stats --cost-image; do
        o=(-o out/a.png)
        [ "$out" = -o ] && o=()
        refused "render $out onto $file" "${render[@]}" scene.nff "${extra[@]}" "${o[@]}" "$out" "$file"
    done
    ext=${file##*.}
    cp "$file" "x1.$ext" && cp "$file" "keep.x1.$ext"
    if [ "$file" = scene.nff ]; then xin=(x1.nff); else xin=(scene.nff "${extra[0]}" "x1.$ext"); fi
    "${run_limited[@]}" "${render[@]}" "${xin[@]}" --orbit 10 --frames 3 -o "x%d.$ext" >/dev/null 2>frame.err </dev/null
    rc=$?
    check "render: frame 1 of -o x%d.$ext is an input: exit $rc: $(head -c 200 frame.err)" [ "$rc" -eq 2 ]
    check "render: x1.$ext unchanged" cmp -s "x1.$ext" "keep.x1.$ext"
    rm -f "x1.$ext" "keep.x1.$ext" x0."$ext" x2."$ext"
done

# The --motion file as --stats, and as frame 1 of the -o pattern: refused, the file unchanged.
sim_animated=("$BUILD/torusrt-sim" -q --size 8x8)  # an animation takes no --t1
for exe in render sim_animated; do
    eval "prog=(\"\${$exe[@]}\")"
    printf 'frames 3\nobjects 0\nkey 2 move 0 1 0\n' >x1.motion && cp x1.motion keep.x1.motion
    "${run_limited[@]}" "${prog[@]}" scene.nff --motion x1.motion -o "out/f%d.png" --stats x1.motion >/dev/null \
        2>frame.err </dev/null
    rc=$?
    check "$exe: --stats onto the --motion file: exit $rc: $(head -c 200 frame.err)" \
        bash -c '[ "$1" -eq 2 ] && grep -q -- "--motion file" frame.err' _ "$rc"
    "${run_limited[@]}" "${prog[@]}" scene.nff --motion x1.motion -o "x%d.motion" >/dev/null 2>frame.err </dev/null
    rc=$?
    check "$exe: frame 1 of -o x%d.motion is the --motion file: exit $rc: $(head -c 200 frame.err)" \
        bash -c '[ "$1" -eq 2 ] && grep -q -- "--motion file" frame.err' _ "$rc"
    check "$exe: x1.motion unchanged" cmp -s x1.motion keep.x1.motion
    check "$exe: no frame or stats written" [ -z "$(ls -A out)" ] && [ ! -e x0.motion ] && [ ! -e x2.motion ]
    rm -f x1.motion keep.x1.motion
done

# Outputs naming each other, a frame included, through another spelling of the name.
refused "sim --stats onto frame 1" "${sim[@]}" scene.nff --frames 3 --orbit 10 -o "out/f%d.png" --stats ./out/f1.png
refused "sim --frames-csv onto --stats" "${sim[@]}" scene.nff --frames 3 --orbit 10 -o "out/f%d.png" \
    --stats out/s.json --frames-csv out/../out/s.json
refused "sim --load-map onto --write-map" "${sim[@]}" scene.nff --ips 2 -o out/a.png --load-map out/m --write-map out/m
refused "render --cost-image onto -o" "${render[@]}" scene.nff -o out/a.png --cost-image "$TMP/out/a.png"
refused "render --stats onto frame 2" "${render[@]}" scene.nff --frames 3 --orbit 10 -o "out/f%02d.png" --stats out/f02.png

# A 254-byte name: written, and no temporary left (its temporary's name is cut to fit).
long=$(printf 'n%.0s' $(seq 250)).png
check "render: a 254-byte -o name is written" "${render[@]}" scene.nff -o "out/$long" --stats "out/${long%.png}.jsn"
check "render: ... the image is there" [ -s "out/$long" ]
check "sim: a 254-byte --stats name is written" "${sim[@]}" scene.nff -o out/b.png --stats "out/${long%.png}.jsn"
check "no temporaries left: $(ls -A out | grep '^\.' | head -c 100)" [ -z "$(ls -A out | grep '^\.')" ]
rm -rf out && mkdir out

# A run with no packets (a camera that sees nothing, every primary ray misses the grid):
# the VCD has its header and signals, and SystemC's internal FIFO is named nowhere.
printf 'v\nfrom 0 0 5\nat 0 0 10\nup 0 1 0\nangle 30\nhither 0.001\nresolution 2 2\nl 0 0 5\nf 1 0 0 1 0 0 0 1\ns 0 0 0 1\n' >away.nff
"${run_limited[@]}" "$BUILD/torusrt-sim" away.nff -o out/away.png --stats out/away.json --vcd out/away.vcd \
    >away.out 2>away.err </dev/null
check "empty run: exit $? : $(head -c 200 away.err)" [ -s out/away.png ]
check "empty run: no packets ($(json_get out/away.json packets.created.ray))" \
    [ "$(json_get out/away.json packets.created.ray)" = 0 ]
check "empty run: the VCD has its header" grep -q '^\$enddefinitions' out/away.vcd
check "empty run: the VCD lists the signals" grep -q '^\$var' out/away.vcd
check "empty run: no message names the FIFO: $(grep -h torusrt-vcd away.out away.err | head -c 200)" \
    [ -z "$(grep -h 'torusrt-vcd' away.out away.err)" ]
finish
