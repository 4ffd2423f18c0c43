// Types: MOD on REAL values (MOD is for integers only).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : REAL;
    b : REAL;
    c : REAL;
END_VAR
    LD a
    MOD b
    ST c
END_FUNCTION_BLOCK
"#);

fn main() {}
