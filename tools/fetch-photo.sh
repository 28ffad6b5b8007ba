#!/usr/bin/env bash
# Puts the scenarios' photograph (scikit-image's camera.png, Debian package
# python3-skimage) at host_sim/scenarios/photos/camera.png. Copies it from the
# installed package when there is one; otherwise downloads the package with
# apt-get and extracts that one file, without installing the package's
# Python dependencies.
set -euo pipefail
cd "$(dirname "$0")/.."
dest=host_sim/scenarios/photos/camera.png
[ -s "$dest" ] && exit 0
mkdir -p "$(dirname "$dest")"
member=usr/lib/python3/dist-packages/skimage/data/camera.png
if [ -s "/$member" ]; then
  cp "/$member" "$dest"
  exit 0
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# (apt warns that _apt cannot write the temporary folder: harmless, shown only on failure)
(cd "$tmp" && apt-get download -q python3-skimage >/dev/null 2>"$tmp/apt.log") ||
  { cat "$tmp/apt.log" >&2; echo "fetch-photo: cannot download python3-skimage (apt-get update first?)" >&2; exit 1; }
dpkg-deb --fsys-tarfile "$tmp"/python3-skimage_*.deb | tar -xO "./$member" > "$tmp/camera.png"
[ -s "$tmp/camera.png" ] || { echo "fetch-photo: camera.png not found in python3-skimage" >&2; exit 1; }
mv "$tmp/camera.png" "$dest"
