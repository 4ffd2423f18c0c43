// Operands: storing to a direct input address (%IX): inputs are written by the host.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    q : BOOL;
END_VAR
    LD q
    ST %IX0.0
END_FUNCTION_BLOCK
"#);

fn main() {}
