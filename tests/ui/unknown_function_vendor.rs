// Semantics: 'dbg 1', a vendor built-in that is not an IEC function or operator.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
END_VAR
    LD n
    dbg 1
END_FUNCTION_BLOCK
"#);

fn main() {}
