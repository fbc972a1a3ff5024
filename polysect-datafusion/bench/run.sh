#!/usr/bin/env bash
# docs/datafusion.md's benchmark, one size: generates two GeoParquet tables, then runs
# `polysect-datafusion join`, SedonaDB and geopandas on them one after the other, each
# under /usr/bin/time -v, and prints per engine: wall time, the engine's own join time,
# peak resident memory, pair count and wrong pairs against polysect's answer.
#
#   polysect-datafusion/bench/run.sh ROWS VERTICES uniform|clustered|adversarial [DIR] [ENGINES]
#
# Run from the workspace root after `cargo build --release -p polysect-datafusion`;
# PYTHON names an interpreter with bench/compare.py's packages (default python3).
# ENGINES is a space-separated subset of "polysect sedonadb geopandas" (default all).
# Not used by any test.
set -euo pipefail
rows=$1 vertices=$2 layout=$3
dir=${4:-target/join-bench}
engines=${5:-polysect sedonadb geopandas}
py=${PYTHON:-python3}
bin=target/release/polysect-datafusion
here=$(dirname "$0")
mkdir -p "$dir"
name="$dir/${layout}-${rows}x${vertices}"
a="$name-a.parquet" b="$name-b.parquet"
if [ ! -s "$a" ] || [ ! -s "$b" ]; then
  if [ "$layout" = adversarial ]; then
    "$bin" gen --rows "$rows" --vertices "$vertices" --seed 1 --layout adversarial --out "$a" --partner-out "$b"
  else
    "$bin" gen --rows "$rows" --vertices "$vertices" --seed 1 --layout "$layout" --out "$a"
    "$bin" gen --rows "$rows" --vertices "$vertices" --seed 2 --layout "$layout" --out "$b"
  fi
fi
echo "== $layout, $rows x $rows, $vertices vertices; $(uptime)"
field() { sed -n "s/^\s*$1: //p" "$2"; }
for engine in $engines; do
  out="$name-$engine.csv" log="$name-$engine.time"
  case $engine in
    polysect) /usr/bin/time -v "$bin" join "$a" "$b" >"$out" 2>"$log" ;;
    *) /usr/bin/time -v "$py" "$here/compare.py" join "$engine" "$a" "$b" --out "$out" >"$name-$engine.txt" 2>"$log" ;;
  esac
  pairs=$(($(wc -l <"$out") - 1))
  own=$(grep -h -o -E '(in [0-9.]+[a-zµ]+ \(grid|total_s=[0-9.]+)' "$log" "$name-$engine.txt" 2>/dev/null | head -1 || true)
  wrong=""
  if [ "$engine" != polysect ] && [ -s "$name-polysect.csv" ]; then
    wrong=$("$py" "$here/compare.py" diff "$name-polysect.csv" "$out" --show 0)
  fi
  printf '%-10s wall %s  peak %s KiB  pairs %s  own [%s]  %s\n' "$engine" \
    "$(field 'Elapsed \(wall clock\) time \(h:mm:ss or m:ss\)' "$log")" \
    "$(field 'Maximum resident set size \(kbytes\)' "$log")" "$pairs" "$own" "$wrong"
done
