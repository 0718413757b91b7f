#!/usr/bin/env bash
# Reproduces the paper's Figure 8 against today's CGAL, and the sample-quality
# report, from a fresh clone:
#
#   benchmark/Penrose_Delaunay_triangulation_2/run_benchmarks.sh [--quick] [--out DIR] [--scaling]
#
# --quick:   sizes up to 10^5 (under a minute); default: 10^3 to 4 x 10^6.
# --out:     where results.csv, the plots and the quality report go (default benchmark-results).
# --scaling: measure the speed-up of Parallel_tag against the number of
#            threads (scaling.csv, scaling.png), and the windowed
#            construction against threads and windows (windows.csv,
#            windows.png), even on 2 cores; they are
#            measured anyway on a machine with more than 2. Their sizes are
#            SCALING_SIZES (default "1000000 10000000"; 10^8 needs about
#            25 GB).
# The last full run's results.csv, ratios.md and quality summaries are kept in
# benchmark/Penrose_Delaunay_triangulation_2/results/, under the same names.
# Installs what is missing (Debian packages), builds in Release, checks the
# triangulation against CGAL's on each input at 10^6 points (10^5 with
# --quick; check.txt) with both concurrency tags, runs every (input, size,
# method) in its own process, and draws the plots with gnuplot.
set -euo pipefail
cd "$(dirname "$0")/../.."

quick=0
scaling=0
out=benchmark-results
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) quick=1 ;;
    --out) out="$2"; shift ;;
    --scaling) scaling=1 ;;
    *) echo "usage: $0 [--quick] [--out DIR] [--scaling]" >&2; exit 2 ;;
  esac
  shift
done
mkdir -p "$out"

bash .ci/install-dependencies gnuplot-nox

build=build-benchmarks
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPENROSE_BUILD_BENCHMARKS=ON -DBUILD_TESTING=OFF \
      -DPENROSE_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$build" -j2 --target figure8_benchmark triangulation_benchmark sample_quality_report >/dev/null
bin="$build/benchmark/Penrose_Delaunay_triangulation_2"

if [ $quick = 1 ]; then sizes="1000 3000 10000 30000 100000"; else sizes="1000 3000 10000 30000 100000 300000 1000000 2000000 4000000"; fi
inputs="constant ramp image terrain"
methods="cgal_range incremental hierarchy hierarchy_range penrose penrose_parallel sampling"
target=$([ $quick = 1 ] && echo 100000 || echo 1000000)

# the timings below are of correct triangulations: equal, edge for edge, to CGAL's
: > "$out/check.txt"
for input in $inputs; do
  "$bin/triangulation_benchmark" check "$target" "$input" data/test_image.png | tee -a "$out/check.txt"
  "$bin/triangulation_benchmark" --threads "$(nproc)" check "$target" "$input" data/test_image.png | tee -a "$out/check.txt"
done

raw="$out/raw.csv"
: > "$raw"
for input in $inputs; do
  incremental_seconds=0; incremental_size=0
  for n in $sizes; do
    for method in $methods; do
      reps=5
      if [ $quick = 1 ]; then reps=3; elif [ "$n" -ge 1000000 ]; then reps=3; fi
      if [ "$method" = incremental ]; then
        # one point at a time from a fixed start costs about n^1.5: stop before a run exceeds ~30 s
        if [ "$incremental_size" -gt 0 ]; then
          predicted=$(awk -v t="$incremental_seconds" -v a="$incremental_size" -v b="$n" 'BEGIN{print t*(b/a)^1.5}')
          if awk -v p="$predicted" 'BEGIN{exit !(p > 30)}'; then continue; fi
          if awk -v p="$predicted" 'BEGIN{exit !(p > 3)}'; then reps=1; fi
        fi
      fi
      row=$("$bin/figure8_benchmark" "$input" "$n" "$method" "$reps" data/test_image.png)
      echo "$row" | tee -a "$raw"
      if [ "$method" = incremental ]; then
        incremental_seconds=$(echo "$row" | cut -d, -f4); incremental_size=$(echo "$row" | cut -d, -f2)
      fi
    done
  done
done

# ratios to CGAL's range insertion of the same points
csv="$out/results.csv"
awk -F, 'BEGIN { OFS = "," }
  { row[NR] = $0; if($3 == "cgal_range") ref[$1 "," $2] = $4 }
  END {
    print "input,N,method,median_seconds,ns_per_point,ratio_to_cgal_range,peak_bytes_per_point"
    for(i = 1; i <= NR; ++i) {
      split(row[i], f, ",")
      r = ref[f[1] "," f[2]]
      print f[1], f[2], f[3], f[4], f[5], (r > 0 ? sprintf("%.4g", f[4] / r) : ""), f[6]
    }
  }' "$raw" > "$csv"

# the table of ratios at the size of the checks
{
  echo "| input | N | method | median s | ns/point | ratio to CGAL range insertion | peak bytes/point |"
  echo "|---|---|---|---|---|---|---|"
  awk -F, -v t="$target" 'NR > 1 && ($2 >= t * 0.97 && $2 <= t * 1.03) { printf "| %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7 }' "$csv"
} > "$out/ratios.md"

# plots: time against N (log-log, like Figure 8) and ns per point against N
labels="cgal_range:CGAL range insertion|incremental:CGAL insert one by one, no hint|hierarchy:Devillers hierarchy, one by one|hierarchy_range:Devillers hierarchy, range|penrose:Penrose DT (sampling + triangulation)|penrose_parallel:Penrose DT, Parallel_tag on $(nproc) threads|sampling:Penrose sampling alone"
for input in $inputs; do
  for m in $methods; do
    awk -F, -v i="$input" -v m="$m" 'NR > 1 && $1 == i && $3 == m { print $2, $4, $5 }' "$csv" > "$out/.$input.$m.dat"
  done
  for kind in time ns; do
    col=$([ $kind = time ] && echo 2 || echo 3)
    plot=""
    IFS='|'
    for pair in $labels; do
      m=${pair%%:*}; title=${pair#*:}
      [ -s "$out/.$input.$m.dat" ] || continue
      plot="$plot${plot:+, }'$out/.$input.$m.dat' using 1:$col with linespoints title '$title'"
    done
    unset IFS
    ylabel=$([ $kind = time ] && echo "seconds (median)" || echo "ns per point")
    logy=$([ $kind = time ] && echo "set logscale y" || echo "unset logscale y")
    gnuplot <<EOF
set terminal pngcairo size 900,600 noenhanced
set output '$out/figure8_${input}_$kind.png'
set title 'Delaunay triangulation of the Penrose samples: $input density'
set logscale x
$logy
set xlabel 'number of points'
set ylabel '$ylabel'
set key top left
set grid
plot $plot
EOF
  done
done
rm -f "$out"/.*.dat

# sample quality, 64k points at constant density, with and without correction vectors
for c in 1 0; do
  name=$([ $c = 1 ] && echo corrected || echo raw)
  "$bin/sample_quality_report" constant 65536 $c "$out/quality_$name" > /dev/null
done
gnuplot <<EOF
set terminal pngcairo size 900,600 noenhanced
set datafile separator ','
set output '$out/quality_spectrum.png'
set title 'Radially averaged power spectrum, constant density, 64k points (16 windows of 4096 points)'
set xlabel 'frequency (1/window)'
set ylabel 'power'
set grid
plot '$out/quality_corrected_spectrum.csv' every ::1 using 1:2 with lines lw 2 title 'with correction vectors', \
     '$out/quality_raw_spectrum.csv' every ::1 using 1:2 with lines title 'raw tile vertices'
set output '$out/quality_anisotropy.png'
set title 'Anisotropy of the power spectrum (dB)'
set ylabel 'anisotropy (dB)'
plot '$out/quality_corrected_spectrum.csv' every ::1 using 1:3 with lines lw 2 title 'with correction vectors', \
     '$out/quality_raw_spectrum.csv' every ::1 using 1:3 with lines title 'raw tile vertices'
set output '$out/quality_angles.png'
set title 'Minimum angle of the Delaunay triangles, constant density, 64k points'
set xlabel 'minimum angle (degrees)'
set ylabel 'fraction of triangles'
set style fill transparent solid 0.5
plot '$out/quality_corrected_angles.csv' every ::1 using 1:2 with boxes title 'with correction vectors', \
     '$out/quality_raw_angles.csv' every ::1 using 1:2 with boxes title 'raw tile vertices'
EOF

# speed-up of Parallel_tag against threads, ramp density: each run a fresh
# process, the median of three against Sequential_tag's
if [ $scaling = 1 ] || [ "$(nproc)" -gt 2 ]; then
  scaling=1
  once() {  # ns per point of one construction of n points: once [--threads T]
    for r in 1 2 3; do "$bin/triangulation_benchmark" "$@" once "$n" ramp penrose | awk '{print $(NF-4)}'; done |
      sort -g | sed -n 2p
  }
  echo "N,threads,ns_per_point,speed_up" > "$out/scaling.csv"
  for n in ${SCALING_SIZES:-1000000 10000000}; do
    sequential=$(once)
    for t in 1 2 4 8 16 32 64; do
      [ "$t" -le "$(nproc)" ] || break
      ns=$(once --threads "$t")
      echo "$n,$t,$ns,$(awk -v s="$sequential" -v p="$ns" 'BEGIN{printf "%.3f", s / p}')" | tee -a "$out/scaling.csv"
    done
  done
  plot=""
  for n in ${SCALING_SIZES:-1000000 10000000}; do
    awk -F, -v n="$n" '$1 == n { print $2, $4 }' "$out/scaling.csv" > "$out/.scaling.$n.dat"
    plot="$plot${plot:+, }'$out/.scaling.$n.dat' using 1:2 with linespoints title '$n points'"
  done
  gnuplot <<EOF
set terminal pngcairo size 900,600 noenhanced
set output '$out/scaling.png'
set title 'Parallel_tag: speed-up against Sequential_tag, ramp density, $(nproc) cores'
set logscale x 2
set xlabel 'threads (tbb::global_control)'
set ylabel 'speed-up'
set key top left
set grid
plot $plot, x with lines dashtype 2 title 'linear'
EOF
  rm -f "$out"/.scaling.*.dat

  # the windowed construction (window_benchmark speed): K x K windows and the
  # border in TBB tasks, its ratio to CGAL's range insertion against threads
  echo "N,windows,threads,ratio_to_cgal" > "$out/windows.csv"
  for n in ${SCALING_SIZES:-1000000 10000000}; do
    for k in 1 2 4 8 16 32; do
      for t in 1 2 4 8 16 32 64; do
        [ "$t" -le "$(nproc)" ] || break
        ratio=$("$bin/window_benchmark" speed "$n" ramp "$k" 3 "$t" | awk '/ratio/ {print $NF}')
        echo "$n,$((k * k)),$t,$ratio" | tee -a "$out/windows.csv"
      done
    done
  done
  plot=""
  for n in ${SCALING_SIZES:-1000000 10000000}; do
    for k in 1 4 16 64 256 1024; do
      awk -F, -v n="$n" -v k="$k" '$1 == n && $2 == k { print $3, $4 }' "$out/windows.csv" > "$out/.windows.$n.$k.dat"
      plot="$plot${plot:+, }'$out/.windows.$n.$k.dat' using 1:2 with linespoints title '$n points, $k windows'"
    done
  done
  gnuplot <<EOF
set terminal pngcairo size 900,600 noenhanced
set output '$out/windows.png'
set title 'Windows and the border in TBB tasks: time against CGAL range insertion, ramp density, $(nproc) cores'
set logscale xy 2
set xlabel 'threads (tbb::global_control)'
set ylabel 'time / CGAL range insertion (one thread)'
set key top right
set grid
plot $plot
EOF
  rm -f "$out"/.windows.*.dat
fi

echo "results: $out/check.txt, $csv, $out/ratios.md, $out/*.png, $out/quality_*_summary.txt$([ $scaling = 1 ] && echo ", $out/scaling.csv, $out/scaling.png, $out/windows.csv, $out/windows.png")"
