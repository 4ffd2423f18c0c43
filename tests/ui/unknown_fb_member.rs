// Semantics: LD ff.Q on an SR flip-flop (its output is Q1): expect a did-you-mean Q1.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    set : BOOL;
    q : BOOL;
    ff : SR;
END_VAR
    LD set
    S1 ff
    LD ff.Q
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
