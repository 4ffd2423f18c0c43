// Parentheses: deferred operators OP( ... ) and what may not appear inside them.
// Each case is one IL mistake in its own module, so that the stub items
// il! emits next to its compile_error!s cannot collide between cases.

// Parentheses: CAL of a timer inside a deferred AND( ... ).
mod cal_inside_paren { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    b : BOOL;
    q : BOOL;
    t : TON;
END_VAR
    LD a
    AND(
        LD b
        CAL t
    )
    ST q
END_FUNCTION_BLOCK
"#); }

// Parentheses: a ')' with no matching OP(.
mod close_paren_without_open { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    b : BOOL;
    q : BOOL;
END_VAR
    LD a
    AND b
    )
    ST q
END_FUNCTION_BLOCK
"#); }

// Parentheses: a JMP inside a deferred AND( ... ).
mod paren_jmp_inside { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    b : BOOL;
    c : BOOL;
    q : BOOL;
END_VAR
    LD a
    AND(
        LD b
        JMP done
        OR c
    )
done:
    ST q
END_FUNCTION_BLOCK
"#); }

// Parentheses: a label inside a deferred AND( ... ).
mod paren_label_inside { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    b : BOOL;
    c : BOOL;
    q : BOOL;
END_VAR
    LD a
    AND(
inner:  LD b
        OR c
    )
    ST q
END_FUNCTION_BLOCK
"#); }

// Parentheses: LD( is not allowed, deferred '(' only follows expression operators.
mod paren_on_ld { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    b : BOOL;
    q : BOOL;
END_VAR
    LD(
        LD a
        AND b
    )
    ST q
END_FUNCTION_BLOCK
"#); }

// Parentheses: AND( opened and never closed with ).
mod paren_unclosed { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    b : BOOL;
    c : BOOL;
    q : BOOL;
END_VAR
    LD a
    AND(
        LD b
        OR c
    ST q
END_FUNCTION_BLOCK
"#); }

// Parentheses: RET inside a deferred OR( ... ).
mod ret_inside_paren { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    b : BOOL;
    q : BOOL;
END_VAR
    LD a
    OR(
        LD b
        RET
    )
    ST q
END_FUNCTION_BLOCK
"#); }

fn main() {}
