// Syntax: NOT with an operand (NOT complements the current result and takes none; use LDN).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
    q : BOOL;
END_VAR
    NOT a
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
