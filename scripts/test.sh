#!/usr/bin/env bash
# Quick start, second command: set up, build, and run the whole test suite (ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh build
ctest --test-dir build --output-on-failure --timeout 900 -j "$(nproc)"
# The checking builds (scripts/check.sh): ASan+UBSan over the whole suite, TSan over the threaded
# tests, a bounded loader-fuzzer run. Each builds in its own folder, so they cost most of CI's
# time; STRATA_CHECKS picks a subset ("asan fuzz") or "none" to skip them locally.
checks=${STRATA_CHECKS:-asan tsan fuzz}
if [ "$checks" != none ]; then
    # shellcheck disable=SC2086  # a list of check names
    bash scripts/check.sh $checks
fi
