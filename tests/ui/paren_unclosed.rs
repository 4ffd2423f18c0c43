// Parentheses: AND( opened and never closed with ).
il_macros::il!(r#"
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
"#);

fn main() {}
