// Globals: storing to a VAR_EXTERNAL CONSTANT.
il_macros::il!(r#"
PROGRAM Main
VAR_EXTERNAL CONSTANT limit : INT; END_VAR
    LD 5
    ST limit
END_PROGRAM
"#);

fn main() {}
