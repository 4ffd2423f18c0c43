// Current result: the CR is undefined after CAL of an FB; here it is stored before any new LD.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    q : BOOL;
    delay : TON;
END_VAR
    CAL delay(IN := start, PT := T#2s)
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
