// Types: AND on INT values (AND is for BOOL and bit strings BYTE/WORD/DWORD/LWORD).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : INT;
    b : INT;
    c : INT;
END_VAR
    LD a
    AND b
    ST c
END_FUNCTION_BLOCK
"#);

fn main() {}
