// Types: a WSTRING literal (double quotes) stored to a STRING.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    s : STRING;
END_VAR
    LD "hello"
    ST s
END_FUNCTION_BLOCK
"#);

fn main() {}
