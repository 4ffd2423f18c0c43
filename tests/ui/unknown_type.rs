// Semantics: an unknown type TONN (typo of the TON timer): expect a did-you-mean.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    delay : TONN;
END_VAR
    LD start
    IN delay
END_FUNCTION_BLOCK
"#);

fn main() {}
