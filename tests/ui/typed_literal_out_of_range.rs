// Literal: SINT#200, the value does not fit its own type.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : SINT;
END_VAR
    LD SINT#200
    ST n
END_FUNCTION_BLOCK
"#);

fn main() {}
