// Semantics: JMP to a label that does not exist.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    q : BOOL;
END_VAR
    LD a
    JMPC finish
    ST q
done:
END_FUNCTION_BLOCK
"#);

fn main() {}
