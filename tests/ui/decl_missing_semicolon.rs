// Declarations: a variable declaration without its closing ';'.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL
    q : BOOL;
END_VAR
    LD a
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
