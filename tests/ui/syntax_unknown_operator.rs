// Syntax: a garbled operator line (LDD is no IL operator).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
    y : INT;
END_VAR
    LDD x
    ST y
END_FUNCTION_BLOCK
"#);

fn main() {}
