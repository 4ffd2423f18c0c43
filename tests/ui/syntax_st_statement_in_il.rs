// Syntax: a Structured Text assignment 'x := 1;' in an IL body.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    x : INT;
END_VAR
    x := 1;
END_FUNCTION_BLOCK
"#);

fn main() {}
