// Current result: the body starts with ST, the CR has no value yet.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    q : BOOL;
END_VAR
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
