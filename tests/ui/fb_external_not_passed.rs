// Globals: a block that uses a global inside a POU that does not declare it.
il_macros::il!(r#"
FUNCTION_BLOCK Counter
VAR_EXTERNAL total : DINT; END_VAR
    LD total
    ADD 1
    ST total
END_FUNCTION_BLOCK

PROGRAM Main
VAR c : Counter; END_VAR
    CAL c
END_PROGRAM
"#);

fn main() {}
