// Declarations: an instance of a PROGRAM inside a FUNCTION_BLOCK (programs are not instantiable in POUs).
il_macros::il!(r#"
PROGRAM Main
VAR
    a : BOOL;
END_VAR
    LD a
    ST a
END_PROGRAM

FUNCTION_BLOCK Fb
VAR
    m : Main;
END_VAR
    CAL m
END_FUNCTION_BLOCK
"#);

fn main() {}
