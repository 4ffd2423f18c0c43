// Semantics: ST to a timer's output t.Q (outputs of an FB instance are read-only).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    t : TON;
END_VAR
    LD start
    ST t.Q
END_FUNCTION_BLOCK
"#);

fn main() {}
