// Current result (CR): its type and whether it is defined, along jumps and after CAL.
// Each case is one IL mistake in its own module, so that the stub items
// il! emits next to its compile_error!s cannot collide between cases.

// Current result: CALC of a timer with an INT in the CR (CALC needs a BOOL CR).
mod calc_with_int_cr { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
    t : TON;
END_VAR
    LD n
    CALC t
END_FUNCTION_BLOCK
"#); }

// Current result: the label 'check' is reached with an INT CR (jump) and a BOOL CR (fall-through); then the CR is used.
mod cr_type_disagrees_at_label { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    n : INT;
    q : BOOL;
END_VAR
    LD a
    JMPC skip
    LD n
    JMP check
skip:
    LD a
check:
    ST q
END_FUNCTION_BLOCK
"#); }

// Current result: the CR is undefined after CAL of an FB; here it is stored before any new LD.
mod cr_undefined_after_cal { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    q : BOOL;
    delay : TON;
END_VAR
    CAL delay(IN := start, PT := T#2s)
    ST q
END_FUNCTION_BLOCK
"#); }

// Current result: the body starts with ST, the CR has no value yet.
mod cr_used_at_start { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    q : BOOL;
END_VAR
    ST q
END_FUNCTION_BLOCK
"#); }

// Current result: JMPC right after CAL, the CR is undefined there.
mod jmpc_after_cal { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    q : BOOL;
    t : TON;
END_VAR
    CAL t(IN := start, PT := T#1s)
    JMPC done
    LD TRUE
    ST q
done:
END_FUNCTION_BLOCK
"#); }

// Current result: JMPC with an INT in the CR (JMPC needs a BOOL CR).
mod jmpc_with_int_cr { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    count : INT;
    q : BOOL;
END_VAR
    LD count
    JMPC done
    LD TRUE
    ST q
done:
END_FUNCTION_BLOCK
"#); }

fn main() {}
