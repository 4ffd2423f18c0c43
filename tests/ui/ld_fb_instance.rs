// Types: LD of a whole timer instance (only its outputs, e.g. t.Q, can be loaded).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    t : TON;
    q : BOOL;
END_VAR
    LD t
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
