// Declarations: a user FUNCTION_BLOCK named TON, the name of a standard timer.
il_macros::il!(r#"
FUNCTION_BLOCK TON
VAR_INPUT
    IN : BOOL;
END_VAR
VAR_OUTPUT
    Q : BOOL;
END_VAR
    LD IN
    ST Q
END_FUNCTION_BLOCK
"#);

fn main() {}
