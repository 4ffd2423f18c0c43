// Globals: VAR_EXTERNAL and VAR_GLOBAL of different types.
il_macros::il!(r#"
PROGRAM Main
VAR_EXTERNAL speed : INT; END_VAR
    LD speed
    ST speed
END_PROGRAM

CONFIGURATION Plant
VAR_GLOBAL speed : REAL; END_VAR
TASK t (INTERVAL := T#10ms, PRIORITY := 1);
PROGRAM m WITH t : Main;
END_CONFIGURATION
"#);

fn main() {}
