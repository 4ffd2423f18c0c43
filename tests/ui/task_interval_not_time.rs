// Configuration: INTERVAL that is not a TIME.
il_macros::il!(r#"
PROGRAM Main
VAR x : INT; END_VAR
    LD x
    ADD 1
    ST x
END_PROGRAM

CONFIGURATION Plant
TASK fast (INTERVAL := 10, PRIORITY := 1);
PROGRAM m WITH fast : Main;
END_CONFIGURATION
"#);

fn main() {}
