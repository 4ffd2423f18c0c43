// Parentheses: LD( is not allowed, deferred '(' only follows expression operators.
il_macros::il!(r#"
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
"#);

fn main() {}
