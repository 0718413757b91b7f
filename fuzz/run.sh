#!/usr/bin/env bash
# Builds the libFuzzer targets of fuzz/ with Clang (ASan and UBSan) in
# fuzz/build/ and runs each for SECONDS seconds (default 60), one after the
# other, from the seed corpus in fuzz/corpus/TARGET (new inputs go to
# fuzz/build/corpus/TARGET). Fails on the first finding, which libFuzzer
# saves as fuzz/build/crash-*, leak-*, timeout-* or oom-*; it prints the
# executions of each target. Needs clang and libclang-rt-14-dev.
set -euo pipefail
cd "$(dirname "$0")"
seconds=${1:-60}
targets="read_image read_height_image read_asc parse_options command_line"
mkdir -p build
flags="-std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -I../include -I../tools"
for t in $targets; do
  libs=-lstb
  # the whole of penrose_mesh: CGAL's exact predicates (GMP, MPFR) and the progress bar's thread
  if [ $t = command_line ]; then libs="$libs -lgmp -lmpfr -pthread"; fi
  clang++ $flags $t.cpp -o build/$t $libs
done
for t in $targets; do
  mkdir -p build/corpus/$t
  # an input over 2 s or 2 GB is a finding
  # (command_line runs penrose_mesh in a folder of its own: findings are saved here all the same)
  (cd build && nice -n 19 ./$t -max_total_time="$seconds" -timeout=2 -rss_limit_mb=2048 -print_final_stats=1 \
       -artifact_prefix="$PWD/" corpus/$t ../corpus/$t 2> $t.log) || { tail -40 build/$t.log; echo "fuzz/run.sh: $t found a problem"; exit 1; }
  echo "$t: $(grep -o 'Done [0-9]* runs in [0-9]* second' build/$t.log)"
done
