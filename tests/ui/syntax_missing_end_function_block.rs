// Syntax: the FUNCTION_BLOCK is never closed with END_FUNCTION_BLOCK.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
    y : INT;
END_VAR
    LD x
    ST y
"#);

fn main() {}
