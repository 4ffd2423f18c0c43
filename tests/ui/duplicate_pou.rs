// Semantics: two FUNCTION_BLOCKs with the same name.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
END_VAR
    LD a
    ST a
END_FUNCTION_BLOCK

FUNCTION_BLOCK Fb
VAR
    b : BOOL;
END_VAR
    LD b
    ST b
END_FUNCTION_BLOCK
"#);

fn main() {}
