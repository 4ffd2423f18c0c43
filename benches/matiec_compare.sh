#!/usr/bin/env bash
# Scan time of each benchmark program (benches/plc/*.il): our generated Rust
# against MATIEC's C (iec2c, gcc -O2) and the hand-written Rust twin, measured
# in the same run.
#
#   IEC2C=/path/to/iec2c MATIEC_LIB=/path/to/matiec/lib bash benches/matiec_compare.sh
#
# IEC2C is the `iec2c` binary of a MATIEC build (https://github.com/beremiz/matiec,
# built outside this repository as its README.build says); MATIEC_LIB is the
# `lib` directory of that checkout (it holds the IEC declarations iec2c reads
# and lib/C with the C headers). Optional: SCANS (scans per timed run, default
# 20000), ROUNDS (alternating timed rounds, default 11), CG_SCANS (scans for
# callgrind, default 200), PROGRAMS (default: all that iec2c accepts).
#
# Figures per program:
# - instructions per scan under `valgrind --tool=callgrind` (load-independent):
#   (Ir of 2*CG_SCANS scans - Ir of CG_SCANS scans) / CG_SCANS, so start-up
#   and set-up cancel out;
# - ns per scan: median of ROUNDS runs of SCANS scans, C and Rust alternating;
# - the outputs' checksum after SCANS scans, which must be equal on all sides
#   (benches/matiec/driver.c and il-bench's `scans` binary set the same inputs).
#
# What iec2c (commit 6bb2c33) refuses or mistranslates, and how the copy it
# gets is adapted (our programs are not changed):
# - a formal CAL list on one line, `CAL t(IN := go, PT := T#30ms)`: iec2c
#   wants an EOL after `(` -> one parameter per line;
# - a formal parameter named R or S (`CAL c(CU := e.Q, R := reset, ...)`):
#   R and S are IL operators to iec2c -> `LD reset  ST c.R ...  CAL c`;
# - a TIME literal in a formal CAL inside a FUNCTION_BLOCK: iec2c also prints
#   the literal at file level before the FB's init function (C that does not
#   compile) -> the same stores-then-CAL form;
# - instance names S1 and R1 (operators of SR/RS to iec2c) -> `s1x`;
# - a variable subscript in IL (`LD samples[i]`): iec2c prints an empty index,
#   `.table[() - (0)]` (generate_c_il.cc prints no symbolic variable in its
#   complextype_suffix mode); the script fills the POU's one subscript
#   variable into the C (`__GET_VAR(data__->I,)`), and stops if a program
#   uses more than one;
# - ARRAY OF a function block (`blocks_loop.il`): refused ("invalid item data
#   type in array specification"); skipped.
set -euo pipefail

: "${IEC2C:?set IEC2C to the iec2c binary}"
: "${MATIEC_LIB:?set MATIEC_LIB to matiec/lib}"
SCANS=${SCANS:-20000}
ROUNDS=${ROUNDS:-11}
CG_SCANS=${CG_SCANS:-200}
PROGRAMS=${PROGRAMS:-"interlock arith_loop array_proc blocks mixed"}
root=$(cd "$(dirname "$0")/.." && pwd)
. "$root/benches/matiec_common.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cargo build --release -q -p il-bench --bin scans --manifest-path "$root/Cargo.toml"
scans="$root/target/release/scans"

adapt() {
    perl -pe '
        if (/^(\s*(?:\w+:\s*)?)CAL(\s+)([^(\s]+)\((.*:=.*)\)\s*$/) {
            my ($pre, $s, $fb, $args) = ($1, $2, $3, $4);
            my $i = "        ";
            my @p = map { [split /\s*:=\s*/, $_, 2] } split /\s*,\s*/, $args;
            if (grep { $_->[0] =~ /^(R|S)$/ || $_->[1] =~ /^T#/i } @p) {
                $_ = $pre . join($i, map { "LD   $_->[1]\n${i}ST   $fb.$_->[0]\n" } @p) . "${i}CAL$s$fb\n";
            } else {
                $_ = "${pre}CAL$s$fb(\n" . join(",\n", map { "$i    $_->[0] := $_->[1]" } @p) . "\n$i)\n";
            }
        }
        s/\b(s1|r1)\b(?=[.(\s])/${1}x/gi unless /^\s*\(\*/;
    '
}

# Instructions per scan of the command "$@" <n>.
ir_per_scan() {
    local a b
    a=$(valgrind --tool=callgrind --callgrind-out-file="$work/cg" "$@" "$CG_SCANS" 2>/dev/null >/dev/null &&
        awk '/^(summary|totals):/ {print $2; exit}' "$work/cg")
    b=$(valgrind --tool=callgrind --callgrind-out-file="$work/cg" "$@" $((2 * CG_SCANS)) 2>/dev/null >/dev/null &&
        awk '/^(summary|totals):/ {print $2; exit}' "$work/cg")
    echo $(((b - a) / CG_SCANS))
}


build_c() {
    local name=$1 il="$root/benches/plc/$1.il" dir="$work/$1" prog
    mkdir -p "$dir"
    prog=$(awk '/^PROGRAM / {print $2}' "$il" | tail -1)
    {
        adapt <"$il"
        matiec_config "$prog"
    } >"$dir/$name.st"
    "$IEC2C" -I "$MATIEC_LIB" -T "$dir" "$dir/$name.st" >/dev/null
    if grep -q '\.table\[() - ' "$dir/POUS.c"; then
        local subs
        subs=$(grep -oE '\[[A-Za-z_][A-Za-z0-9_]*\]' "$il" | sort -u)
        if [ "$(echo "$subs" | wc -l)" != 1 ]; then
            echo "$name: more than one subscript variable ($subs), cannot repair iec2c's empty index" >&2
            return 1
        fi
        local var
        var=$(echo "$subs" | tr -d '[]' | tr '[:lower:]' '[:upper:]')
        sed -i "s/\.table\[() - /.table[(__GET_VAR(data__->$var,)) - /g" "$dir/POUS.c"
    fi
    gcc -O2 -w -DPROG_"$name" -I "$MATIEC_LIB/C" -I "$dir" "$root/benches/matiec/driver.c" \
        "$dir/config.c" "$dir/resource1.c" -o "$dir/run"
}

printf '%s, load average %s\n' "$(date -u '+%F %H:%M UTC')" "$(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-11s %9s %9s %9s %7s %7s %10s %10s %10s %7s %7s  %s\n' program "C Ir" "gen Ir" "hand Ir" \
    gen/C gen/hand "C ns" "gen ns" "hand ns" gen/C gen/hand checksums
for name in $PROGRAMS; do
    build_c "$name"
    ic=$(ir_per_scan "$work/$name/run")
    ig=$(ir_per_scan "$scans" "$name" gen)
    ih=$(ir_per_scan "$scans" "$name" hand)
    : >"$work/tc"
    : >"$work/tg"
    : >"$work/th"
    for ((r = 0; r < ROUNDS; r++)); do
        read -r t sc <<<"$("$work/$name/run" "$SCANS")"
        echo "$t" >>"$work/tc"
        read -r t sg <<<"$("$scans" "$name" gen "$SCANS")"
        echo "$t" >>"$work/tg"
        read -r t sh <<<"$("$scans" "$name" hand "$SCANS")"
        echo "$t" >>"$work/th"
    done
    tc=$(median <"$work/tc")
    tg=$(median <"$work/tg")
    th=$(median <"$work/th")
    same=$([ "$sc" = "$sg" ] && [ "$sg" = "$sh" ] && echo "equal" || echo "DIFFER: $sc $sg $sh")
    [ "$same" = equal ] || differ=1
    awk -v n="$name" -v ic="$ic" -v ig="$ig" -v ih="$ih" -v tc="$tc" -v tg="$tg" -v th="$th" -v s="$same" \
        'BEGIN {printf "%-11s %9d %9d %9d %7.3f %7.3f %10.1f %10.1f %10.1f %7.3f %7.3f  %s\n",
            n, ic, ig, ih, ig / ic, ig / ih, tc, tg, th, tg / tc, tg / th, s}'
done
printf 'load average at the end %s\n' "$(cut -d' ' -f1-3 /proc/loadavg)"
# Outputs that differ mean one side computes something else: not a figure.
[ -z "${differ:-}" ] || { echo "checksums differ" >&2; exit 1; }
