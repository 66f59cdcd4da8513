#!/usr/bin/env bash
# Nonsense options give a clear message naming the option, a non-zero exit, and no output files.
source "$(dirname "$0")/common.bash" "$@"
f="$SRC/scenes/paper-image2.nff"
bad() {
  local expect=$1; shift
  rm -rf "$TMP/out"; mkdir -p "$TMP/out"
  "$BUILD/torusrt-sim" "$f" -o "$TMP/out/x.png" --stats "$TMP/out/x.json" --vcd "$TMP/out/x.vcd" "$@" \
    > "$TMP/stdout" 2> "$TMP/stderr"
  local rc=$?
  if [ $rc -eq 0 ] || [ $rc -ge 128 ]; then fail "$* exited $rc"; return; fi
  if ! grep -q -- "$expect" "$TMP/stderr"; then fail "$*: message lacks '$expect': $(cat "$TMP/stderr")"; return; fi
  if [ -n "$(ls -A "$TMP/out")" ]; then fail "$*: left files $(ls "$TMP/out")"; return; fi
  pass
}
bad "--ips" --ips 0
bad "--ips" --ips 0x2
bad "--ips" --ips 2x2x2x2
bad "--ips" --ips -4
bad "--ips" --ips abc
bad "--map" --map spiral
bad "--map" --map block-cyclic:0
bad "--topology" --topology ring
bad "--link-us" --link-us -5
bad "--link-us" --link-us nan
# One range message for every size out of range, 0 included.
bad "--packet-bytes '-1': must be more than 0 and at most 1000000" --packet-bytes -1
bad "--packet-bytes '0': must be more than 0 and at most 1000000" --packet-bytes 0
bad "--packet-bytes '1e308': must be more than 0 and at most 1000000" --packet-bytes 1e308
bad "--cells" --cells 0
bad "--cells" --cells 2x2
bad "--size" --size 0x10
bad "--quantum" --style lt --quantum 5parsecs
bad "--quantum" --quantum 5ms
# Below SystemC's 1 ps resolution a time would be rounded to nothing: refused.
bad "--link-us: .*1 ps" --link-us 1e-7
bad "--link-bytes-per-us: .*1 ps" --packet-bytes 0.0001 --link-bytes-per-us 1e6
bad "--quantum: .*1 ps" --style lt --quantum 1e-7us
bad "--style" --style fast
bad "--cluster" --cluster 0
bad "--queue" --queue -1
bad "--min-weight" --min-weight -1
bad "--trace-ips" --ips 2 --trace-ips 7
# An empty value is refused, not read as the option's default.
bad "--link-us: an empty value" --link-us ""
bad "--stats: an empty value" --stats ""
bad "--remap: an empty value" --orbit 90 --frames 2 --remap ""
bad "--remap-window: an empty value" --orbit 90 --frames 2 --remap adaptive --remap-window ""
bad "--link-us: an empty value" --link-us=
bad "--data" --data everywhere
bad "--t1" --t1 0
# Ranges and combinations the validator checks before the scene is read.
bad "--cells" --cells 1024
bad "--pilot-size" --pilot-size 8x8
bad "--replicate: only with --map cost" --replicate 0.5
bad "--replicate" --map cost --replicate -1
bad "--replica-choice" --replica-choice far
bad "--queue" --queue 100000001
bad "--max-depth" --max-depth 1001
bad "--trace-from" --trace-from 5 --trace-to 4
bad "frobnicate" --frobnicate
bad "cannot open" --timing "$TMP/missing.timing"
printf 'test_miss -3\n' > "$TMP/neg.timing"
bad "neg.timing:1:" --timing "$TMP/neg.timing"
# A timing file that is not a regular file is named with its option.
mkfifo "$TMP/fifo.timing"
bad "--timing: .*fifo.timing: is a FIFO" --timing "$TMP/fifo.timing"
# A leading zero: the message shows the value as written without it.
bad "--max-depth '012': decimal only .*write '12'" --max-depth 012
bad "--min-weight '00.5': decimal only .*write '0.5'" --min-weight 00.5
bad "--link-us '-007': decimal only .*write '-7'" --link-us -007
bad "--ips '00': decimal only .*write '0'" --ips 00
bad "--t1 '-00': decimal only .*write '-0'" --t1 -00
bad "--pilot-size '016x16': .*decimal only .*write '16'" --ips 2x2 --map cost --pilot-size 016x16
bad "--link-us '00e1': decimal only .*write '0e1'" --link-us 00e1
# A timing key given twice in --timing-values.
bad "--timing-values 'link=2': the key 'link' is given twice" --timing-values link=1,link=2
# A value that underflows to 0 is refused, not read as 0.
bad "--min-weight '1e-400': too close to 0" --min-weight 1e-400
# --help and --version to a full device: exit 1 with the system's reason.
if [ -w /dev/full ]; then
  for option in --help --version; do
    "$BUILD/torusrt-sim" "$option" > /dev/full 2> "$TMP/stderr"
    rc=$?
    check "$option > /dev/full: exit $rc, expected 1" [ "$rc" -eq 1 ]
    check "$option > /dev/full: the system's reason: $(cat "$TMP/stderr")" \
      grep -q "^torusrt-sim: standard output: cannot write: No space left on device$" "$TMP/stderr"
  done
fi
finish
