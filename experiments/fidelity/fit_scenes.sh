# shellcheck shell=bash
# shellcheck disable=SC2154  # the variables of study.sh, which sources this file
# fit_scenes.sh - stage 1 of experiments/fidelity/study.sh (sourced): the scene work and the
# packet cost per cell step, chosen jointly on F1 (units) and F0 (the T(1) window).
# Runs the renderer's units at 8x8 for every layout x scale x counting rule and one T(1) run at
# cell_step_packet 0 for every scene variant; the four costs come from the identity
# T(1)|c = T(1)|0 + c x cell_steps, checked on the chosen combination by a real run (more than
# 0.1 % apart: every c is run and stage 1 scored again on the runs).
# Sets spec1 rule spec2 c (the choice), image1 image2 (its scene files), t1json1 t1json2.

: >"$scratch/units.tsv"; : >"$scratch/units.list"
for l in "${layouts[@]}"; do
    for s in "${scales[@]}"; do
        f=$(scene 1 "layout=$l,scale=$s,lights=2,margin=1.03")
        for r in "${rules[@]}"; do
            j=$runs/units-$l-$s-$r.json
            printf '%s\t%s\t%s\t%s\n' "$l" "$s" "$r" "$j" >>"$scratch/units.tsv"
            # The renderer writes its files only when it succeeds: the JSON marks the run done.
            printf '%s\t%q %q --size 8x8 --preprocess-count %q -q -o %q --stats %q\n' "$j" "$render" "$f" "$r" \
                "${j%.json}.png" "$j" >>"$scratch/units.list"
        done
    done
done
done_file units.tsv; done_file units.list
runs "$res/units.list"

# t1_run IMAGE SPEC COST TIMING LIST: one T(1) run added to the list LIST; its row on stdout.
t1_run() {
    local j=$runs/t1-$(stem "$1" "$2")-c$3.json
    printf 'image%s\t%s\t%s\t%s\n' "$1" "$2" "$3" "$j"
    point "$j" -- "$sim" "$(scene "$1" "$2")" --size "$size" --ips 1 --timing "$4" >>"$scratch/$5.list"
}
t0=$(timing c0 cell_step_packet=0)
: >"$scratch/t1.tsv"; : >"$scratch/t1.list"
for s in "${image1_specs[@]}"; do t1_run 1 "$s" 0 "$t0" t1; done >>"$scratch/t1.tsv"
for s in "${image2_specs[@]}"; do t1_run 2 "$s" 0 "$t0" t1; done >>"$scratch/t1.tsv"
done_file t1.tsv; done_file t1.list
runs "$res/t1.list"
IFS=$'\t' read -r spec1 rule spec2 c < <(fit fit1 "$res" $smoke)
echo "study: stage 1 chose image 1 $spec1, counting $rule, image 2 $spec2, cell_step_packet $c us"

if [ "$c" != 0 ]; then
    tc=$(timing "c$c" "cell_step_packet=$c")
    : >"$scratch/identity.tsv"; : >"$scratch/identity.list"
    { t1_run 1 "$spec1" "$c" "$tc" identity; t1_run 2 "$spec2" "$c" "$tc" identity; } >>"$scratch/identity.tsv"
    done_file identity.tsv; done_file identity.list
    runs "$res/identity.list"
    if ! fit identity "$res"; then
        echo "study: the identity does not hold: every cell_step_packet value is run" >&2
        : >"$scratch/t1all.list"
        for cc in "${cell_steps[@]:1}"; do
            tcc=$(timing "c$cc" "cell_step_packet=$cc")
            for s in "${image1_specs[@]}"; do t1_run 1 "$s" "$cc" "$tcc" t1all; done >>"$scratch/t1.tsv"
            for s in "${image2_specs[@]}"; do t1_run 2 "$s" "$cc" "$tcc" t1all; done >>"$scratch/t1.tsv"
        done
        done_file t1all.list
        runs "$res/t1all.list"
        done_file t1.tsv
        : | write_file "$res/identity-failed"
        IFS=$'\t' read -r spec1 rule spec2 c < <(fit fit1 "$res" $smoke)
        echo "study: stage 1 on every c's runs chose image 1 $spec1, counting $rule, image 2 $spec2, c $c us"
    fi
fi
image1=$(scene 1 "$spec1") image2=$(scene 2 "$spec2")
t1json1=$runs/t1-$(stem 1 "$spec1")-c$c.json t1json2=$runs/t1-$(stem 2 "$spec2")-c$c.json
