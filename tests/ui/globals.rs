// Globals and configurations: VAR_GLOBAL / VAR_EXTERNAL, tasks.
// Each case is one IL mistake in its own module, so that the stub items
// il! emits next to its compile_error!s cannot collide between cases.

// Globals: storing to a VAR_EXTERNAL CONSTANT.
mod external_constant_written { il_macros::il!(r#"
PROGRAM Main
VAR_EXTERNAL CONSTANT limit : INT; END_VAR
    LD 5
    ST limit
END_PROGRAM
"#); }

// Globals: a program's VAR_EXTERNAL that the configuration does not declare.
mod external_missing_global { il_macros::il!(r#"
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
"#); }

// Globals: VAR_EXTERNAL and VAR_GLOBAL of different types.
mod external_type_mismatch { il_macros::il!(r#"
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
"#); }

// Globals: a block that uses a global inside a POU that does not declare it.
mod fb_external_not_passed { il_macros::il!(r#"
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
"#); }

// Globals: VAR_GLOBAL inside a FUNCTION_BLOCK.
mod global_in_pou { il_macros::il!(r#"
FUNCTION_BLOCK Pump
VAR_GLOBAL pressure : REAL; END_VAR
    LD pressure
    ST pressure
END_FUNCTION_BLOCK
"#); }

// Configuration: INTERVAL that is not a TIME.
mod task_interval_not_time { il_macros::il!(r#"
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
"#); }

// Configuration: a program instance on a task that does not exist.
mod task_unknown { il_macros::il!(r#"
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
"#); }

fn main() {}
