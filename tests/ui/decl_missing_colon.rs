// Declarations: 'a BOOL;' without the ':' between name and type.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a BOOL;
    q : BOOL;
END_VAR
    LD a
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
