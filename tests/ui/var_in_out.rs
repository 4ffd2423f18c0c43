// Declarations: a VAR_IN_OUT block (check the message if it is not supported).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR_IN_OUT
    n : INT;
END_VAR
    LD n
    ADD 1
    ST n
END_FUNCTION_BLOCK
"#);

fn main() {}
