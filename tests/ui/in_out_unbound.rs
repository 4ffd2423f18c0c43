// VAR_IN_OUT left unbound in a CAL.
il_macros::il!(r#"
FUNCTION_BLOCK Scale
VAR_INPUT k : INT; END_VAR
VAR_IN_OUT value : INT; END_VAR
    LD value
    MUL k
    ST value
END_FUNCTION_BLOCK

PROGRAM Main
VAR s : Scale; x : INT; END_VAR
    CAL s(k := 2)
END_PROGRAM
"#);

fn main() {}
