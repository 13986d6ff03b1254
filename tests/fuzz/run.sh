#!/usr/bin/env bash
# Runs the scene-loader fuzz target for SECONDS (default 120) from the seed corpus of
# tests/data (valid glTF/GLB/PLY/OBJ/XML fixtures and every malformed one) and tests/fuzz/seeds
# (Mitsuba XML that includes itself, <default>s, several sensors); exits non-zero on a
# finding, whose reproducer is kept in the folder it prints. Usage (after building with
# MVPL_FUZZ=ON, see README.md): tests/fuzz/run.sh [SECONDS] [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-120}
build=${2:-build-fuzz}
work=$(mktemp -d "${TMPDIR:-/tmp}/mvpl-fuzz.XXXXXX")
mkdir -p "$work/corpus" "$work/findings"
cp tests/data/gltf/*.gltf tests/data/gltf/*.glb tests/data/mesh/*.ply tests/data/mesh/*.obj \
  tests/data/mitsuba/*.xml tests/data/bad/* tests/fuzz/seeds/* "$work/corpus/"
# A fixed seed: the same run on every machine of the same speed. 10 s per input is a hang.
if "$build/bin/fuzz_scene_loader" -seed=1 -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$work/findings/" \
    "$work/corpus" > "$work/log.txt" 2>&1; then
  grep -E "^stat::(number_of_executed_units|average_exec_per_sec)|^Done" "$work/log.txt" || true
  rm -rf "$work"
else
  tail -40 "$work/log.txt"
  echo "fuzz: a finding; reproducer and log in $work/findings" >&2
  exit 1
fi
