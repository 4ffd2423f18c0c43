// Semantics: 'Start' and 'START' are the same name (IEC identifiers are case-insensitive).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    Start : BOOL;
    START : BOOL;
END_VAR
    LD Start
    ST START
END_FUNCTION_BLOCK
"#);

fn main() {}
