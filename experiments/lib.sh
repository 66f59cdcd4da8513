# shellcheck shell=bash
# shellcheck disable=SC2034  # the settings are used by the scripts that source this file
# lib.sh - shared settings for the reproduction scripts (sourced, not run).
# Sets EXP (this folder), REPO (the source tree), BUILD (the build folder) and SIM (torusrt-sim).
# The build folder comes from --build DIR (parsed by each script), else $TORUSRT_BUILD,
# else REPO/build.
EXP=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
REPO=$(cd "$EXP/.." && pwd)
BUILD=${TORUSRT_BUILD:-$REPO/build}

die() { echo "$(basename "$0"): $*" >&2; exit 2; }

# set_build DIR: make BUILD absolute and check the simulator is there.
set_build() {
    [ -d "$1" ] || die "build folder '$1' does not exist (configure and build first, or pass --build / TORUSRT_BUILD)"
    BUILD=$(cd "$1" && pwd)
    SIM=$BUILD/torusrt-sim
}

# abspath PATH: absolute form of a path whose parent exists (the path itself need not).
abspath() { local d; d=$(cd "$(dirname "$1")" && pwd) || return 1; echo "$d/$(basename "$1")"; }

# The readings of the paper's unknowns a sweep runs under (docs/fidelity.md), each from the
# environment, today's reading when unset:
#   TORUSRT_SHAPE16        the arrangement of 16 nodes, flat and clustered (default 4x2x2)
#   TORUSRT_LB_MAP         what the load-balancing ("cyclic") points run (default cyclic)
#   TORUSRT_SCENE_IMAGE1/2 the scene files of image 1 and image 2 (default scenes/paper-imageN.nff)
#   TORUSRT_POINT_ARGS     more torusrt-sim arguments for every point, split at spaces
#   TORUSRT_MAPS           the full mode's mappings (default "block cyclic bc2 bc3")
SHAPE16=${TORUSRT_SHAPE16:-4x2x2}
read -r -a POINT_ARGS <<<"${TORUSRT_POINT_ARGS:-}"
# The paper's 3D torus shapes for each IP count.
declare -A SHAPE=([1]=1x1x1 [2]=2x1x1 [4]=2x2x1 [8]=2x2x2 [16]=$SHAPE16 [32]=4x4x2 [64]=4x4x4
                  [128]=8x4x4 [256]=8x8x4 [512]=8x8x8)
# Mapping short names (used in point names and CSVs) and torusrt-sim arguments.
declare -A MAPARG=([block]=block [cyclic]=${TORUSRT_LB_MAP:-cyclic} [bc2]=block-cyclic:2 [bc3]=block-cyclic:3)
# The cluster study: 16 clusters on a 4x2x2 torus, load-balancing mapping at the cluster level.
CLUSTER_SHAPE=$SHAPE16
CLUSTER_NODES=16
# The timing profiles swept (torusrt-sim --timing-profile), the default first: each has its own
# results folder RESULTS/PROFILE with the same points, CSVs and plots.
PROFILES=(calibrated literal)

# Sweep definition per mode: image size, scenes, IP counts, mappings, processors per cluster.
# define_mode full|quick
define_mode() {
    case $1 in
        full)
            SIZE=144x144
            SCENES=(image1 image2)
            NLIST=(1 2 4 8 16 32 64 128 256 512)
            read -r -a MAPS <<<"${TORUSRT_MAPS:-block cyclic bc2 bc3}"
            MLIST=(1 2 4 8 12 16 32 64)
            DATAS=(replicated shared)
            CLUSTER_SCENES=(image1 image2)
            ;;
        quick)
            SIZE=32x32
            SCENES=(image1 image2)
            NLIST=(1 4 16)
            MAPS=(block cyclic bc2)
            MLIST=(1 4 16)
            DATAS=(replicated shared)
            CLUSTER_SCENES=(image1)
            ;;
        *) die "mode must be full or quick, not '$1'" ;;
    esac
    MODE=$1
}

scene_file() {
    case $1 in
        image1) echo "${TORUSRT_SCENE_IMAGE1:-$REPO/scenes/paper-image1.nff}" ;;
        image2) echo "${TORUSRT_SCENE_IMAGE2:-$REPO/scenes/paper-image2.nff}" ;;
        *) echo "$REPO/scenes/paper-$1.nff" ;;
    esac
}
