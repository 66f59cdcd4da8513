#!/usr/bin/env bash
# bad_nff.sh - every malformed scene in tests/nff_bad must make torusrt-render fail cleanly:
# a non-zero exit that is not a crash (< 128), a "FILE:LINE:" message on stderr, and no
# output file of any kind left behind.
#
# Usage (CTest runs it so): bash tests/cli/bad_nff.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-render
render="$BUILD/torusrt-render"
corpus="$SRC/tests/nff_bad"
if [ ! -d "$corpus" ]; then
    echo "bad_nff: no corpus folder $corpus" >&2
    exit 1
fi

# A hung renderer is a failure, not a stuck test run.
time_limit 120

shopt -s nullglob
files=("$corpus"/*.nff)
if [ ${#files[@]} -eq 0 ]; then
    echo "bad_nff: no .nff files in $corpus" >&2
    exit 1
fi

# Whether some line of $1 (a file) contains "$2:NUMBER:"; the path is matched literally.
names_file_and_line() {
    local log=$1 path=$2 line rest
    while IFS= read -r line || [ -n "$line" ]; do
        while [[ $line == *"$path:"* ]]; do
            rest=${line#*"$path:"}
            if [[ $rest =~ ^[0-9]+: ]]; then
                return 0
            fi
            line=$rest
        done
    done <"$log"
    return 1
}

for file in "${files[@]}"; do
    name=$(basename "$file")
    out_dir="$TMP/out_$name"   # the renderer's output folder: must stay empty
    log="$TMP/stderr_$name"    # kept outside out_dir
    mkdir -p "$out_dir"
    "${run_limited[@]}" "$render" "$file" -o "$out_dir/out.png" --stats "$out_dir/out.json" \
        >/dev/null 2>"$log" </dev/null
    status=$?

    problems=()
    if [ "$status" -eq 0 ]; then
        problems+=("exit status 0 (the file was accepted)")
    elif [ "$status" -ge 128 ]; then
        problems+=("exit status $status (killed by signal $((status - 128)): a crash)")
    elif [ "${#run_limited[@]}" -gt 0 ] && [ "$status" -eq 124 ]; then
        problems+=("timed out")
    fi
    if ! names_file_and_line "$log" "$file"; then
        problems+=("stderr does not contain '$file:LINE:'")
    fi
    leftovers=$(find "$out_dir" -mindepth 1 -print 2>/dev/null)
    if [ -n "$leftovers" ]; then
        problems+=("left files behind: $(echo "$leftovers" | tr '\n' ' ')")
    fi

    if [ ${#problems[@]} -eq 0 ]; then
        pass
    else
        fail "$name:"
        for p in "${problems[@]}"; do
            echo "    $p"
        done
        echo "    stderr: $(head -c 400 "$log")"
    fi
done

finish
