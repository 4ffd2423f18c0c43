// Parentheses: RET inside a deferred OR( ... ).
il_macros::il!(r#"
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
"#);

fn main() {}
