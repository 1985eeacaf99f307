#!/usr/bin/env bash
# The main job: install what is missing, build, generate the default tables into tables/
# and print, per table, its size and its measured off-grid error.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
./build/brdftab generate --manifest tables/default.json --tables tables
