#!/usr/bin/env bash
# experiments/sweep --backend slurm takes --slurm-args as one sbatch option ("--partition=short",
# a value that starts with a dash), as several in one word, and in the --slurm-args=VALUE form;
# each reaches the sbatch command line as its own words. No Slurm is needed: a stand-in sbatch
# on PATH records its arguments and refuses the job, so the sweep stops after submitting.
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim
for tool in python3 jq; do
    command -v $tool >/dev/null || { fail "$tool not installed"; finish; exit 1; }
done
mkdir -p "$TMP/bin"
cat >"$TMP/bin/sbatch" <<SBATCH
#!/usr/bin/env bash
printf '%s\n' "\$@" >"$TMP/sbatch.args"
echo "sbatch: stand-in: no Slurm here" >&2
exit 1
SBATCH
chmod +x "$TMP/bin/sbatch"
scene=$SRC/scenes/paper-image2.nff

# submitted NAME SLURM-OPTION...: runs a one-point Slurm sweep with the given --slurm-args words;
# passes if the sweep reached sbatch (the command line was accepted), its output in $TMP/NAME.out.
submitted() {
    local name=$1
    shift
    rm -f "$TMP/sbatch.args"
    PATH=$TMP/bin:$PATH TORUSRT_BUILD=$BUILD "$SRC/experiments/sweep" "$scene" --axis ips=1 --out "$TMP/$name" \
        --backend slurm "$@" -- --size 8x8 >"$TMP/$name.out" 2>&1
    check "$name: the command line is accepted and sbatch runs ($(tail -n 2 "$TMP/$name.out" | tr '\n' ' '))" \
        test -s "$TMP/sbatch.args"
}
# has WORD: sbatch got WORD as one of its arguments.
has() { grep -qxF -- "$1" "$TMP/sbatch.args"; }

submitted one --slurm-args "--partition=short"
check "one option: sbatch gets --partition=short" has --partition=short
submitted equals --slurm-args=--account=foo
check "--slurm-args=VALUE: sbatch gets --account=foo" has --account=foo
submitted several --slurm-args "--partition=short --time=0:20:00 --account foo"
check "several options: sbatch gets --partition=short" has --partition=short
check "several options: sbatch gets --time=0:20:00" has --time=0:20:00
check "several options: sbatch gets --account and foo as two words" \
    test "$(grep -A1 -xF -- --account "$TMP/sbatch.args" | tail -n 1)" = foo
submitted several_equals "--slurm-args=--partition=short --time=0:20:00"
check "several options after '=': sbatch gets --time=0:20:00" has --time=0:20:00
check "the refused job is reported" grep -q "sbatch failed" "$TMP/several_equals.out"
finish
