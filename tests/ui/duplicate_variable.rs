// Semantics: the same variable declared twice (once as input, once local).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR_INPUT
    speed : INT;
END_VAR
VAR
    speed : INT;
    limit : INT;
END_VAR
    LD speed
    ST limit
END_FUNCTION_BLOCK
"#);

fn main() {}
