// Calls: a user FUNCTION with two inputs called with three arguments (CR + 2).
il_macros::il!(r#"
FUNCTION SCALE : INT
VAR_INPUT
    raw : INT;
    factor : INT;
END_VAR
    LD raw
    MUL factor
    ST SCALE
END_FUNCTION

FUNCTION_BLOCK Fb
VAR
    sensor : INT;
    value : INT;
END_VAR
    LD sensor
    SCALE 10, 20
    ST value
END_FUNCTION_BLOCK
"#);

fn main() {}
