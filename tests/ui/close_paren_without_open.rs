// Parentheses: a ')' with no matching OP(.
il_macros::il!(r#"
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
"#);

fn main() {}
