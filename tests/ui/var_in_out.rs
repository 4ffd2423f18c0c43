// Declarations: VAR_IN_OUT of a PROGRAM is not supported (IL0121): share the
// variable through VAR_GLOBAL / VAR_EXTERNAL instead.
il_macros::il!(r#"
PROGRAM Main
VAR_IN_OUT
    n : INT;
END_VAR
    LD n
    ADD 1
    ST n
END_PROGRAM
"#);

fn main() {}
