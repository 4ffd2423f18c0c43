// Declarations: TYPE is an IEC 61131-3 keyword and cannot name a variable.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    type : BOOL;
    q : BOOL;
END_VAR
    LD type
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
