# shellcheck shell=bash
# shellcheck disable=SC2154  # the variables of study.sh, which sources this file
# fit_machine.sh - stages 2 to 5 of experiments/fidelity/study.sh (sourced), on stage 1's scenes
# and cell-step cost, cyclic and route-ties split:
#   2. the bus (F3): bus_cycle x memory_access, shared and replicated at m = M_FIT on 4x2x2,
#      hand-over 0;
#   3. the 1024 times (F2): arrangement x the hand-overs stage 1's cost allows, replicated, with
#      stage 2's bus; once more (stage 2 at stage 3's choice, then stage 3) if that choice is not
#      4x2x2 with hand-over 0;
#   4. the memory accounting (F4) at 16 IPs;
#   5. the fitted files written, and F0-F4 measured again on them.
# Every timed point of stages 2, 3 and 5 is the mean of runs at each bus_arbitration value.
# Sets bus memory shape handover header entry record.

# stage2 TABLE SHAPE HANDOVER: the penalty runs into RES/TABLE.tsv (shape, hand-over, bus, memory,
# image, data, arbitration, JSON).
stage2() {
    local bm b m a d i f t j t1j
    : >"$scratch/$1.tsv"; : >"$scratch/$1.list"
    for bm in "${bus_pairs[@]}"; do
        b=${bm%/*} m=${bm#*/}
        for a in "${arbitrations[@]}"; do
            t=$(timing "bus$b-mem$m-h$3-c$c-a$a" bus_cycle="$b" memory_access="$m" handover="$3" \
                cell_step_packet="$c" bus_arbitration="$a")
            for i in 1 2; do
                f=$image1 t1j=$t1json1; [ $i = 2 ] && f=$image2 t1j=$t1json2
                for d in replicated shared; do
                    j=$runs/$1-$2-h$3-bus$b-mem$m-image$i-$d-a$a.json
                    printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$2" "$3" "$b" "$m" "image$i" "$d" "$a" "$j" \
                        >>"$scratch/$1.tsv"
                    point "$j" --t1-from "$t1j" -- "$sim" "$f" "${common[@]}" --timing "$t" --ips "$2" \
                        --cluster "$m_fit" --data "$d" --preprocess-count "$rule" >>"$scratch/$1.list"
                done
            done
        done
    done
    done_file "$1.tsv"; done_file "$1.list"
    runs "$res/$1.list"
}
# stage3 TABLE: the replicated runs of every arrangement and allowed hand-over into RES/TABLE.tsv
# (shape, hand-over, image, arbitration, JSON), at the bus chosen.
stage3() {
    local sh h a i f t j t1j
    : >"$scratch/$1.tsv"; : >"$scratch/$1.list"
    for sh in "${shapes[@]}"; do
        for h in $(fit allowed "$c"); do
            for a in "${arbitrations[@]}"; do
                t=$(timing "bus$bus-mem$memory-h$h-c$c-a$a" bus_cycle="$bus" memory_access="$memory" handover="$h" \
                    cell_step_packet="$c" bus_arbitration="$a")
                for i in 1 2; do
                    f=$image1 t1j=$t1json1; [ $i = 2 ] && f=$image2 t1j=$t1json2
                    j=$runs/$1-$sh-h$h-bus$bus-mem$memory-image$i-a$a.json
                    printf '%s\t%s\t%s\t%s\t%s\n' "$sh" "$h" "image$i" "$a" "$j" >>"$scratch/$1.tsv"
                    point "$j" --t1-from "$t1j" -- "$sim" "$f" "${common[@]}" --timing "$t" --ips "$sh" \
                        --cluster "$m_fit" --data replicated --preprocess-count "$rule" >>"$scratch/$1.list"
                done
            done
        done
    done
    done_file "$1.tsv"; done_file "$1.list"
    runs "$res/$1.list"
}

stage2 stage2 4x2x2 0
read -r bus memory < <(fit fit2 "$res")
echo "study: stage 2 chose bus_cycle $bus us, memory_access $memory us"
stage3 stage3
read -r shape handover < <(fit fit3 "$res")
echo "study: stage 3 chose $shape, hand-over $handover us"
if [ "$shape" != 4x2x2 ] || [ "$handover" != 0 ]; then
    # The one refinement: stage 2 at stage 3's choice, then stage 3 again; these choices stand.
    stage2 stage2b "$shape" "$handover"
    read -r bus memory < <(fit fit2 "$res" --table stage2b.tsv)
    stage3 stage3b
    read -r shape handover < <(fit fit3 "$res" --table stage3b.tsv)
    echo "study: the refinement chose bus_cycle $bus us, memory_access $memory us, $shape, hand-over $handover us"
fi

# ---- stage 4: memory accounting, the memory figures at 16 IPs
: >"$scratch/stage4.tsv"; : >"$scratch/stage4.list"
for acc in "${accountings[@]}"; do
    IFS=/ read -r hb eb ob <<<"$acc"
    for i in 1 2; do
        f=$image1; [ $i = 2 ] && f=$image2
        j=$runs/stage4-$shape-$hb-$eb-$ob-image$i.json
        printf '%s\t%s\t%s\t%s\t%s\n' "$hb" "$eb" "$ob" "image$i" "$j" >>"$scratch/stage4.tsv"
        point "$j" -- "$sim" "$f" "${common[@]}" --timing "$t0" --ips "$shape" --cell-header-bytes "$hb" \
            --list-entry-bytes "$eb" --object-record-bytes "$ob" >>"$scratch/stage4.list"
    done
done
done_file stage4.tsv; done_file stage4.list
runs "$res/stage4.list"
read -r header entry record < <(fit fit4 "$res")
echo "study: stage 4 chose cell header $header B, list entry $entry B, object record $record B"

# ---- stage 5: the fitted files, and every target measured again on them
"$gen" --variant paper-image1 "$spec1" "$dest/scenes" paper-image1 >/dev/null
"$gen" --variant paper-image2 "$spec2" "$dest/scenes" paper-image2 >/dev/null
fit machines "$res" "$dest/machines" --rule "$rule" --bus "$bus" --memory "$memory" --shape "$shape" \
    --handover "$handover" --cell-step "$c" --header "$header" --entry "$entry" --record "$record" --sim "$sim"
printf '%s\n' "$spec1" "$spec2" | write_file "$res/fitted-specs"
: >"$scratch/residuals.tsv"; : >"$scratch/residuals.list"; : >"$scratch/residuals2.list"
fitted=$dest/machines/timing/fitted.timing
for i in 1 2; do
    f=$dest/scenes/paper-image$i.nff
    j=$runs/residual-t1-image$i.json
    printf 't1\timage%s\t-\t%s\n' "$i" "$j" >>"$scratch/residuals.tsv"
    point "$j" -- "$sim" "$f" --size "$size" --config "$dest/machines/paper-16.toml" --ips 1 >>"$scratch/residuals.list"
    j=$runs/residual-memory-image$i.json
    printf 'memory\timage%s\t-\t%s\n' "$i" "$j" >>"$scratch/residuals.tsv"
    point "$j" -- "$sim" "$f" --size "$size" --config "$dest/machines/paper-16.toml" >>"$scratch/residuals.list"
    for a in "${arbitrations[@]}"; do
        t=$res/timing/fitted-a$a.timing
        sed "s/^bus_arbitration .*/bus_arbitration $a/" "$fitted" | write_file "$t"
        for d in replicated shared; do
            j=$runs/residual-$d-image$i-a$a.json
            printf '%s\timage%s\t%s\t%s\n' "$d" "$i" "$a" "$j" >>"$scratch/residuals.tsv"
            point "$j" --t1-from "$runs/residual-t1-image$i.json" -- "$sim" "$f" --size "$size" \
                --config "$dest/machines/paper-1024-$d.toml" --timing "$t" --cluster "$m_fit" >>"$scratch/residuals2.list"
        done
    done
done
done_file residuals.tsv; done_file residuals.list; done_file residuals2.list
runs "$res/residuals.list"
runs "$res/residuals2.list"
