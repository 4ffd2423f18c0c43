// Semantics: CAL of a BOOL variable (only FB instances can be called).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
END_VAR
    CAL start
END_FUNCTION_BLOCK
"#);

fn main() {}
