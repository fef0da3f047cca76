#!/usr/bin/env bash
# lancer vs POV-Ray 3.7 on one scene written for both, rendered with 1 and 2 threads. Prints a
# Markdown report: median times and the ratios POV-Ray / lancer. Both renderers use POV-Ray's
# default adaptive depth control (adc_bailout 1/255: lancer's --adc-bailout), and again without
# it (adc_bailout 0: every ray down to the depth), each against the other with the same setting.
#   whitted: scenes/whitted.json (lancer) and bench/whitted.pov (the same scene for POV-Ray, see
#            its header), 640x480, 16 samples per pixel, depth 5
#   csg:     scenes/csg-whitted.json and bench/csg.pov (POV-Ray's union, merge, intersection and
#            difference of boxes, spheres, cylinders, cones, tori), 640x400, 16 spp, depth 8
#
# Usage: bench/povray_comparison.sh [--scene whitted|csg] [--runs N] [--no-adc0] [--images DIR]
#                                   [--max-wait S]
#   --scene S     the scene to compare: whitted (the default) or csg
#   --runs N      timed runs of each configuration (default 5), after one untimed warm-up run
#   --no-adc0     skip the configurations with adc_bailout 0 (every ray traced), both renderers'
#   --images DIR  also write half-size copies of both renders to DIR (e.g. docs/bench), as
#                 SCENE-lancer.png and SCENE-povray.png (needs ImageMagick's convert)
#   --max-wait S  before each run, wait up to S seconds (default 120) for an idle CPU
#
# The runs of the different configurations are interleaved (lancer 1T, lancer 2T, POV 1T, ...,
# then again) so that a change in the machine's load during the benchmark affects all of them
# alike. Exit status: 0 on success, 1 if anything failed (build, a render, a missing image).
set -euo pipefail

scene_name=whitted
runs=5
adc0=1
images_dir=""
max_wait=120
while (($#)); do
    case $1 in
        --scene) scene_name=${2:?--scene needs whitted or csg}; shift 2 ;;
        --runs) runs=${2:?--runs needs a number}; shift 2 ;;
        --no-adc0) adc0=0; shift ;;
        --images) images_dir=${2:?--images needs a folder}; shift 2 ;;
        --max-wait) max_wait=${2:?--max-wait needs a number of seconds}; shift 2 ;;
        -h|--help) sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
        *) echo "povray_comparison.sh: unknown option '$1' (see --help)" >&2; exit 1 ;;
    esac
done

fail() { echo "povray_comparison.sh: error: $*" >&2; exit 1; }

[[ $runs =~ ^[1-9][0-9]*$ ]] || fail "--runs must be a positive integer"
[[ $max_wait =~ ^[0-9]+$ ]] || fail "--max-wait must be a number of seconds"
# Each scene: the lancer scene, the same scene for POV-Ray, the image size (the .pov files take
# theirs from the command line), a title for the report.
case $scene_name in
    whitted) scene=scenes/whitted.json pov=bench/whitted.pov width=640 height=480
             title="Whitted scene" ;;
    csg)     scene=scenes/csg-whitted.json pov=bench/csg.pov width=640 height=400
             title="CSG scene" ;;
    *) fail "--scene must be whitted or csg, not '$scene_name'" ;;
esac

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"

command -v povray >/dev/null || fail "povray not found (Debian: apt-get install povray)"
command -v python3 >/dev/null || fail "python3 not found"
if [[ ! -x bin/lancer ]]; then
    echo "bin/lancer is missing: building the release preset" >&2
    { cmake --preset release && cmake --build --preset release; } >&2 || fail "the release build failed"
    [[ -x bin/lancer ]] || fail "the release build did not produce bin/lancer"
fi

out=$(mktemp -d /tmp/lancer-povray-bench.XXXXXX)   # POV-Ray may only write in . and /tmp
# Time a private copy, so that a rebuild of bin/lancer during the benchmark cannot mix versions.
cp bin/lancer "$out/lancer"
lancer_tree=$(git describe --always --dirty 2>/dev/null || echo "not a git checkout")
# POV-Ray: the scene's size; +AM1 +A0.0 +R4 +J1.0 = every pixel supersampled on a jittered 4x4
# grid (16 samples per pixel, see bench/whitted.pov); an sRGB PNG like lancer's; -D no display,
# -P no pause. Its statistics on stderr hold the trace time read below.
pov_args=(+I"$pov" +W"$width" +H"$height" +AM1 +A0.0 +R4 +J1.0 File_Gamma=sRGB +FN -D -P)

configs=(lancer-1 lancer-2 povray-1 povray-2)
if ((adc0)); then configs+=(lancer-adc0-1 lancer-adc0-2 povray-adc0-1 povray-adc0-2); fi

run_config() { # name log: renders once, the image to $out/name.png, all output to log
    local name=$1 log=$2 threads=${1##*-}
    case $name in
        lancer-adc0-*)
            "$out/lancer" "$scene" -o "$out/$name.png" --threads "$threads" --adc-bailout 0 ;;
        lancer-*)  # POV-Ray's default adc_bailout, 1/255
            "$out/lancer" "$scene" -o "$out/$name.png" --threads "$threads" \
                --adc-bailout 0.00392156863 ;;
        povray-adc0-*)
            povray "${pov_args[@]}" +O"$out/$name.png" +WT"$threads" Declare=ADC=0 ;;
        povray-*)
            povray "${pov_args[@]}" +O"$out/$name.png" +WT"$threads" ;;
    esac >"$log" 2>&1
}

# The machine may be shared: before each run, wait (up to --max-wait seconds) until the CPUs
# have been idle for half a second, so that other work does not land in the timings.
cpu_busy_percent() {
    local _ u n s idle iow irq sirq steal t1 i1 t2 i2
    read -r _ u n s idle iow irq sirq steal _ </proc/stat
    t1=$((u + n + s + idle + iow + irq + sirq + steal)) i1=$((idle + iow))
    sleep 0.5
    read -r _ u n s idle iow irq sirq steal _ </proc/stat
    t2=$((u + n + s + idle + iow + irq + sirq + steal)) i2=$((idle + iow))
    echo $((100 * ((t2 - t1) - (i2 - i1)) / (t2 - t1 > 0 ? t2 - t1 : 1)))
}
busy_starts=0
wait_for_idle() {
    local deadline=$((SECONDS + max_wait))
    while (($(cpu_busy_percent) > 10)); do
        if ((SECONDS >= deadline)); then
            busy_starts=$((busy_starts + 1))
            return 0
        fi
        sleep 2
    done
}

timings=$out/timings.tsv
: >"$timings"
one_run() { # name run-index (0 = warm-up, not recorded)
    local name=$1 i=$2 log=$out/$1.$2.log inner wall user sys TIMEFORMAT='%3R %3U %3S'
    rm -f "$out/$name.png"
    wait_for_idle
    # bash's `time`: wall clock, user and system CPU seconds of the renderer.
    if ! { time run_config "$name" "$log"; } 2>"$out/$name.$i.time"; then
        cat "$log" >&2
        fail "$name failed (log above, kept in $log)"
    fi
    read -r wall user sys <"$out/$name.$i.time"
    [[ -s $out/$name.png ]] || { cat "$log" >&2; fail "$name wrote no image ($out/$name.png)"; }
    case $name in
        # lancer's last line: "lancer: FILE: 640x480, 16 spp, 2 threads, 2.28 s, 37.6 M rays, ..."
        lancer-*) inner=$(grep -oE '[0-9]+\.[0-9]+ s, [0-9.]+ M rays' "$log" | tail -1 | cut -d' ' -f1) ;;
        # POV-Ray: "  Trace Time:       0 hours  0 minutes  2 seconds (2.426 seconds)"
        povray-*) inner=$(grep -E '^ *Trace Time:' "$log" | grep -oE '\([0-9.]+ seconds\)' | tr -d '(' | cut -d' ' -f1) ;;
    esac
    if ((i > 0)); then
        printf '%s\t%s\t%s\t%s\t%s\n' "$name" "$wall" "$user" "$sys" "${inner:-nan}" >>"$timings"
    fi
}

echo "lancer vs POV-Ray, $scene_name scene: $runs timed runs per configuration (+1 warm-up), images and logs in $out" >&2
load_before=$(cut -d' ' -f1-3 /proc/loadavg)
for ((i = 0; i <= runs; i++)); do
    for name in "${configs[@]}"; do
        printf '  run %d/%d %-14s\r' "$i" "$runs" "$name" >&2
        one_run "$name" "$i"
    done
done
printf '%40s\r' '' >&2
load_after=$(cut -d' ' -f1-3 /proc/loadavg)

if [[ -n $images_dir ]]; then
    command -v convert >/dev/null || fail "--images needs ImageMagick's convert"
    mkdir -p "$images_dir"
    convert "$out/lancer-2.png" -resize 50% "$images_dir/$scene_name-lancer.png"
    convert "$out/povray-2.png" -resize 50% "$images_dir/$scene_name-povray.png"
    echo "wrote $images_dir/$scene_name-lancer.png and $images_dir/$scene_name-povray.png" >&2
fi

model=$(lscpu | sed -n 's/^Model name: *//p' | head -1)
options="--runs $runs --max-wait $max_wait"
[[ $scene_name == whitted ]] || options="--scene $scene_name $options"
((adc0)) || options+=" --no-adc0"
echo "## $title, lancer vs POV-Ray 3.7"
echo
echo "- scene: $scene (lancer) and $pov (POV-Ray), ${width}x$height, 16 samples per pixel"
echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "- machine: ${model:-unknown CPU}, $(nproc) CPUs, $(free -g | awk '/^Mem:/ {print $2}') GiB RAM"
echo "- command: \`bench/povray_comparison.sh $options\`"
echo "- lancer: $("$out/lancer" --version 2>&1 | head -1) (bin/lancer; source tree: $lancer_tree)"
echo "- POV-Ray: $(povray --version 2>&1 | grep -m1 -oE 'POV-Ray [0-9][^ ]*')"
echo "- $runs timed runs of each configuration after one warm-up, interleaved; load average before"
echo "  $load_before, after $load_after; runs that started on a busy CPU (waited $max_wait s): $busy_starts"
echo "- lancer: $(grep -oE '[0-9.]+ M rays' "$out/lancer-2.$runs.log" | tail -1) with adc_bailout 1/255$( ((adc0)) && echo ", $(grep -oE '[0-9.]+ M rays' "$out/lancer-adc0-2.$runs.log" | tail -1) with 0") (camera, reflected, refracted and shadow rays)"
echo "- POV-Ray (last 2-thread run):" \
    "$(grep -oE 'Samples: *[0-9]+' "$out/povray-2.$runs.log" | grep -oE '[0-9]+$' | awk -v p=$((width * height)) '{print $1 / p}')" \
    "supersamples per pixel of the image" \
    "(plus the centre ray), $(grep -oE '^Rays: *[0-9]+' "$out/povray-2.$runs.log" | grep -oE '[0-9]+$') rays" \
    "(shadow rays not counted), max trace level reached $(grep -oE 'Max Level: *[0-9/]+' "$out/povray-2.$runs.log" | grep -oE '[0-9/]+$')"
echo
python3 - "$timings" <<'PYTHON'
import statistics, sys

rows = {}
for line in open(sys.argv[1]):
    name, wall, user, system, inner = line.rstrip("\n").split("\t")
    rows.setdefault(name, []).append((float(wall), float(user) + float(system), float(inner)))

def median(name, column):
    values = [r[column] for r in rows.get(name, []) if r[column] == r[column]]  # drop NaN
    return statistics.median(values) if values else float("nan")

label = {
    "lancer": "lancer, adc_bailout 1/255 (POV-Ray's default)",
    "povray": "POV-Ray 3.7 (default adc_bailout 1/255)",
    "lancer-adc0": "lancer, adc_bailout 0 (every ray)",
    "povray-adc0": "POV-Ray 3.7, adc_bailout 0 (every ray)",
}
# Each POV-Ray configuration against lancer's with the same adc_bailout.
against = {"povray": "lancer", "povray-adc0": "lancer-adc0"}
print("| renderer | threads | wall clock: median (min-max) | CPU time | render phase "
      "| POV-Ray / lancer: wall clock | POV-Ray / lancer: render phase |")
print("| --- | ---: | ---: | ---: | ---: | ---: | ---: |")
for kind in ("lancer", "povray", "lancer-adc0", "povray-adc0"):
    for threads in (1, 2):
        name = f"{kind}-{threads}"
        if name not in rows:
            continue
        walls = [r[0] for r in rows[name]]
        wall, cpu, inner = median(name, 0), median(name, 1), median(name, 2)
        if kind not in against:
            ratio_wall = ratio_inner = "1"
        else:
            ratio_wall = f"{wall / median(f'{against[kind]}-{threads}', 0):.2f}"
            ratio_inner = f"{inner / median(f'{against[kind]}-{threads}', 2):.2f}"
        print(f"| {label[kind]} | {threads} | {wall:.2f} s ({min(walls):.2f}-{max(walls):.2f}) "
              f"| {cpu:.2f} s | {inner:.2f} s | {ratio_wall} | {ratio_inner} |")
print()
print("Medians. Wall clock: the whole process as a user waits for it (start-up, parse, render,")
print("PNG). CPU time: user + system. Render phase: lancer's own reported render time, POV-Ray's")
print("reported \"Trace Time\" (POV-Ray also spends about 0.6 s idle in start-up and shut-down,")
print("outside its trace time). Ratios: each POV-Ray row against the lancer row of the same")
print("adc_bailout and threads; above 1 means lancer is faster.")
PYTHON
