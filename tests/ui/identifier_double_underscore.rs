// Declarations: '__ctx', IEC identifiers may not contain two underscores in a row.
il_macros::il!(r#"
FUNCTION TWICE : INT
VAR_INPUT
    __ctx : INT;
END_VAR
    LD __ctx
    MUL 2
    ST TWICE
END_FUNCTION
"#);

fn main() {}
