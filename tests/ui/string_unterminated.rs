// Literal: a STRING literal without its closing quote.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    msg : STRING;
END_VAR
    LD 'motor fault
    ST msg
END_FUNCTION_BLOCK
"#);

fn main() {}
