// Literal: 16#FG, G is no hexadecimal digit.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    w : WORD;
END_VAR
    LD 16#FG
    ST w
END_FUNCTION_BLOCK
"#);

fn main() {}
