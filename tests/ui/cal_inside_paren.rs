// Parentheses: CAL of a timer inside a deferred AND( ... ).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    b : BOOL;
    q : BOOL;
    t : TON;
END_VAR
    LD a
    AND(
        LD b
        CAL t
    )
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
