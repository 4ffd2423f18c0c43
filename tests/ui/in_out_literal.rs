// VAR_IN_OUT bound to a literal.
il_macros::il!(r#"
FUNCTION_BLOCK Scale
VAR_IN_OUT value : INT; END_VAR
    LD value
    MUL 2
    ST value
END_FUNCTION_BLOCK

PROGRAM Main
VAR s : Scale; END_VAR
    CAL s(value := 5)
END_PROGRAM
"#);

fn main() {}
