// Types: S (set) on an INT variable (S sets a BOOL).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    n : INT;
END_VAR
    LD a
    S n
END_FUNCTION_BLOCK
"#);

fn main() {}
