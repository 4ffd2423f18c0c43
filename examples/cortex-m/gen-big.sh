#!/usr/bin/env bash
# Writes an IL program of about LINES lines (default 2000) to stdout for
# size-check.sh: N function blocks of a typical station (scaling a raw
# reading as REAL, a TON, an R_TRIG, a CTU, INT and DINT arithmetic, a jump),
# each with constants of its own so that no two compile to the same code,
# and a PROGRAM Big that calls every one of them.
set -euo pipefail
lines="${1:-2000}"
# 42 lines a block, one more to declare it and one to call it.
n=$(( (lines - 14) / 44 ))
for ((i = 1; i <= n; i++)); do
    cat <<IL
FUNCTION_BLOCK Station$i
VAR_INPUT
    enable : BOOL;
    raw    : INT;
END_VAR
VAR_OUTPUT
    out    : BOOL;
    scaled : REAL;
    count  : INT;
END_VAR
VAR
    t   : TON;
    e   : R_TRIG;
    c   : CTU;
    acc : DINT;
END_VAR
    LD   raw
    INT_TO_REAL
    MUL  0.$((i % 9 + 1))5
    ADD  $i.25
    ST   scaled
    LD   raw
    GT   $((100 + i))
    AND  enable
    ST   t.IN
    CAL  t(PT := T#$((10 * i))ms)
    LD   t.Q
    CLK  e
    CAL  c(CU := e.Q, R := FALSE, PV := $((i % 5 + 2)))
    LD   c.CV
    ST   count
    LD   c.Q
    OR   t.Q
    ST   out
    JMPCN done
    LD   acc
    ADD  $((i * 7))
    MOD  $((1000 + i))
    ST   acc
done:
END_FUNCTION_BLOCK

IL
done
echo "PROGRAM Big"
echo "VAR"
for ((i = 1; i <= n; i++)); do echo "    s$i : Station$i;"; done
cat <<IL
    n    : INT;
    run  : BOOL;
END_VAR
    LD   n
    ADD  37
    MOD  1000
    ST   n
    GT   500
    ST   run
IL
for ((i = 1; i <= n; i++)); do echo "    CAL  s$i(enable := run, raw := n)"; done
echo "END_PROGRAM"
