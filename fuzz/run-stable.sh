#!/usr/bin/env bash
# Coverage-guided fuzzing of the front end on a *stable* toolchain: the same
# SanitizerCoverage flags cargo-fuzz passes, without -Zsanitizer (nightly only),
# so memory errors in unsafe code are not caught, but panics, stack overflows,
# hangs and unbounded memory are.
#
#   fuzz/run-stable.sh [seconds]      (default 60; seeds: ../shared/corpus)
set -euo pipefail
cd "$(dirname "$0")"
secs="${1:-60}"
target="$(rustc -vV | sed -n 's/^host: //p')"
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
 -Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
 -Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks"
# --target keeps RUSTFLAGS off build scripts.
cargo build --release --target "$target" --target-dir target/stable-cov
mkdir -p corpus/front_end artifacts/front_end
seeds=()
if [ -d ../../shared/corpus ]; then seeds+=(../../shared/corpus); fi
exec "target/stable-cov/$target/release/front_end" corpus/front_end "${seeds[@]}" \
  -max_total_time="$secs" -max_len=4096 -rss_limit_mb=2048 -timeout=10 \
  -artifact_prefix=artifacts/front_end/
