// Declarations: VAR blocks, names, types of POUs and their variables, duplicates.
// Each case is one IL mistake in its own module, so that the stub items
// il! emits next to its compile_error!s cannot collide between cases.

// Declarations: initial value 300 for a SINT (-128..127).
mod decl_initial_value_out_of_range { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    small : SINT := 300;
    n : SINT;
END_VAR
    LD small
    ST n
END_FUNCTION_BLOCK
"#); }

// Declarations: initial value TRUE for an INT.
mod decl_initial_value_wrong_type { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    n : INT := TRUE;
    m : INT;
END_VAR
    LD n
    ST m
END_FUNCTION_BLOCK
"#); }

// Declarations: 'a BOOL;' without the ':' between name and type.
mod decl_missing_colon { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a BOOL;
    q : BOOL;
END_VAR
    LD a
    ST q
END_FUNCTION_BLOCK
"#); }

// Declarations: a variable declaration without its closing ';'.
mod decl_missing_semicolon { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL
    q : BOOL;
END_VAR
    LD a
    ST q
END_FUNCTION_BLOCK
"#); }

// Declarations: a FUNCTION_BLOCK holding an instance of itself (infinite size).
mod fb_contains_itself { il_macros::il!(r#"
FUNCTION_BLOCK Node
VAR
    a : BOOL;
    next : Node;
END_VAR
    LD a
    ST a
END_FUNCTION_BLOCK
"#); }

// Declarations: a FUNCTION without ': type' for its result.
mod function_without_result_type { il_macros::il!(r#"
FUNCTION TWICE
VAR_INPUT
    a : INT;
END_VAR
    LD a
    MUL 2
    ST TWICE
END_FUNCTION
"#); }

// Declarations: '__ctx', IEC identifiers may not contain two underscores in a row.
mod identifier_double_underscore { il_macros::il!(r#"
FUNCTION TWICE : INT
VAR_INPUT
    __ctx : INT;
END_VAR
    LD __ctx
    MUL 2
    ST TWICE
END_FUNCTION
"#); }

// Declarations: TYPE is an IEC 61131-3 keyword and cannot name a variable.
mod keyword_as_variable { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    type : BOOL;
    q : BOOL;
END_VAR
    LD type
    ST q
END_FUNCTION_BLOCK
"#); }

// Declarations: ON is an IEC 61131-3 keyword (RESOURCE ... ON) and cannot name a variable.
mod keyword_on_as_variable { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    on : BOOL;
    q : BOOL;
END_VAR
    LD q
    ST q
END_FUNCTION_BLOCK
"#); }

// Declarations: an instance of a PROGRAM inside a FUNCTION_BLOCK (programs are not instantiable in POUs).
mod program_instance_in_fb { il_macros::il!(r#"
PROGRAM Main
VAR
    a : BOOL;
END_VAR
    LD a
    ST a
END_PROGRAM

FUNCTION_BLOCK Fb
VAR
    m : Main;
END_VAR
    CAL m
END_FUNCTION_BLOCK
"#); }

// Declarations: a user FUNCTION_BLOCK named TON, the name of a standard timer.
mod redefine_standard_fb { il_macros::il!(r#"
FUNCTION_BLOCK TON
VAR_INPUT
    IN : BOOL;
END_VAR
VAR_OUTPUT
    Q : BOOL;
END_VAR
    LD IN
    ST Q
END_FUNCTION_BLOCK
"#); }

// Declarations: a PROGRAM's VAR_IN_OUT must be bound where the
// configuration instantiates it (IL0130).
mod var_in_out { il_macros::il!(r#"
PROGRAM Main
VAR_IN_OUT
    n : INT;
END_VAR
    LD n
    ADD 1
    ST n
END_PROGRAM
CONFIGURATION Plant
    PROGRAM main1 : Main;
END_CONFIGURATION
"#); }

// Semantics: a FUNCTION declaring a TON instance (a FUNCTION has no memory between calls).
mod function_with_fb_instance { il_macros::il!(r#"
FUNCTION DELAYED : BOOL
VAR_INPUT
    start : BOOL;
END_VAR
VAR
    t : TON;
END_VAR
    LD start
    ST t.IN
    CAL t(PT := T#1s)
    LD t.Q
    ST DELAYED
END_FUNCTION
"#); }

// Semantics: the same variable declared twice (once as input, once local).
mod duplicate_variable { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR_INPUT
    speed : INT;
END_VAR
VAR
    speed : INT;
    limit : INT;
END_VAR
    LD speed
    ST limit
END_FUNCTION_BLOCK
"#); }

// Semantics: 'Start' and 'START' are the same name (IEC identifiers are case-insensitive).
mod duplicate_variable_case { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    Start : BOOL;
    START : BOOL;
END_VAR
    LD Start
    ST START
END_FUNCTION_BLOCK
"#); }

// Semantics: two FUNCTION_BLOCKs with the same name.
mod duplicate_pou { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    a : BOOL;
END_VAR
    LD a
    ST a
END_FUNCTION_BLOCK

FUNCTION_BLOCK Fb
VAR
    b : BOOL;
END_VAR
    LD b
    ST b
END_FUNCTION_BLOCK
"#); }

// Semantics: an unknown type TONN (typo of the TON timer): expect a did-you-mean.
mod unknown_type { il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    start : BOOL;
    delay : TONN;
END_VAR
    LD start
    IN delay
END_FUNCTION_BLOCK
"#); }

fn main() {}
