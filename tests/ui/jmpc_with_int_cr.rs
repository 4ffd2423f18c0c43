// Current result: JMPC with an INT in the CR (JMPC needs a BOOL CR).
il_macros::il!(r#"
FUNCTION_BLOCK Fb
VAR
    count : INT;
    q : BOOL;
END_VAR
    LD count
    JMPC done
    LD TRUE
    ST q
done:
END_FUNCTION_BLOCK
"#);

fn main() {}
