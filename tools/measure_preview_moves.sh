#!/usr/bin/env bash
# Measures `mvpl preview` across camera moves (docs/results.md, "The preview after a camera
# move"): on the Cornell box and DamagedHelmet under the default sky at 512², a scripted run
# that rests, orbits for three frames and resets the view, three times, with
#   before:  no kept shadow cubes, no catch-up (--kept-maps 0 --catch-up 0)
#   kept:    kept cubes, the frame budget after a move (--catch-up 0)
#   after:   the defaults (kept cubes, the first frame at rest catching up)
# and prints each run's summary (fps while moving, the share of the resting VPLs in the first
# frame at rest, the time to 90 % of them). Then the relMSE of the resting picture before a move
# and of the first frame at rest after it, against a long render of the same view.
#
# usage: tools/measure_preview_moves.sh [BUILD_DIR [OUT_DIR]]   (defaults: build, a temp dir)
# Environment: REST (frames at rest before each move, default 60), REF_VPLS (light paths of the
# converged image, default 2048), SCENES (default: the two above), PREVIEW_ARGS (added to every
# preview, e.g. "--devices 1"; default none: the preview's defaults).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=${2:-$(mktemp -d)}
rest=${REST:-60}
ref_vpls=${REF_VPLS:-2048}
mvpl="$build/bin/mvpl"
helmet=../shared/gltf-samples/DamagedHelmet/glTF/DamagedHelmet.gltf
read -r -a scenes <<<"${SCENES:-assets/cornell-box/cbox.gltf $helmet}"
mkdir -p "$out"
read -r -a preview_args <<<"${PREVIEW_ARGS:-}"
window() { xvfb-run -a -s "-screen 0 1024x768x24" "$mvpl" preview "$@" "${preview_args[@]}"; }

# Three moves: two orbit steps and a reset (back to the first view), then `rest` frames at rest.
script="$out/moves.txt"
: >"$script"
for m in 0 1 2; do
  f=$((rest + m * (rest + 3)))
  printf '%d orbit 10 0\n%d orbit 10 0\n%d key r\n' "$f" $((f + 1)) $((f + 2)) >>"$script"
done
frames=$((3 * (rest + 3) + rest))

for scene in "${scenes[@]}"; do
  name=$(basename "$scene" .gltf)
  echo "== $name"
  for config in "before:--kept-maps 0 --catch-up 0" "kept:--catch-up 0" "after:"; do
    label=${config%%:*}
    # shellcheck disable=SC2086
    window "$scene" --res 512x512 --frames "$frames" --script "$script" ${config#*:} |
      sed "s/^/$label: /"
  done
  "$mvpl" render "$scene" --res 512x512 --vpls "$ref_vpls" -o "$out/$name-converged.exr" --quiet
  # The resting picture just before the first move, and the first frame at rest after it.
  window "$scene" --res 512x512 --frames "$rest" --screenshot "$out/$name-resting.exr" --quiet
  for config in "before:--kept-maps 0 --catch-up 0" "after:"; do
    label=${config%%:*}
    # shellcheck disable=SC2086
    window "$scene" --res 512x512 --frames $((rest + 4)) --script "$script" \
      --screenshot "$out/$name-first-$label.exr" --quiet ${config#*:}
  done
  for image in resting first-before first-after; do
    printf '%s relMSE: ' "$image"
    "$mvpl" compare "$out/$name-$image.exr" "$out/$name-converged.exr" | head -1
  done
done
