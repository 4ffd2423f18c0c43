// Types: GT makes the current result BOOL; storing it to an INT is a mismatch.
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
    m : INT;
END_VAR
    LD n
    GT 10
    ST m
END_FUNCTION_BLOCK
"#);

fn main() {}
