// Declarations: initial value TRUE for an INT.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT := TRUE;
    m : INT;
END_VAR
    LD n
    ST m
END_FUNCTION_BLOCK
"#);

fn main() {}
