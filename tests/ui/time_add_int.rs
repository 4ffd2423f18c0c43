// Types: ADD of an INT to a TIME (TIME arithmetic is TIME + TIME; write T#5ms).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    t : TIME;
END_VAR
    LD t
    ADD 5
    ST t
END_FUNCTION_BLOCK
"#);

fn main() {}
