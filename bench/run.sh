#!/usr/bin/env bash
# Builds hpc_bench (Release), runs every benchmark into build/bench/results.json and writes BENCHMARKS.md.
# Usage: bash bench/run.sh [hpc_bench options, e.g. --benchmark_filter=Element]; BUILD_DIR overrides build/.
# SECTIONS=hex-element,hex-solve bash bench/run.sh runs only those sections' benchmarks and rewrites
# only those sections of BENCHMARKS.md (bench/report.py --only; the names are its PARTIAL_SECTIONS).
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}

if [[ ! -f "$build_dir/CMakeCache.txt" ]]; then
  cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
fi
if ! grep -q '^CMAKE_BUILD_TYPE:STRING=Release$' "$build_dir/CMakeCache.txt"; then
  echo "bench/run.sh: $build_dir is not a Release build; timings would be meaningless." >&2
  echo "  reconfigure: cmake -S . -B $build_dir -DCMAKE_BUILD_TYPE=Release" >&2
  exit 1
fi
cmake --build "$build_dir" --target hpc_bench

if [[ -n "${SECTIONS:-}" ]]; then
  filter=$(/usr/bin/python3 -c 'import sys; sys.path.insert(0, "bench"); import report
names = sys.argv[1].split(",")
missing = [n for n in names if n not in report.PARTIAL_SECTIONS]
sys.exit("bench/run.sh: no section " + ", ".join(missing)) if missing else None
print("|".join(report.PARTIAL_SECTIONS[n][1] for n in names))' "$SECTIONS")
  results="$build_dir/bench/results-sections.json"
  "$build_dir/bench/hpc_bench" \
    --benchmark_filter="$filter" \
    --benchmark_min_time=0.2 \
    --benchmark_repetitions=5 \
    --benchmark_enable_random_interleaving=true \
    --benchmark_report_aggregates_only=true \
    --benchmark_out_format=json \
    --benchmark_out="$results" \
    "$@"
  /usr/bin/python3 bench/report.py --only "$SECTIONS" "$results" BENCHMARKS.md
  echo "bench/run.sh: rewrote the sections $SECTIONS of BENCHMARKS.md (raw results: $results)"
  exit 0
fi

# Five repetitions of at least 0.2 s each, interleaved in random order so that a burst of load
# from elsewhere spreads over all benchmarks instead of skewing one; the report uses the median
# (and the spread, cv). The whole run takes about a minute on two cores.
results="$build_dir/bench/results.json"
"$build_dir/bench/hpc_bench" \
  --benchmark_min_time=0.2 \
  --benchmark_repetitions=5 \
  --benchmark_enable_random_interleaving=true \
  --benchmark_report_aggregates_only=true \
  --benchmark_out_format=json \
  --benchmark_out="$results" \
  "$@"

# The factorisation's benchmarks again on Debian's reference BLAS and LAPACK, when another BLAS
# is installed (BLIS, scripts/install-deps.sh): the before / after rows of BENCHMARKS.md.
reference="$build_dir/bench/results-reference-blas.json"
rm -f "$reference"
multiarch=$(gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)
netlib_blas="/usr/lib/$multiarch/blas/libblas.so.3"
netlib_lapack="/usr/lib/$multiarch/lapack/liblapack.so.3"
if [[ -f "$netlib_blas" && -f "$netlib_lapack" && "$(readlink -f "/usr/lib/$multiarch/libblas.so.3")" != "$(readlink -f "$netlib_blas")" ]]; then
  netlib_dir=$(mktemp -d)
  trap 'rm -rf "$netlib_dir"' EXIT
  ln -s "$netlib_blas" "$netlib_dir/libblas.so.3"
  ln -s "$netlib_lapack" "$netlib_dir/liblapack.so.3"
  LD_LIBRARY_PATH="$netlib_dir" "$build_dir/bench/hpc_bench" \
    --benchmark_filter='BM_LinearSolve|BM_HertzP8LinearSolve|BM_TwoBarsLinearStep|BM_ExampleEndToEnd' \
    --benchmark_min_time=0.2 \
    --benchmark_repetitions=5 \
    --benchmark_enable_random_interleaving=true \
    --benchmark_report_aggregates_only=true \
    --benchmark_out_format=json \
    --benchmark_out="$reference" > /dev/null
fi

/usr/bin/python3 bench/report.py "$results" BENCHMARKS.md $([[ -f "$reference" ]] && echo "$reference")
echo "bench/run.sh: wrote BENCHMARKS.md (raw results: $results)"
