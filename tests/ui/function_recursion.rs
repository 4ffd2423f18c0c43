// Calls: a FUNCTION that calls itself (IEC 61131-3 forbids recursion).
il_macros::il!(r#"
FUNCTION FACT : DINT
VAR_INPUT
    n : DINT;
END_VAR
    LD n
    LE 1
    JMPCN again
    LD 1
    ST FACT
    RET
again:
    LD n
    SUB 1
    FACT
    MUL n
    ST FACT
END_FUNCTION
"#);

fn main() {}
