#!/usr/bin/env bash
# The size check of BENCHMARKS.md: adds a generated IL program of about
# LINES lines (default 2000, gen-big.sh) to the firmware, whose every
# variable must follow the interpreter's trace, and which must still link
# into 64 KiB of flash and 16 KiB of RAM (memory-budget.x) and run there
# (run-qemu.sh); then prints where the flash goes.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
lines="${1:-2000}"
# The example's own target directory: only the firmware is rebuilt, once
# for each variant (and by the next run-qemu.sh, without the program).
target_dir="${CARGO_TARGET_DIR:-$here/target}"
mkdir -p "$target_dir"
big="$target_dir/big.il"
bash "$here/gen-big.sh" "$lines" >"$big"
echo "== $(wc -l <"$big") lines of IL in $(grep -c '^FUNCTION_BLOCK' "$big") function blocks and PROGRAM Big"
# First every variable of Big traced and compared with the interpreter's
# (that build's visit code and float formatting need the chip's whole
# memory; its trace lines need a slower virtual clock), then the budget.
echo "== Big traced (whole memory)"
IL_EXTRA="$big" IL_EXTRA_PROGRAM=Big IL_EXTRA_TRACE=1 ICOUNT_SHIFT=3 bash "$here/run-qemu.sh"
echo "== Big within 64 KiB / 16 KiB"
IL_EXTRA="$big" IL_EXTRA_PROGRAM=Big bash "$here/run-qemu.sh"

elf="$target_dir/thumbv7m-none-eabi/release/il-cortex-m"
if command -v llvm-nm >/dev/null; then
    # Functions (and constants) by whose code they are; LTO inlines most of
    # the program and of il-std into main, which counts as the example's.
    echo "== flash by owner, symbols not inlined (llvm-nm)"
    # Identical functions folded into one address count once.
    llvm-nm -S -C --size-sort --radix=d "$elf" | awk 'NF >= 4 && $3 ~ /^[tTrR]$/ && $2 > 0 && !seen[$1]++ {
        if ($0 ~ /il_cortex_m(::|\.\.)plc/) k = "generated code (plc)"
        else if ($0 ~ /il_std/) k = "il-std"
        else if ($0 ~ /il_cortex_m/) k = "example (main, I/O)"
        else if ($0 ~ /compiler_builtins|__aeabi/) k = "compiler_builtins"
        else if ($0 ~ /cortex_m|__INTERRUPTS|__EXCEPTIONS|__RESET|Reset|Handler|HardFault/) k = "cortex-m crates, vector tables"
        else if ($0 ~ /core/) k = "core (fmt)"
        else k = "constants"
        sum[k] += $2 }
        END { for (k in sum) printf "  %6d bytes  %s\n", sum[k], k }' | sort -n -r
else
    echo "(llvm-nm not found: no breakdown)"
fi
