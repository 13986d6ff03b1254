#!/usr/bin/env bash
# Regenerates the measurements of docs/results.md: `mvpl convergence` on the Cornell box (against
# Mitsuba 2's reference) and on the two-room scene (against the mean of four long references of
# our path tracer, made once and kept in OUT/two-room-ref{,-2,-3,-4}.exr), then `mvpl bench` on
# the Cornell box.
#
# usage: tools/make_results.sh [BUILD_DIR [OUT_DIR]]   (defaults: build, docs/results)
# Environment: BUDGET (seconds per method, default 60), REF_SPP (two-room reference, default 16384).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-docs/results}
budget=${BUDGET:-60}
ref_spp=${REF_SPP:-16384}
mvpl="$build/bin/mvpl"
mkdir -p "$out/cornell-box" "$out/two-room"

"$mvpl" convergence assets/cornell-box/cbox.gltf --ref assets/cornell-box/ref-cbox-d6-4096.exr \
  --budget "$budget" --out "$out/cornell-box" | tee "$out/cornell-box/summary.txt"

# The two-room references: the path tracer at 128² and max depth 6, far longer than any budget
# above, four seeds; convergence measures against their mean, whose own noise (≈ 0.3·10⁻³ of
# relMSE, a quarter of one reference's) it prints (docs/results.md, "The reference's own noise").
refs=()
for seed_name in 12345: 2026:-2 2027:-3 2028:-4; do
  seed=${seed_name%%:*}
  ref="$out/two-room-ref${seed_name#*:}.exr"
  if [ ! -f "$ref" ]; then
    "$mvpl" reference assets/two-room/two-room.gltf --res 128x128 --spp "$ref_spp" --seed "$seed" \
      -o "$ref"
  fi
  if [ ${#refs[@]} -eq 0 ]; then refs+=(--ref "$ref"); else refs+=(--and-ref "$ref"); fi
done
"$mvpl" convergence assets/two-room/two-room.gltf "${refs[@]}" \
  --budget "$budget" --out "$out/two-room" | tee "$out/two-room/summary.txt"

"$mvpl" bench assets/cornell-box/cbox.gltf --res 512x512 --shadow-res 256 \
  --json "$out/bench-cornell-box.json" | tee "$out/bench-cornell-box.txt"
