// Syntax: LD without an operand.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
END_VAR
    LD
    ST x
END_FUNCTION_BLOCK
"#);

fn main() {}
