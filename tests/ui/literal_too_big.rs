// Literal: an integer larger than any IEC integer type (LINT/ULINT).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : LINT;
END_VAR
    LD 99999999999999999999999
    ST n
END_FUNCTION_BLOCK
"#);

fn main() {}
