// Calls: a formal parameter PTT that the TON does not have (did you mean PT?).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    t : TON;
END_VAR
    CAL t(IN := start, PTT := T#1s)
END_FUNCTION_BLOCK
"#);

fn main() {}
