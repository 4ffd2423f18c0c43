// Current result: the label 'check' is reached with an INT CR (jump) and a BOOL CR (fall-through); then the CR is used.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    n : INT;
    q : BOOL;
END_VAR
    LD a
    JMPC skip
    LD n
    JMP check
skip:
    LD a
check:
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
