#!/usr/bin/env bash
# Installs the Debian bookworm packages visp-ssl needs to build, test and run its demo, and nothing else.
# Idempotent: when everything is already installed it does not touch apt at all.
# Usage: scripts/setup-deps.sh        (as root, or as a user allowed to sudo)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

packages=(
  # Toolchain.
  cmake g++ make pkg-config
  # The ViSP modules the plugin uses (the top-level CMakeLists.txt names the same ones). Naming the
  # components keeps the install short: the full ViSP stack with its recommends takes over 5 minutes.
  libvisp-core-dev libvisp-io-dev libvisp-vision-dev libvisp-detection-dev libvisp-robot-dev
  libvisp-visual-features-dev libvisp-vs-dev libvisp-gui-dev
  # vpV4l2Grabber for tutorial-ssl-detector-live; OpenCV's videoio reads video files and other cameras.
  libvisp-sensor-dev libopencv-videoio-dev
  # libvisp-dev is needed too: it is the package that ships ViSP's CMake config (VISPConfig.cmake), without
  # which find_package(VISP) fails. With --no-install-recommends it only adds the remaining small component
  # -dev packages (about 19 in all), not the heavy recommends.
  libvisp-dev
  # cv::aruco for the AprilTag/ArUco baseline: Debian 4.6 ships it in the contrib package only.
  libopencv-contrib-dev
  # SIMD matching function (Highway), target generator (cairo), linear algebra used with ViSP.
  libhwy-dev libcairo2-dev libeigen3-dev
  # sequence.json and the tutorials' JSON output (nlohmann::ordered_json, header-only, never in an installed header).
  nlohmann-json3-dev
  # ROS 1 bags (modules/rosbag, optional at build time, built and tested in CI).
  librosbag-storage-dev libsensor-msgs-dev libnav-msgs-dev libgeometry-msgs-dev libcv-bridge-dev
  # Tests and benchmarks; visp-images-data holds the real photographs the false-positive tests use.
  libgtest-dev libbenchmark-dev visp-images-data
  # Formatting check, python3 for the end-to-end scripts' JSON and CSV checks, doxygen for the API reference
  # (Doxyfile; built and checked for warnings by scripts/test.sh).
  clang-format python3 doxygen
  # libFuzzer targets (fuzz/, scripts/fuzz.sh): clang 14 and its runtime (libFuzzer, sanitizers).
  clang-14 libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  if [ "$(dpkg-query -W -f='${db:Status-Status}' "$p" 2>/dev/null)" != "installed" ]; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup-deps: all ${#packages[@]} packages already installed"
  exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "setup-deps: not root and no sudo: install these packages as root: ${missing[*]}" >&2
  exit 1
fi

log="${TMPDIR:-/tmp}/visp-ssl-setup-deps.log"
: >"$log"
start=$SECONDS
echo "setup-deps: installing ${#missing[@]} missing packages (log: $log)"
run_logged "$log" "${sudo[@]}" apt-get update
run_logged "$log" "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive \
  apt-get install -y --no-install-recommends "${missing[@]}"
echo "setup-deps: installed ${missing[*]} in $((SECONDS - start)) s"
