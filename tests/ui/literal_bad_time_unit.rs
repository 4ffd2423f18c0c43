// Literal: T#5x, 'x' is no duration unit (d h m s ms).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    t : TIME;
END_VAR
    LD T#5x
    ST t
END_FUNCTION_BLOCK
"#);

fn main() {}
