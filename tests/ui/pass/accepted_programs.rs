// Accepted IL compiles: a function block with a timer, an edge, a counter,
// labels, deferred parentheses and a user FUNCTION, called from Rust.
use il_std::Cycle;

il_macros::il!(r#"
FUNCTION SCALE : INT
VAR_INPUT
    raw : INT;
    factor : INT;
END_VAR
    LD raw
    MUL factor
    ST SCALE
END_FUNCTION

FUNCTION_BLOCK Station
VAR_INPUT
    start : BOOL;
    stop : BOOL;
    part : BOOL;
    sensor : INT;
END_VAR
VAR_OUTPUT
    run : BOOL;
    parts : INT;
    value : INT;
    alarm : BOOL;
END_VAR
VAR
    settle : TON;
    edge : R_TRIG;
    counter : CTU;
    ff : SR;
END_VAR
VAR CONSTANT
    BATCH : INT := 12;
END_VAR
    LD   start
    OR   run
    ANDN stop
    ST   run
    IN   settle
    LD   T#500ms
    PT   settle
    LD   part
    AND( settle.Q
    OR   alarm
    )
    CLK  edge
    LD   edge.Q
    CU   counter
    LD   BATCH
    PV   counter
    LD   counter.CV
    ST   parts
    LD   sensor
    SCALE 10
    LIMIT 0, 1000
    ST   value
    GT   900
    JMPCN done
    LD   TRUE
    S1   ff
done:
    LD   ff.Q1
    ST   alarm
END_FUNCTION_BLOCK
"#);

fn main() {
    let mut ctx = Cycle::new();
    let mut s = Station::default();
    s.start = true;
    s.sensor = 95;
    s.call(&mut ctx);
    assert!(s.run);
    assert_eq!(s.value, 950);
    assert!(s.alarm);
    assert_eq!(SCALE(&mut ctx, 3, 4), 12);
}
