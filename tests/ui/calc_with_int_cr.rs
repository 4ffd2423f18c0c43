// Current result: CALC of a timer with an INT in the CR (CALC needs a BOOL CR).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
    t : TON;
END_VAR
    LD n
    CALC t
END_FUNCTION_BLOCK
"#);

fn main() {}
