#!/usr/bin/env bash
# The main job: install what is missing, build, generate the default tables into tables/
# and print, per table, its size and its measured off-grid error (also when nothing was rebuilt).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
./build/brdftab generate --manifest tables/default.json --tables tables
# Always end with the per-table summary (size, stated off-grid error), also when every
# file was up to date and nothing was regenerated.
./build/brdftab info --markdown tables/*.h5
