// VAR_IN_OUT bound to a variable of another type (a reference needs the same type).
il_macros::il!(r#"
FUNCTION Twice : BOOL
VAR_IN_OUT value : DINT; END_VAR
    LD value
    MUL 2
    ST value
    LD TRUE
    ST Twice
END_FUNCTION

PROGRAM Main
VAR x : INT; ok : BOOL; END_VAR
    Twice(value := x)
    ST ok
END_PROGRAM
"#);

fn main() {}
