#!/usr/bin/env bash
# Installs exactly the Debian 12 packages that mvpl's build and tests need. Idempotent: does
# nothing when everything is already installed. Nothing else is downloaded at build or run time.
set -euo pipefail

packages=(
  # toolchain
  cmake g++ make pkg-config clang-format mold
  # engine: Embree (brings oneTBB), glTF, EXR, PNG, maths
  libembree-dev libtbb-dev libtinygltf-dev nlohmann-json3-dev libopenexr-dev libstb-dev libglm-dev
  # tests
  libgtest-dev libgmock-dev
  # GPU renderer (Vulkan on Mesa lavapipe, run-time GLSL compilation, validation in tests);
  # glslang-tools because glslang-dev's CMake config names /usr/bin/glslangValidator
  libvulkan-dev mesa-vulkan-drivers glslang-dev glslang-tools vulkan-validationlayers
  # mesh formats: OBJ (PLY is read by our own loader)
  libtinyobjloader-dev
  # Mitsuba XML scenes (engine/scene/mitsuba/): pugixml, and zlib for `serialized` meshes
  libpugixml-dev zlib1g-dev
  # the shadow pass's simplified shadow proxy (engine/render/shadow_clusters.cpp)
  libmeshoptimizer-dev
  # interactive preview, and its tests under a virtual X server
  libglfw3-dev libimgui-dev xvfb xauth
  # rendering across ranks under mpirun (engine/cluster; optional: -DMVPL_MPI=OFF builds without)
  libopenmpi-dev openmpi-bin
  # convergence plots (tools/plot_convergence.py)
  python3-matplotlib
  # the Python module (python/; optional: -DMVPL_PYTHON=OFF builds without)
  python3-dev python3-numpy pybind11-dev
  # the man page (optional: without help2man the install has none) and `man -l` in its test
  help2man man-db
  # the loaders' fuzz target (tests/fuzz): clang with libFuzzer and its sanitizer runtimes
  clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}" >&2
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
