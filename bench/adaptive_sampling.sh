#!/usr/bin/env bash
# Adaptive against uniform sampling at equal cost, on scenes/whitted.json and scenes/spot.json
# (textured): each is rendered uniformly at increasing spp and adaptively at decreasing
# thresholds, one thread each, and every image's error is measured against a uniform render at
# many more samples. bench/adaptive_sampling_report.py then compares each adaptive render with the
# uniform curve interpolated at the same CPU time (and at the same ray count) and prints Markdown.
#
#   bench/adaptive_sampling.sh [--lancer PATH] [--size WxH] [--reference-spp N]
#                              [--uniform "16 32 ..."] [--thresholds "0.1 0.05 ..."]
#                              [--min-spp N] [--max-spp N] [--scenes "whitted spot"]
#
# Times are CPU seconds (user + system, from /usr/bin/time) of a whole lancer process at
# --threads 1: on a machine shared with other work they move far less than wall-clock times.
# Images and the CSV go to a fresh /tmp/lancer-adaptive-bench.* folder.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
lancer=$root/bin/lancer
size=160x120
reference_spp=8192
uniform="16 32 64 128 256 512"
thresholds="0.1 0.07 0.05 0.03 0.02"
min_spp=16
max_spp=1024
scenes="whitted spot"
while [[ $# -gt 0 ]]; do
    case $1 in
        --lancer) lancer=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        --reference-spp) reference_spp=$2; shift 2 ;;
        --uniform) uniform=$2; shift 2 ;;
        --thresholds) thresholds=$2; shift 2 ;;
        --min-spp) min_spp=$2; shift 2 ;;
        --max-spp) max_spp=$2; shift 2 ;;
        --scenes) scenes=$2; shift 2 ;;
        *) echo "usage: see the header of $0" >&2; exit 2 ;;
    esac
done
[[ -x $lancer ]] || { echo "no lancer at $lancer (build it, or give --lancer)" >&2; exit 1; }
width=${size%x*}
height=${size#*x}
out=$(mktemp -d /tmp/lancer-adaptive-bench.XXXXXX)
csv=$out/runs.csv
echo "scene,mode,parameter,cpu_seconds,rays,samples,image,reference" >"$csv"

# A copy of the scene with an "adaptive" block, beside a link to the models it names.
adaptive_scene() {  # scene threshold
    local copy=$out/$1-adaptive-$2.json
    sed "0,/\"render\": {/s//\"render\": { \"adaptive\": { \"min_spp\": $min_spp, \"threshold\": $2 },/" \
        "$root/scenes/$1.json" >"$copy"
    echo "$copy"
}
ln -s "$root/scenes/models" "$out/models"

# Renders; appends one CSV row with the CPU time and lancer's own counts (--stats).
render() {  # scene mode parameter scene-file image options...
    local scene=$1 mode=$2 parameter=$3 file=$4 image=$5
    shift 5
    /usr/bin/time -f "%U %S" -o "$out/time.txt" \
        "$lancer" "$file" -o "$image" --width "$width" --height "$height" --threads 1 --stats \
        --quiet "$@" 2>"$out/stats.txt"
    local cpu rays samples
    cpu=$(awk '{ print $1 + $2 }' "$out/time.txt")
    read -r rays samples < <(sed -n 's/^stats: \([0-9]*\) rays, \([0-9]*\) samples.*/\1 \2/p' "$out/stats.txt")
    echo "$scene,$mode,$parameter,$cpu,$rays,$samples,$image,$out/$scene-reference.pfm" >>"$csv"
    echo "  $mode $parameter: ${cpu} s CPU, $rays rays, $samples samples" >&2
}

for scene in $scenes; do
    echo "$scene: reference at $reference_spp spp (seed 1, all threads)" >&2
    "$lancer" "$root/scenes/$scene.json" -o "$out/$scene-reference.pfm" --width "$width" \
        --height "$height" --spp "$reference_spp" --seed 1 --quiet
    for spp in $uniform; do
        render "$scene" uniform "$spp" "$root/scenes/$scene.json" "$out/$scene-uniform-$spp.pfm" \
            --spp "$spp"
    done
    for threshold in $thresholds; do
        render "$scene" adaptive "$threshold" "$(adaptive_scene "$scene" "$threshold")" \
            "$out/$scene-adaptive-$threshold.pfm" --spp "$max_spp"
    done
done

echo "images and $csv in $out" >&2
python3 "$root/bench/adaptive_sampling_report.py" "$csv" \
    --setup "$size, reference $reference_spp spp, adaptive min_spp $min_spp, max_spp $max_spp"
