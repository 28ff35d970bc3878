#!/usr/bin/env bash
# Quick start, second command: set up, build, and run the whole test suite (ctest).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh build
ctest --test-dir build --output-on-failure --timeout 900 -j "$(nproc)"
