#!/usr/bin/env bash
# Builds and runs every test on a fresh machine: the release tree (CPU, headless GL on EGL,
# viewer smoke test under Xvfb, the demo report in headless Chromium), then an AddressSanitizer
# + UBSan tree (CPU, loader and GL tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh --test
export EGL_PLATFORM=${EGL_PLATFORM:-surfaceless}

echo "== release build and tests"
bash scripts/build.sh build
ctest --test-dir build --output-on-failure

echo "== ASan + UBSan build and tests"
bash scripts/build.sh build-asan -DSTRATA_SANITIZE=ON -DSTRATA_BUILD_VIEWER=OFF
# Mesa's llvmpipe keeps allocations alive until exit by design; leak checking would only
# report the driver. Every other ASan and UBSan check stays on.
ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir build-asan --output-on-failure
