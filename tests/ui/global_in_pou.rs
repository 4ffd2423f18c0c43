// Globals: VAR_GLOBAL inside a FUNCTION_BLOCK.
il_macros::il!(r#"
FUNCTION_BLOCK Pump
VAR_GLOBAL pressure : REAL; END_VAR
    LD pressure
    ST pressure
END_FUNCTION_BLOCK
"#);

fn main() {}
