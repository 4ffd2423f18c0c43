// Declarations: a FUNCTION without ': type' for its result.
il_macros::il!(r#"
FUNCTION TWICE
VAR_INPUT
    a : INT;
END_VAR
    LD a
    MUL 2
    ST TWICE
END_FUNCTION
"#);

fn main() {}
