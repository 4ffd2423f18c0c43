// Declarations: ON is an IEC 61131-3 keyword (RESOURCE ... ON) and cannot name a variable.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    on : BOOL;
    q : BOOL;
END_VAR
    LD q
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
