// Operands: a direct address %IX0.0 used in the body (check the message if it is not supported).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    q : BOOL;
END_VAR
    LD %IX0.0
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
