#!/bin/sh
# Installs what libsample's build, tools and tests need on Debian 12, and
# nothing if it is all there already. Run as root (or with sudo available).
set -eu
PKGS="cmake make gcc g++ pkg-config
libopenimageio-dev openimageio-tools
libopencolorio-dev opencolorio-tools
libopenexr-dev openexr
libcjson-dev
libosmesa6-dev
libegl-dev libopengl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
clang libclang-rt-14-dev
chromium fonts-dejavu-core
python3 python3-numpy python3-pytest"
missing=""
for p in $PKGS; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "install-deps: installing:$missing" >&2
  SUDO=""
  [ "$(id -u)" = 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
