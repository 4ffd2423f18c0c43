// Configuration: a program instance on a task that does not exist.
il_macros::il!(r#"
PROGRAM Main
VAR x : INT; END_VAR
    LD x
    ADD 1
    ST x
END_PROGRAM

CONFIGURATION Plant
TASK fast (INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM m WITH fsat : Main;
END_CONFIGURATION
"#);

fn main() {}
