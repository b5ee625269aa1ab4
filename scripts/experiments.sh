#!/usr/bin/env bash
# Regenerate the paper's experiments (issue 8): CSVs and PNGs in doc/results/, and doc/results.md.
#
#   bash scripts/experiments.sh              # every experiment on every pair (see README for how long it takes)
#   bash scripts/experiments.sh --pairs 12   # 12 pairs per object and experiment, spread over the overlaps
#   bash scripts/experiments.sh --quick      # 4 pairs per object and experiment, for development
#   bash scripts/experiments.sh --noise      # one experiment (flags: build/bench/eval_paper --help)
#   bash scripts/experiments.sh --no-run     # only redraw the plots and rewrite doc/results.md
#
# Experiments not selected keep their earlier CSVs; doc/results.md is rebuilt from every summary present,
# and says for each experiment how it was run (run_<experiment>.csv).
set -euo pipefail
cd "$(dirname "$0")/.."
command -v gnuplot > /dev/null || bash scripts/setup_experiments.sh
out=doc/results
mkdir -p "$out"

args=()
selected=0
run=1
for a in "$@"; do
  case "$a" in
    --no-run) run=0; continue ;;
    --quick|--out|--data|--max-hypotheses|--pairs) ;;
    --*) selected=1 ;;
  esac
  args+=("$a")
done
[ "$selected" -eq 1 ] || args+=(--all)

if [ "$run" -eq 1 ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > /dev/null
  cmake --build build -j2 --target eval_paper > /dev/null
  start=$(date +%s)
  build/bench/eval_paper "${args[@]}" --out "$out" | tee "$out/eval_paper.log"
  seconds=$(( $(date +%s) - start ))
  echo "arguments,started_utc,wall_seconds,cores" > "$out/run.csv"
  echo "${args[*]},$(date -u -d @"$start" +%Y-%m-%dT%H:%MZ),$seconds,$(nproc)" >> "$out/run.csv"
fi

for plot in efficiency overlap accuracy noise stability resolution discrimination; do
  case $plot in
    efficiency) need=efficiency.csv ;; overlap) need=overlap_bins_tensor.csv ;; accuracy) need=accuracy_bunny.csv ;;
    noise) need=noise.csv ;; stability) need=stability.csv ;; resolution) need=resolution.csv ;;
    discrimination) need=discrimination.csv ;;
  esac
  if [ -f "$out/$need" ]; then gnuplot -e "dir='$out'" "bench/plots/$plot.gp"; fi
done
bash scripts/results_md.sh "$out" > doc/results.md
echo "experiments: wrote $out/ and doc/results.md"
