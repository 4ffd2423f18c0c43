#!/usr/bin/env bash
# Release build of the 10k-line program's output against gcc -O2 on MATIEC's
# C for the same program (issue 14's build-time row), measured in one run:
#
#   IEC2C=/path/to/iec2c MATIEC_LIB=/path/to/matiec/lib bash benches/matiec_build.sh
#
# (IEC2C and MATIEC_LIB as for benches/matiec_compare.sh.) Optional: LINES
# (default 10000), ROUNDS (alternating rounds, default 5).
#
# The program is `gen_il LINES 1 --matiec` (il_bench::generator::matiec_program:
# 25 FUNCTION_BLOCKs of ~400 lines with labels and jumps, in the forms iec2c
# translates). Each round, alternating:
# - gcc: `gcc -O2 -c` of iec2c's config.c and resource1.c (which #includes
#   POUS.c), the whole C compile of the program;
# - rustc: `cargo build --release` of a crate whose lib.rs `include!`s
#   `ilc emit`'s file, after `touch src/lib.rs` (il-std is built once before
#   the rounds, so the time is this crate's rustc alone).
# Prints each side's median wall and user+sys CPU seconds (GNU time, which
# counts the compiler processes cargo and gcc wait for) and their ratio.
set -euo pipefail

: "${IEC2C:?set IEC2C to the iec2c binary}"
: "${MATIEC_LIB:?set MATIEC_LIB to matiec/lib}"
LINES=${LINES:-10000}
ROUNDS=${ROUNDS:-5}
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/benches/matiec_common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cargo build --release -q -p il-bench --bin gen_il --manifest-path "$root/Cargo.toml"
cargo build --release -q -p il-cli --manifest-path "$root/Cargo.toml"
"$root/target/release/gen_il" "$LINES" 1 --matiec >"$work/prog.il"

# MATIEC: iec2c wants a CONFIGURATION to write config.c and resource1.c.
mkdir -p "$work/c"
{
    cat "$work/prog.il"
    matiec_config Big
} >"$work/c/prog.st"
s=$(date +%s.%N)
"$IEC2C" -I "$MATIEC_LIB" -T "$work/c" "$work/c/prog.st" >/dev/null
iec2c_s=$(echo "$(date +%s.%N) - $s" | bc)

# Ours: the crate around `ilc emit`'s file.
r="$work/rust"
mkdir -p "$r/src"
"$root/target/release/ilc" emit "$work/prog.il" -o "$r/src" >/dev/null
cat >"$r/Cargo.toml" <<EOT
[package]
name = "matiec_build"
version = "0.0.0"
edition = "2024"
publish = false
[workspace]
[dependencies]
il-std = { path = "$root/il-std" }
EOT
cp "$root/Cargo.lock" "$r/Cargo.lock"
echo 'include!("prog.rs");' >"$r/src/lib.rs"
(cd "$r" && cargo build --release -q --offline)

# wall and user+sys of "$@", one line.
timed() {
    /usr/bin/time -f '%e %U %S' -o "$work/t" "$@" >/dev/null 2>&1
    awk '{printf "%s %.2f\n", $1, $2 + $3}' "$work/t"
}

printf '%s, load average %s\n' "$(date -u '+%F %H:%M UTC')" "$(cut -d' ' -f1-3 /proc/loadavg)"
printf 'program: %s lines of IL; iec2c %.1f s -> %s KB of C; ilc emit -> %s KB of Rust\n' \
    "$(wc -l <"$work/prog.il")" "$iec2c_s" \
    "$(($(cat "$work/c/POUS.c" "$work/c/POUS.h" "$work/c/config.c" "$work/c/resource1.c" | wc -c) / 1024))" \
    "$(($(wc -c <"$r/src/prog.rs") / 1024))"
: >"$work/gw"; : >"$work/gc"; : >"$work/rw"; : >"$work/rc"; : >"$work/ratio"
for ((i = 0; i < ROUNDS; i++)); do
    read -r gw gc <<<"$(cd "$work/c" && timed gcc -O2 -w -c -I "$MATIEC_LIB/C" -I . config.c resource1.c)"
    touch "$r/src/lib.rs"
    read -r rw rc <<<"$(cd "$r" && timed cargo build --release -q --offline)"
    echo "$gw" >>"$work/gw"; echo "$gc" >>"$work/gc"
    echo "$rw" >>"$work/rw"; echo "$rc" >>"$work/rc"
    awk -v a="$rc" -v b="$gc" 'BEGIN {print a / b}' >>"$work/ratio"
    printf 'round %d: gcc %5.2f s wall %5.2f s cpu   rustc %5.2f s wall %5.2f s cpu   (load %s)\n' \
        "$((i + 1))" "$gw" "$gc" "$rw" "$rc" "$(cut -d' ' -f1 /proc/loadavg)"
done
printf 'medians: gcc %.2f s wall %.2f s cpu; rustc %.2f s wall %.2f s cpu; rustc/gcc cpu per round, median %.2f\n' \
    "$(median <"$work/gw")" "$(median <"$work/gc")" "$(median <"$work/rw")" "$(median <"$work/rc")" \
    "$(median <"$work/ratio")"
printf 'load average at the end %s\n' "$(cut -d' ' -f1-3 /proc/loadavg)"
