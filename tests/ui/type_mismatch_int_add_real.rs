// Types: LD of an INT, then ADD of a REAL (no implicit conversion in IEC 61131-3).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    count : INT;
    gain : REAL;
    total : INT;
END_VAR
    LD count
    ADD gain
    ST total
END_FUNCTION_BLOCK
"#);

fn main() {}
