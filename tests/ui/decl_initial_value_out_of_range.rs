// Declarations: initial value 300 for a SINT (-128..127).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    small : SINT := 300;
    n : SINT;
END_VAR
    LD small
    ST n
END_FUNCTION_BLOCK
"#);

fn main() {}
