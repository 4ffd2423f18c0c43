// Semantics: a FUNCTION declaring a TON instance (a FUNCTION has no memory between calls).
il_macros::il!(r#"
FUNCTION DELAYED : BOOL
VAR_INPUT
    start : BOOL;
END_VAR
VAR
    t : TON;
END_VAR
    LD start
    ST t.IN
    CAL t(PT := T#1s)
    LD t.Q
    ST DELAYED
END_FUNCTION
"#);

fn main() {}
