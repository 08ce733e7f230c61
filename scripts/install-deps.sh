#!/usr/bin/env bash
# Installs the Debian (bookworm) packages FloorCover needs to build, test and run, skipping
# the ones already installed. Run as root (or with sudo available).
set -euo pipefail

packages=(
  build-essential cmake ninja-build ccache pkg-config git file dpkg-dev
  qt6-base-dev qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools qt6-svg-dev libgl-dev
  libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev libboost-dev libboost-graph-dev liblemon-dev
  libtorch-dev libopenblas0-pthread
  libassimp-dev libgdal-dev libgeos-dev libopencv-dev libqcustomplot-dev nlohmann-json3-dev
  libgtest-dev libbenchmark-dev
  libproj-dev proj-bin
  gdal-bin python3 python3-yaml libxml2-utils qpdf
  # the editor tested on a real X server with a window manager (tests/gui/run_under_x11.sh)
  xvfb openbox
  # Qt's own dialogs in the user's language (widgets/window/Translations.cpp)
  qt6-translations-l10n
  # import/export fixtures and validators (issue 5): a CAD library writing DXF, third-party
  # DXF edge cases and 3D models, a JSON-schema validator, clang for the libFuzzer targets
  python3-ezdxf openscad-testing-data assimp-testmodels python3-jsonschema clang
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root (missing: ${missing[*]})" >&2; exit 1; }
  sudo="sudo"
fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
