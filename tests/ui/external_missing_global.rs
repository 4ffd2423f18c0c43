// Globals: a program's VAR_EXTERNAL that the configuration does not declare.
il_macros::il!(r#"
PROGRAM Main
VAR_EXTERNAL speed : INT; END_VAR
    LD speed
    ADD 1
    ST speed
END_PROGRAM

CONFIGURATION Plant
VAR_GLOBAL sped : INT; END_VAR
TASK t (INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM m WITH t : Main;
END_CONFIGURATION
"#);

fn main() {}
