// Types: a TIME literal stored to an INT.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
END_VAR
    LD T#5s
    ST n
END_FUNCTION_BLOCK
"#);

fn main() {}
