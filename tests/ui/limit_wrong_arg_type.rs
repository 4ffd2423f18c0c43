// Calls: LIMIT on an INT CR with a REAL upper bound (all LIMIT arguments have one type).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT;
    hi : REAL;
    q : INT;
END_VAR
    LD n
    LIMIT 0, hi
    ST q
END_FUNCTION_BLOCK
"#);

fn main() {}
