// Stub: the FUNCTION_BLOCK Pump has a mistake (an unknown variable); the
// FUNCTION_BLOCK Station that uses a Pump instance is correct. Only Pump's
// error may appear: no error in Station, no Rust error.
il_macros::il!(r#"
FUNCTION_BLOCK Pump
VAR_INPUT
    run : BOOL;
END_VAR
VAR_OUTPUT
    running : BOOL;
END_VAR
    LD rnu
    ST running
END_FUNCTION_BLOCK

FUNCTION_BLOCK Station
VAR
    p : Pump;
    go : BOOL;
    lamp : BOOL;
END_VAR
    LD go
    ST p.run
    CAL p
    LD p.running
    ST lamp
END_FUNCTION_BLOCK
"#);

fn main() {}
