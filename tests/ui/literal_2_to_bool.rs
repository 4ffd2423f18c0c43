// Literal: LD 2 then ST to a BOOL (only 0 and 1 fit a BOOL).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    flag : BOOL;
END_VAR
    LD 2
    ST flag
END_FUNCTION_BLOCK
"#);

fn main() {}
