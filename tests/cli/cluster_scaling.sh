#!/usr/bin/env bash
# cluster_scaling.sh - the paper's hierarchical-system study in small: image 1 on 16
# clusters (--ips 4x2x2) with m = 1, 2, 4, 8, 16, 32, 64 processors per cluster.
#   - replicated data: simulated image time strictly falls as m grows, with either dispatch
#     policy, and 64 processors per cluster are more than 32x faster than one;
#   - shared data is never faster than replicated (shortest-queue dispatch at every m), and with
#     either dispatch policy its processors are busier in total (the remote object reads);
#   - every image equals torusrt-render's.
# Image size: the scene's full 144x144 (each run takes 1-3 s); at 48x48 the handful of packets
# per processor makes scheduling luck (which processor gets which packet) larger than the few
# microseconds a remote object read costs, and shared runs can come out faster by chance.
# With round-robin dispatch that luck also shows at 144x144 (under the calibrated profile, with
# ties on the even rings split over both links, shared is 4.8 %, 1.3 % and 6.1 % faster at
# m = 16, 32 and 64), so the shared-vs-replicated time comparison uses the load-aware
# shortest-queue dispatch; the busy-time comparison, which does not depend on scheduling, uses
# both. Shortest-queue can still leave a trace of luck at m = 64 (1,024 processors for 20,736
# pixels), so there shared may be at most 0.5 % faster; below m = 64 it must be strictly slower.
#
# The scene is paper-image1-planar (the nine flakes in one plane): replicated m = 64 runs 59.8x
# faster than m = 1 with shortest-queue dispatch and 51.5x with round-robin.
# The bus runs at the calibrated profile's 0.5 us cycle and memory access: under the fitted
# profile's 4 us cycle the bus carrying every packet into and out of the processors is the
# bottleneck at m = 64 (99 % busy on the busiest bus), and replicated m = 64 is no faster than
# m = 32 (3.0045 s against 3.0043 s).
#
# Usage (CTest runs it so): bash tests/cli/cluster_scaling.sh BUILD_DIR SOURCE_DIR
set -u
source "$(dirname "$0")/common.bash" "$@"
need_exe torusrt-sim torusrt-render
sim="$BUILD/torusrt-sim"
render="$BUILD/torusrt-render"
time_limit 300

# less A B - exit 0 if A < B (numbers).
less() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a != "" && b != "" && a + 0 < b + 0) }'; }

scene=$(source_scene paper-image1-planar) || exit 1
ref="$TMP/ref.png"
if ! "$render" "$scene" -q -o "$ref"; then
    echo "cluster_scaling: torusrt-render failed" >&2
    exit 1
fi

ms="1 2 4 8 16 32 64"
declare -A T BUSY UTIL
for dispatch in round-robin shortest-queue; do
    for data in replicated shared; do
        for m in $ms; do
            name="$dispatch.$data.m$m"
            if ! "${run_limited[@]}" "$sim" "$scene" --ips 4x2x2 --cluster "$m" --data "$data" --dispatch "$dispatch" \
                --timing-profile calibrated --t1 1 -q -o "$TMP/$name.png" --stats "$TMP/$name.json" 2>"$TMP/$name.err"; then
                fail "$name: torusrt-sim failed: $(head -c 400 "$TMP/$name.err")"
                continue
            fi
            if cmp -s "$TMP/$name.png" "$ref"; then pass; else fail "$name: PNG differs from torusrt-render's"; fi
            T[$name]=$(json_get "$TMP/$name.json" sim_time_s)
            BUSY[$name]=$(json_get "$TMP/$name.json" load.busy_s.mean)
            UTIL[$name]=$(json_get "$TMP/$name.json" bus.utilisation.mean)
        done
    done
done

printf '%-15s %4s %14s %14s %10s\n' dispatch m replicated_s shared_s shared_bus
for dispatch in round-robin shortest-queue; do
    for m in $ms; do
        printf '%-15s %4s %14.6f %14.6f %10s\n' "$dispatch" "$m" "${T[$dispatch.replicated.m$m]:-0}" \
            "${T[$dispatch.shared.m$m]:-0}" "${UTIL[$dispatch.shared.m$m]:-}"
    done
done

for dispatch in round-robin shortest-queue; do
    prev=""
    for m in $ms; do
        t=${T[$dispatch.replicated.m$m]:-}
        if [ -n "$prev" ]; then
            if less "$t" "$prev"; then pass
            else fail "$dispatch replicated: m=$m ($t s) not faster than before ($prev s)"; fi
        fi
        prev=$t
        if [ "$m" -gt 1 ]; then
            if less "${BUSY[$dispatch.replicated.m$m]:-}" "${BUSY[$dispatch.shared.m$m]:-}"; then pass
            else fail "$dispatch m=$m: shared processors not busier than replicated"; fi
        fi
    done
    if awk -v a="${T[$dispatch.replicated.m1]:-}" -v b="${T[$dispatch.replicated.m64]:-}" \
        'BEGIN { exit !(a != "" && b + 0 > 0 && a / b > 32) }'; then pass
    else fail "$dispatch replicated: speed-up from m=1 to m=64 not above 32"; fi
done
for m in $ms; do
    r=${T[shortest-queue.replicated.m$m]:-}
    s=${T[shortest-queue.shared.m$m]:-}
    slack=1; [ "$m" = 64 ] && slack=0.995
    if [ -n "$r" ] && [ -n "$s" ] && awk -v s="$s" -v r="$r" -v k="$slack" 'BEGIN { exit !(s + 0 >= r * k) }'; then pass
    else fail "shortest-queue m=$m: shared ($s s) faster than replicated ($r s)"; fi
done

finish
