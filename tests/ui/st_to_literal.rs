// Syntax: ST into a literal (ST needs a variable).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
END_VAR
    LD n
    ST 5
END_FUNCTION_BLOCK
"#);

fn main() {}
