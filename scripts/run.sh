#!/usr/bin/env bash
# Quick start, first command: set up, build, then show the bundled Cornell box.
# With a display this opens the interactive viewer; without one it renders headless and says where
# the images went.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh build
strata=build/app/strata
scene=assets/cornell/cornell.obj
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ] && "$strata" view --help >/dev/null 2>&1; then
  exec "$strata" view "$scene" "$@"
fi
echo "run: no display; rendering headless instead" >&2
"$strata" render "$scene" --spp 240 --depth 8 --out cornell.png --out cornell.exr "$@"
