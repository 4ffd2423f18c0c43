// Literal: 1e5, an IEC REAL literal needs a decimal point (1.0E5).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    r : REAL;
END_VAR
    LD 1e5
    ST r
END_FUNCTION_BLOCK
"#);

fn main() {}
