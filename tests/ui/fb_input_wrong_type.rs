// Types: IN of a TON set from an INT current result (IN is BOOL).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
    t : TON;
END_VAR
    LD n
    IN t
END_FUNCTION_BLOCK
"#);

fn main() {}
