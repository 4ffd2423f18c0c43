// Syntax: a VAR block without END_VAR.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
    y : INT;
    LD x
    ST y
END_FUNCTION_BLOCK
"#);

fn main() {}
