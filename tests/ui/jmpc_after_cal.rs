// Current result: JMPC right after CAL, the CR is undefined there.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    q : BOOL;
    t : TON;
END_VAR
    CAL t(IN := start, PT := T#1s)
    JMPC done
    LD TRUE
    ST q
done:
END_FUNCTION_BLOCK
"#);

fn main() {}
