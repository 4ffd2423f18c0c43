#!/usr/bin/env bash
# Builds the Cortex-M example (release), runs it under QEMU (lm3s6965evb),
# and compares its trace with the reference interpreter's (`ilc run` of the
# same program, inputs, scan count and step, all read from scans.txt).
# Exits 0 only when the two traces are equal and the firmware's own check
# passed; 1 on a mismatch or a failed run; 2 when a tool is missing.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
target=thumbv7m-none-eabi

if ! command -v qemu-system-arm >/dev/null; then
    echo "run-qemu.sh: qemu-system-arm is not installed." >&2
    echo "  Debian/Ubuntu: sudo apt-get install --no-install-recommends qemu-system-arm" >&2
    echo "  Fedora: sudo dnf install qemu-system-arm; macOS: brew install qemu" >&2
    exit 2
fi
if command -v rustup >/dev/null && ! rustup target list --installed | grep -qx "$target"; then
    echo "run-qemu.sh: the Rust target $target is not installed." >&2
    echo "  rustup target add $target" >&2
    exit 2
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "== build (release, $target)"
(cd "$here" && cargo build --release --quiet)
elf="${CARGO_TARGET_DIR:-$here/target}/$target/release/il-cortex-m"

echo "== run under QEMU"
# -icount: virtual time counts instructions (1 instruction = 2^shift ns), so
# the run is deterministic and the SysTick measure of a scan is in
# instructions; sleep=off jumps over the idle time between scans. A scan
# and its trace lines must fit the period: ICOUNT_SHIFT=3 gives a long trace
# (size-check.sh's) eight times the instructions. The timeout ends a
# firmware that hangs instead of exiting through semihosting.
status=0
timeout 60 qemu-system-arm -cpu cortex-m3 -machine lm3s6965evb -nographic \
    -monitor none -serial none -semihosting-config enable=on,target=native \
    -icount "shift=${ICOUNT_SHIFT:-6},sleep=off" -kernel "$elf" >"$work/qemu.out" \
    2> >(grep -v "^Timer with period zero" >&2) || status=$?
grep '^#' "$work/qemu.out" || true
grep -v '^[#x]' "$work/qemu.out" >"$work/qemu.trace" || true
# IL_EXTRA_TRACE: the extra program's own trace, `x ` lines (src/visit.rs).
sed -n 's/^x //p' "$work/qemu.out" >"$work/extra.trace"
if [ "$status" -eq 124 ]; then
    echo "run-qemu.sh: QEMU did not finish within 60 s" >&2
    exit 1
fi

# The interpreter, with the names of the firmware's header line and the
# inputs of scans.txt (`SCAN ADDRESS=VALUE` becomes --set ADDRESS=VALUE@SCAN).
read -r first second watch <<<"$(head -n 1 "$work/qemu.trace")"
if [ "$first $second" != "cycle time" ] || [ -z "$watch" ]; then
    echo "run-qemu.sh: FAILED: QEMU printed no trace header (exit status $status)" >&2
    exit 1
fi
cycles="$(awk '$1 == "cycles" { print $2 }' "$here/scans.txt")"
step="$(awk '$1 == "step" { print $2 }' "$here/scans.txt")"
mapfile -t sets < <(awk '$1 ~ /^[0-9]+$/ { print "--set=" $2 "@" $1 }' "$here/scans.txt")
# ILC names an ilc binary to use (CI passes the one its tests built, which
# `cargo run -p il-cli` would rebuild with other features); else cargo runs it.
if [ -n "${ILC:-}" ]; then ilc=("$ILC"); else ilc=(cargo run --quiet -p il-cli --); fi
echo "== ilc run (the reference interpreter)"
(cd "$root" && "${ilc[@]}" run examples/cortex-m/plc/pump.il \
    --program Pump --cycles "$cycles" --step "$step" "${sets[@]}" \
    --watch "${watch// /,}") >"$work/ilc.out"
# ilc's table, in the firmware's format: single spaces, the time as a TIME literal.
awk '{ if (NR > 1) $2 = "T#" $2; $1 = $1; print }' "$work/ilc.out" >"$work/ilc.trace"

if ! diff -u --label "ilc run" --label "QEMU" "$work/ilc.trace" "$work/qemu.trace"; then
    echo "run-qemu.sh: FAILED: the trace under QEMU differs from the interpreter's (above)" >&2
    exit 1
fi
if [ -n "${IL_EXTRA_TRACE:-}" ]; then
    # The extra program reads no inputs: the same scans and step, no --set.
    read -r first second watch <<<"$(head -n 1 "$work/extra.trace")"
    if [ "$first $second" != "cycle time" ] || [ -z "$watch" ]; then
        echo "run-qemu.sh: FAILED: QEMU printed no trace of $IL_EXTRA_PROGRAM" >&2
        exit 1
    fi
    echo "== ilc run of $IL_EXTRA_PROGRAM ($(wc -w <<<"$watch") variables)"
    (cd "$root" && "${ilc[@]}" run "$IL_EXTRA" --program "$IL_EXTRA_PROGRAM" \
        --cycles "$cycles" --step "$step" --watch "${watch// /,}") >"$work/ilc-extra.out"
    awk '{ if (NR > 1) $2 = "T#" $2; $1 = $1; print }' "$work/ilc-extra.out" >"$work/ilc-extra.trace"
    if ! diff -u --label "ilc run" --label "QEMU" "$work/ilc-extra.trace" "$work/extra.trace" >"$work/extra.diff"; then
        # Lines of hundreds of values: the start of the diff is enough.
        head -c 4000 "$work/extra.diff"
        echo
        echo "run-qemu.sh: FAILED: $IL_EXTRA_PROGRAM's trace under QEMU differs from the interpreter's (above)" >&2
        exit 1
    fi
fi
if [ "$status" -ne 0 ]; then
    echo "run-qemu.sh: FAILED: the firmware's check failed (QEMU exit status $status)" >&2
    exit 1
fi
traced=""
[ -n "${IL_EXTRA_TRACE:-}" ] && traced=" (and $IL_EXTRA_PROGRAM's)"
echo "run-qemu.sh: ok: $(($(wc -l <"$work/qemu.trace") - 1)) scans under QEMU equal the interpreter's$traced, check passed"
