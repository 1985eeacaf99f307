#!/usr/bin/env bash
# Install what is missing, build, run every test (doctest cases registered with CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
