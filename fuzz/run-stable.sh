#!/usr/bin/env bash
# Coverage-guided fuzzing on a *stable* toolchain: the same SanitizerCoverage
# flags cargo-fuzz passes, without -Zsanitizer (nightly only), so memory
# errors in unsafe code are not caught, but panics, broken assertions,
# arithmetic overflow (overflow checks are on), stack overflows, hangs and
# unbounded memory are.
#
#   fuzz/run-stable.sh [TARGET] [LIMIT] [libFuzzer options...]
#
# TARGET: front_end (default), check or pipeline. LIMIT: seconds (default 60),
# or `-runs=N` for exactly N executions. libFuzzer mutates inputs, seeded with
# the checked-in regressions (fuzz/regressions), tests/plc and
# ../shared/corpus; new inputs go to fuzz/corpus/TARGET, crashes to
# fuzz/artifacts/TARGET. Replay one input: target/stable-cov/*/release/TARGET FILE
set -euo pipefail
cd "$(dirname "$0")"
name="${1:-front_end}"
limit="${2:-60}"
shift $(($# > 2 ? 2 : $#))
case "$name" in front_end|check|pipeline) ;; *) echo "unknown target $name" >&2; exit 2;; esac
case "$limit" in -runs=*) limit_opt="$limit";; *) limit_opt="-max_total_time=$limit";; esac
target="$(rustc -vV | sed -n 's/^host: //p')"
export RUSTFLAGS="-Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
 -Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
 -Cllvm-args=-sanitizer-coverage-trace-compares --cfg fuzzing -Cdebug-assertions -Coverflow-checks"
# Same dependency versions as the workspace.
[ -f Cargo.lock ] || cp ../Cargo.lock Cargo.lock
# --target keeps RUSTFLAGS off build scripts.
cargo build --release --target "$target" --target-dir target/stable-cov --bin "$name"
mkdir -p "corpus/$name" "artifacts/$name"
seeds=(regressions ../tests/plc ../tests/plc-hostile)
if [ -d ../../shared/corpus ]; then seeds+=(../../shared/corpus); fi
exec "target/stable-cov/$target/release/$name" "corpus/$name" "${seeds[@]}" \
  "$limit_opt" -max_len=4096 -rss_limit_mb=2048 -timeout=10 -print_final_stats=1 \
  "-artifact_prefix=artifacts/$name/" "$@"
