// Names, labels and stores: unknown variables and labels, duplicate labels, read-only targets, direct addresses.
// Each case is one IL mistake in its own module, so that the stub items
// il! emits next to its compile_error!s cannot collide between cases.

// Semantics: JMP to a label that does not exist.
mod unknown_label { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    q : BOOL;
END_VAR
    LD a
    JMPC finish
    ST q
done:
END_FUNCTION_BLOCK
"#); }

// Semantics: the same label defined twice.
mod duplicate_label { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    q : BOOL;
END_VAR
    LD a
    JMPC done
    ST q
done:
    LD FALSE
done:
    ST q
END_FUNCTION_BLOCK
"#); }

// Semantics: an unknown variable (a typo of 'speed'): expect a did-you-mean.
mod unknown_variable { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    speed : INT;
    limit : INT;
END_VAR
    LD spede
    ST limit
END_FUNCTION_BLOCK
"#); }

// Semantics: ST to a VAR CONSTANT.
mod st_to_constant { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR CONSTANT
    LIMIT_HI : INT := 100;
END_VAR
VAR
    n : INT;
END_VAR
    LD n
    ST LIMIT_HI
END_FUNCTION_BLOCK
"#); }

// Semantics: ST to a timer's output t.Q (outputs of an FB instance are read-only).
mod st_to_fb_output { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    t : TON;
END_VAR
    LD start
    ST t.Q
END_FUNCTION_BLOCK
"#); }

// Operands: storing to a direct input address (%IX): inputs are written by the host.
mod direct_address_operand { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    q : BOOL;
END_VAR
    LD q
    ST %IX0.0
END_FUNCTION_BLOCK
"#); }

fn main() {}
