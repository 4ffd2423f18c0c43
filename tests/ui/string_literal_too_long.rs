// Literal: a 14-character string stored to a STRING[5].
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    s : STRING[5];
END_VAR
    LD 'motor overload'
    ST s
END_FUNCTION_BLOCK
"#);

fn main() {}
