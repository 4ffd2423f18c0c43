// Calls: CAL of FB instances, FUNCTION calls, formal parameters, VAR_IN_OUT bindings, FB members.
// Each case is one IL mistake in its own module, so that the stub items
// il! emits next to its compile_error!s cannot collide between cases.

// Semantics: CAL of a BOOL variable (only FB instances can be called).
mod cal_non_fb { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
END_VAR
    CAL start
END_FUNCTION_BLOCK
"#); }

// Calls: a formal parameter PTT that the TON does not have (did you mean PT?).
mod cal_unknown_formal { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    t : TON;
END_VAR
    CAL t(IN := start, PTT := T#1s)
END_FUNCTION_BLOCK
"#); }

// Calls: a FUNCTION that calls itself (IEC 61131-3 forbids recursion).
mod function_recursion { il_macros::il!(r#"
FUNCTION FACT : DINT
VAR_INPUT
    n : DINT;
END_VAR
    LD n
    LE 1
    JMPCN again
    LD 1
    ST FACT
    RET
again:
    LD n
    SUB 1
    FACT
    MUL n
    ST FACT
END_FUNCTION
"#); }

// Calls: a user FUNCTION with two inputs called with three arguments (CR + 2).
mod function_wrong_arg_count { il_macros::il!(r#"
FUNCTION SCALE : INT
VAR_INPUT
    raw : INT;
    factor : INT;
END_VAR
    LD raw
    MUL factor
    ST SCALE
END_FUNCTION

FUNCTION_BLOCK Fb
VAR
    sensor : INT;
    value : INT;
END_VAR
    LD sensor
    SCALE 10, 20
    ST value
END_FUNCTION_BLOCK
"#); }

// Calls: LIMIT on an INT CR with a UINT upper bound (one type; neither widens into the other).
mod limit_wrong_arg_type { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
    hi : UINT;
    q : INT;
END_VAR
    LD n
    LIMIT 0, hi
    ST q
END_FUNCTION_BLOCK
"#); }

// VAR_IN_OUT bound to a literal.
mod in_out_literal { il_macros::il!(r#"
FUNCTION_BLOCK Scale
VAR_IN_OUT value : INT; END_VAR
    LD value
    MUL 2
    ST value
END_FUNCTION_BLOCK

PROGRAM Main
VAR s : Scale; END_VAR
    CAL s(value := 5)
END_PROGRAM
"#); }

// VAR_IN_OUT bound to a variable of another type (a reference needs the same type).
mod in_out_type_mismatch { il_macros::il!(r#"
FUNCTION Twice : BOOL
VAR_IN_OUT value : DINT; END_VAR
    LD value
    MUL 2
    ST value
    LD TRUE
    ST Twice
END_FUNCTION

PROGRAM Main
VAR x : INT; ok : BOOL; END_VAR
    Twice(value := x)
    ST ok
END_PROGRAM
"#); }

// VAR_IN_OUT left unbound in a CAL.
mod in_out_unbound { il_macros::il!(r#"
FUNCTION_BLOCK Scale
VAR_INPUT k : INT; END_VAR
VAR_IN_OUT value : INT; END_VAR
    LD value
    MUL k
    ST value
END_FUNCTION_BLOCK

PROGRAM Main
VAR s : Scale; x : INT; END_VAR
    CAL s(k := 2)
END_PROGRAM
"#); }

// Semantics: PT (a timer's input) used on a CTU counter c.
mod input_operator_wrong_fb { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    preset : TIME;
    c : CTU;
END_VAR
    LD preset
    PT c
END_FUNCTION_BLOCK
"#); }

// Semantics: LD ff.Q on an SR flip-flop (its output is Q1): expect a did-you-mean Q1.
mod unknown_fb_member { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    set : BOOL;
    q : BOOL;
    ff : SR;
END_VAR
    LD set
    S1 ff
    LD ff.Q
    ST q
END_FUNCTION_BLOCK
"#); }

// Semantics: 'dbg 1', a vendor built-in that is not an IEC function or operator.
mod unknown_function_vendor { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
END_VAR
    LD n
    dbg 1
END_FUNCTION_BLOCK
"#); }

fn main() {}
