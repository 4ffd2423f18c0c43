// Literal: LD 300 then ST to a SINT (range -128..127).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    small : SINT;
END_VAR
    LD 300
    ST small
END_FUNCTION_BLOCK
"#);

fn main() {}
