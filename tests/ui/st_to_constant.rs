// Semantics: ST to a VAR CONSTANT.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR CONSTANT
    LIMIT_HI : INT := 100;
END_VAR
VAR
    n : INT;
END_VAR
    LD n
    ST LIMIT_HI
END_FUNCTION_BLOCK
"#);

fn main() {}
