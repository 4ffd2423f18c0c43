// Semantics: an unknown variable (a typo of 'speed'): expect a did-you-mean.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    speed : INT;
    limit : INT;
END_VAR
    LD spede
    ST limit
END_FUNCTION_BLOCK
"#);

fn main() {}
