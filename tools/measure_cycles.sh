#!/usr/bin/env bash
# Blender Cycles (CPU) against mvpl at equal wall time on the reference Cornell box (256², max
# depth 6; docs/results.md, "Against Mitsuba 0.6's `vpl`, Cycles and our path tracer"): at each
# level Cycles at a sample count that takes about the level's wall time here, `mvpl render
# --time-budget T` with every VPL shaded, and with row-column sampling (--pool 16384), one after
# the other, seed by seed. Prints one line a run: method, level, seed, what ran, whole-process
# wall seconds, relMSE per pixel and on 8×8 block means against the Mitsuba 2 reference.
#
# usage: tools/measure_cycles.sh [BUILD_DIR [OUT_DIR]]   (defaults: build, a temp dir)
# Needs Debian 12's `blender` (apt-get install blender) and the set-up script of
# ../shared/anchors/cycles (CORNELL_PY), which matches Cycles to the reference (its README).
# Environment: LEVELS ("T:SPP …", default "2:7 5:70 15:290 60:1250": Cycles' spp for about T
# seconds of wall time on two cores), SEEDS (default "1 2"), POOL (default 16384).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-$(mktemp -d)}
mvpl="$build/bin/mvpl"
cornell_py=${CORNELL_PY:-../shared/anchors/cycles/cornell.py}
scene=assets/cornell-box/cbox.gltf
ref=assets/cornell-box/ref-cbox-d6-4096.exr
read -r -a levels <<<"${LEVELS:-2:7 5:70 15:290 60:1250}"
read -r -a seeds <<<"${SEEDS:-1 2}"
pool=${POOL:-16384}
mkdir -p "$out"

errors() {  # IMAGE -> "relMSE_per_pixel relMSE_8x8"
  echo "$("$mvpl" compare "$1" "$ref" | awk '/^relMSE/{print $2}')" \
    "$("$mvpl" compare "$1" "$ref" --block 8 | awk '/^relMSE/{print $2}')"
}
timed() {  # LOG CMD... -> whole-process wall seconds
  /usr/bin/time -f %e -o "$1.time" "${@:2}" >"$1" 2>&1
  cat "$1.time"
}
vpls() { grep -o '^render: [0-9]* VPLs' "$1" | tail -1 | awk '{print $2 " VPLs"}'; }

printf 'method\tT\tseed\twhat\twall_s\trelmse_pixel relmse_8x8\n'
for seed in "${seeds[@]}"; do
  for level in "${levels[@]}"; do
    t=${level%%:*} spp=${level##*:}
    wall=$(timed "$out/cycles.log" blender -b --factory-startup --python "$cornell_py" -- \
      --gltf "$scene" --out "$out/cycles.exr" --spp "$spp" --seed "$seed" --bounces 4)
    printf 'cycles\t%s\t%s\t%s spp\t%s\t%s\n' "$t" "$seed" "$spp" "$wall" "$(errors "$out/cycles.exr")"
    for method in every row-column; do
      extra=(--pool 0)  # every VPL shaded, whatever render's --pool auto picks
      [ "$method" = row-column ] && extra=(--pool "$pool")
      wall=$(timed "$out/$method.log" "$mvpl" render "$scene" --res 256x256 --max-depth 6 \
        --time-budget "$t" --seed "$seed" "${extra[@]}" -o "$out/$method.exr")
      printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$method" "$t" "$seed" "$(vpls "$out/$method.log")" \
        "$wall" "$(errors "$out/$method.exr")"
    done
  done
done
