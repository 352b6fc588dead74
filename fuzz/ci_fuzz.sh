#!/bin/sh
# A short libFuzzer run of each reader target, side by side (one per core), for CI (`make
# ci-fuzz`; fuzz/README.md). Seeds from fuzz/make_corpus.py, the dictionary from
# fuzz/make_dict.sh; both are made from the repository alone, so every run starts from the same
# corpus. Exit 1 when a target reports anything (a crash, a leak, a sanitizer report, a timeout,
# an out-of-memory, a rejection without a line): its input is kept in BUILD_DIR/fuzz-ci/.
#   fuzz/ci_fuzz.sh BUILD_DIR [SECONDS [SEED]]     # 60 s each, seed 1 by default
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd)
seconds=${2:-60}
seed=${3:-1}
work=$build/fuzz-ci
rm -rf "$work"
mkdir -p "$work"
formats="keyword inp msh"
for format in $formats; do
  python3 "$root/fuzz/make_corpus.py" "$format" "$work/seed-$format"
  sh "$root/fuzz/make_dict.sh" "$format" > "$work/$format.dict"
  mkdir -p "$work/corpus-$format" "$work/findings-$format"
done
echo "libFuzzer: $seconds s per target, seed $seed"
for format in $formats; do
  # New inputs go to corpus-<format>, the seeds are read from seed-<format>; a finding is
  # written to findings-<format>/ (crash-*, leak-*, timeout-*, oom-*).
  "$build/fuzz/deck_libfuzzer_${format}_reader" -seed="$seed" -max_total_time="$seconds" \
    -max_len=65536 -timeout=20 -rss_limit_mb=4096 -dict="$work/$format.dict" \
    -print_final_stats=1 -artifact_prefix="$work/findings-$format/" \
    "$work/corpus-$format" "$work/seed-$format" > "$work/$format.log" 2>&1 &
  echo $! > "$work/$format.pid"
done
status=0
for format in $formats; do
  if wait "$(cat "$work/$format.pid")"; then
    runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$format.log")
    cov=$(grep -E '^#[0-9]+' "$work/$format.log" | tail -n 1 | grep -oE 'cov: [0-9]+ ft: [0-9]+')
    echo "deck_libfuzzer_${format}_reader: $runs inputs, $cov, no finding"
  else
    status=1
    echo "deck_libfuzzer_${format}_reader: FINDING (log $work/$format.log)"
    tail -n 60 "$work/$format.log"
    for f in "$work/findings-$format"/*; do
      [ -e "$f" ] || continue
      echo "input: $f (reproduce: $build/fuzz/deck_libfuzzer_${format}_reader $f)"
    done
  fi
done
exit $status
