#!/usr/bin/env bash
# Scenes of 1, 10, 100 and 1,000 synthetic materials (ghs and ls alternating, seed 7):
# the cost model's choices, generation time, bytes on disk, the largest stored off-grid
# error per family, and the time of a second generate on the unchanged scene (no table work).
# Usage: scripts/scene_bench.sh [BUILD_DIR] [WORK_DIR]   (docs/scenes.md "Measured")
set -euo pipefail
cd "$(dirname "$0")/.."
exe="${1:-build}/brdftab"
work="${2:-build/scene_bench}"
mkdir -p "$work"
for n in 1 10 100 1000; do
  d="$work/n$n"
  rm -rf "$d"
  "$exe" scene-synth "$n" --seed 7 > "$work/scene$n.json"
  echo "== $n materials"
  "$exe" plan --scene "$work/scene$n.json" | sed -n '2,6p'
  s=$(date +%s.%N)
  /usr/bin/time -f "peak_rss_kb %M" "$exe" generate -q --scene "$work/scene$n.json" --tables "$d" > "$d.log" 2> "$d.time"
  e=$(date +%s.%N)
  s2=$(date +%s.%N)
  "$exe" generate -q --scene "$work/scene$n.json" --tables "$d" > "$d.log2"
  e2=$(date +%s.%N)
  echo "generate: $(echo "$e - $s" | bc) s, $(cat "$d.time"); second generate: $(echo "$e2 - $s2" | bc) s ($(tail -c 120 "$d.log2"))"
  echo "bytes on disk: $(du -cb "$d"/*.h5 "$d"/scene.index | tail -1 | cut -f1)"
  "$exe" info --markdown "$d"/*.h5 | awk -F'|' 'NR > 2 { split($2, f, "."); fam = f[1]; gsub(/ /, "", fam);
      v = $8 + 0; if (v > m[fam]) m[fam] = v } END { for (k in m) printf "max stored abs error %s: %.2e\n", k, m[k] }'
done
echo "== the generic default tables (reference)"
"$exe" info --markdown tables/smith_gbeckmann.h5 tables/ghs_sigma_rel.h5 tables/hfunc.h5 tables/ls.h5 tables/fresnel.h5 |
  awk -F'|' 'NR > 2 && $3 ~ /g1_precise|sigma_rel2_grid|hfunc_ls[012] |ls_kd|ls_albedo |fresnel/ {
               split($2, f, "."); fam = f[1]; gsub(/ /, "", fam); v = $8 + 0; if (v > m[fam]) m[fam] = v }
             END { for (k in m) printf "max stored abs error %s (generic, the grid form datasets): %.2e\n", k, m[k] }'
