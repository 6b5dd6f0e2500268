#!/usr/bin/env bash
# The main job on a fresh machine: install what is missing, build, run `strata demo`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh build
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}
exec ./build/viewer/strata demo "$@"
