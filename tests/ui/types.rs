// Types: operators and stores on values of the wrong type.
// Each case is one IL mistake in its own module, so that the stub items
// il! emits next to its compile_error!s cannot collide between cases.

// Types: AND on INT values (AND is for BOOL and bit strings BYTE/WORD/DWORD/LWORD).
mod and_on_int { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : INT;
    b : INT;
    c : INT;
END_VAR
    LD a
    AND b
    ST c
END_FUNCTION_BLOCK
"#); }

// Types: GT makes the current result BOOL; storing it to an INT is a mismatch.
mod compare_result_to_int { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
    m : INT;
END_VAR
    LD n
    GT 10
    ST m
END_FUNCTION_BLOCK
"#); }

// Types: IN of a TON set from an INT current result (IN is BOOL).
mod fb_input_wrong_type { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
    t : TON;
END_VAR
    LD n
    IN t
END_FUNCTION_BLOCK
"#); }

// Types: LD of a whole timer instance (only its outputs, e.g. t.Q, can be loaded).
mod ld_fb_instance { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    t : TON;
    q : BOOL;
END_VAR
    LD t
    ST q
END_FUNCTION_BLOCK
"#); }

// Types: MOD on REAL values (MOD is for integers only).
mod mod_on_real { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : REAL;
    b : REAL;
    c : REAL;
END_VAR
    LD a
    MOD b
    ST c
END_FUNCTION_BLOCK
"#); }

// Types: S (set) on an INT variable (S sets a BOOL).
mod set_on_int { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    n : INT;
END_VAR
    LD a
    S n
END_FUNCTION_BLOCK
"#); }

// Types: ADD of an INT to a TIME (TIME arithmetic is TIME + TIME; write T#5ms).
mod time_add_int { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    t : TIME;
END_VAR
    LD t
    ADD 5
    ST t
END_FUNCTION_BLOCK
"#); }

// Types: a TIME literal stored to an INT.
mod time_literal_to_int { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
END_VAR
    LD T#5s
    ST n
END_FUNCTION_BLOCK
"#); }

// Types: LD of a DINT, then ADD of a REAL (DINT → REAL loses precision, so
// it is no implicit conversion; INT → REAL would be).
mod type_mismatch_dint_add_real { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    count : DINT;
    gain : REAL;
    total : DINT;
END_VAR
    LD count
    ADD gain
    ST total
END_FUNCTION_BLOCK
"#); }

// Types: a WSTRING literal (double quotes) stored to a STRING.
mod wstring_to_string { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    s : STRING;
END_VAR
    LD "hello"
    ST s
END_FUNCTION_BLOCK
"#); }

fn main() {}
